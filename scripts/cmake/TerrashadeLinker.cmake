# Links with mold when it is installed (scripts/setup.sh installs it): the same executables,
# linked several times faster than with the default GNU ld (docs/dependencies.md, "The linker").
# -DTERRASHADE_MOLD=OFF keeps the default linker.
option(TERRASHADE_MOLD "Link with mold when it is installed" ON)
if(TERRASHADE_MOLD)
  include(CheckLinkerFlag)
  check_linker_flag(CXX "-fuse-ld=mold" TS_LINKER_MOLD)
  if(TS_LINKER_MOLD)
    add_link_options(-fuse-ld=mold)
  endif()
endif()
