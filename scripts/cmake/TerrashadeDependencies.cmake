# Every external library, found once. scripts/setup.sh installs them (docs/dependencies.md says why each).
find_package(Threads REQUIRED)
find_package(PROJ CONFIG REQUIRED)
find_package(OpenImageIO CONFIG REQUIRED)  # tests read images with it; later: EXR/HDR environment maps
# Debian 12's OpenImageIO config lists /usr/include/opencv4 even when OpenCV is not installed,
# which makes every target linking it fail to generate: drop that one directory.
get_target_property(_ts_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
if(_ts_oiio_includes)
  list(FILTER _ts_oiio_includes EXCLUDE REGEX "opencv4")
  set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_ts_oiio_includes}")
endif()
find_package(TIFF REQUIRED)
# libzip: its Debian CMake config demands the zipcmp tools; pkg-config needs nothing more.
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBZIP REQUIRED IMPORTED_TARGET libzip)
# ISA-L and libdeflate: PNG compression (core/raster/zlib_stream.hpp says why); Debian 12 ships
# pkg-config files only.
pkg_check_modules(LIBDEFLATE REQUIRED IMPORTED_TARGET libdeflate)
pkg_check_modules(LIBISAL REQUIRED IMPORTED_TARGET libisal)
find_package(glm CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(SQLite3 REQUIRED)
find_package(assimp CONFIG REQUIRED)
find_package(nlohmann_json 3 CONFIG REQUIRED)  # info --json output; gdalinfo -json in tests

# GeographicLib: Debian ships only a Find module in a non-standard place.
find_path(GeographicLib_INCLUDE_DIR GeographicLib/Config.h REQUIRED)
find_library(GeographicLib_LIBRARY NAMES GeographicLib REQUIRED)
add_library(ts_geographiclib INTERFACE)
target_include_directories(ts_geographiclib SYSTEM INTERFACE ${GeographicLib_INCLUDE_DIR})
target_link_libraries(ts_geographiclib INTERFACE ${GeographicLib_LIBRARY})

# libgeotiff: no CMake config or pkg-config file on Debian 12.
find_path(GeoTIFF_INCLUDE_DIR geotiffio.h PATH_SUFFIXES geotiff REQUIRED)
find_library(GeoTIFF_LIBRARY NAMES geotiff REQUIRED)
add_library(ts_geotiff INTERFACE)
target_include_directories(ts_geotiff SYSTEM INTERFACE ${GeoTIFF_INCLUDE_DIR})
target_link_libraries(ts_geotiff INTERFACE ${GeoTIFF_LIBRARY} TIFF::TIFF PROJ::proj)

if(TERRASHADE_BUILD_GPU)
  find_package(Vulkan REQUIRED)
  find_package(glfw3 CONFIG REQUIRED)
  find_program(GLSLANG_VALIDATOR NAMES glslangValidator glslang REQUIRED)
endif()
# The tests' own libraries come with `scripts/setup.sh test`; a machine set up for the demo only
# (`scripts/setup.sh demo`) builds terrashade without them.
if(TERRASHADE_BUILD_TESTS)
  find_package(GTest CONFIG QUIET)
  find_package(PNG QUIET)                   # tests: an independent PNG decoder and the reference encoder
  if(NOT GTest_FOUND OR NOT PNG_FOUND)
    message(STATUS "GoogleTest or libpng not found: the tests are not configured (scripts/setup.sh test installs them)")
    set(TERRASHADE_BUILD_TESTS OFF)
  endif()
  find_package(benchmark CONFIG QUIET)
endif()
