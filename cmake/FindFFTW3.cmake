# FFTW 3 (double precision) through pkg-config: Debian ships no CMake config for it.
# Defines the imported targets FFTW3::fftw3 and FFTW3::fftw3_threads.
find_package(PkgConfig REQUIRED)
pkg_check_modules(PC_FFTW3 QUIET fftw3)
find_path(FFTW3_INCLUDE_DIR fftw3.h HINTS ${PC_FFTW3_INCLUDE_DIRS})
find_library(FFTW3_LIBRARY NAMES fftw3 HINTS ${PC_FFTW3_LIBRARY_DIRS})
find_library(FFTW3_THREADS_LIBRARY NAMES fftw3_threads HINTS ${PC_FFTW3_LIBRARY_DIRS})
find_package(Threads REQUIRED)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FFTW3 REQUIRED_VARS FFTW3_LIBRARY FFTW3_THREADS_LIBRARY FFTW3_INCLUDE_DIR)
if(FFTW3_FOUND AND NOT TARGET FFTW3::fftw3)
  add_library(FFTW3::fftw3 UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3 PROPERTIES
    IMPORTED_LOCATION "${FFTW3_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${FFTW3_INCLUDE_DIR}")
endif()
if(FFTW3_FOUND AND NOT TARGET FFTW3::fftw3_threads)
  add_library(FFTW3::fftw3_threads UNKNOWN IMPORTED)
  set_target_properties(FFTW3::fftw3_threads PROPERTIES
    IMPORTED_LOCATION "${FFTW3_THREADS_LIBRARY}"
    INTERFACE_LINK_LIBRARIES "FFTW3::fftw3;Threads::Threads")
endif()
mark_as_advanced(FFTW3_INCLUDE_DIR FFTW3_LIBRARY FFTW3_THREADS_LIBRARY)
