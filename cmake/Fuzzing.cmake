# -DDYNCONTACT_FUZZ=ON (clang only): every target gets libFuzzer's coverage instrumentation and
# tests/fuzz builds the fuzz targets (scripts/fuzz.sh; combine with DYNCONTACT_SANITIZE).
option(DYNCONTACT_FUZZ "Build the libFuzzer targets of tests/fuzz (needs clang)" OFF)
if(DYNCONTACT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "DYNCONTACT_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
