# Ipopt through pkg-config: Debian's coinor-libipopt-dev ships no CMake config.
# Defines the imported target Ipopt::ipopt (include dir .../coin, MUMPS and BLAS on the link line).
find_package(PkgConfig REQUIRED)
pkg_check_modules(PC_IPOPT QUIET IMPORTED_TARGET GLOBAL ipopt)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Ipopt REQUIRED_VARS PC_IPOPT_FOUND VERSION_VAR PC_IPOPT_VERSION)
if(Ipopt_FOUND AND NOT TARGET Ipopt::ipopt)
  add_library(Ipopt::ipopt INTERFACE IMPORTED)
  target_link_libraries(Ipopt::ipopt INTERFACE PkgConfig::PC_IPOPT)
endif()
