# Warnings on for every target of ours; sanitizers optional (core/ tests run clean under them).
add_library(ts_warnings INTERFACE)
target_compile_options(ts_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wno-missing-field-initializers)
if(TERRASHADE_SANITIZE)
  # -Wno-maybe-uninitialized: GCC's flow analysis misreads the sanitizers' instrumentation (at the
  # preset's -O1 it flags std::regex and std::function inside libstdc++); the release build keeps
  # the warning for our code.
  target_compile_options(ts_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
                                               $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
  target_link_options(ts_warnings INTERFACE -fsanitize=address,undefined)
endif()
# Fuzzing: our code gets libFuzzer's coverage instrumentation (the targets in tests/fuzz link
# the fuzzer's main) and ASan + UBSan, so a bad read is a crash the fuzzer keeps.
if(TERRASHADE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "TERRASHADE_FUZZ needs clang with libFuzzer: -DCMAKE_CXX_COMPILER=clang++-14 (scripts/fuzz.sh)")
  endif()
  target_compile_options(ts_warnings INTERFACE -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                                               -fno-sanitize-recover=undefined)
  target_link_options(ts_warnings INTERFACE -fsanitize=address,undefined)
endif()

# ts_add_library(name SOURCES ... DEPS ...): one core module = one static library.
function(ts_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ts_warnings)
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
