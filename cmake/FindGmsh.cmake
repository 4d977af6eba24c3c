# Gmsh's C++ API (Debian: libgmsh-dev). Defines Gmsh::gmsh when found; quiet otherwise.
find_path(GMSH_INCLUDE_DIR gmsh.h)
find_library(GMSH_LIBRARY NAMES gmsh)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Gmsh REQUIRED_VARS GMSH_LIBRARY GMSH_INCLUDE_DIR)
if(Gmsh_FOUND AND NOT TARGET Gmsh::gmsh)
  add_library(Gmsh::gmsh UNKNOWN IMPORTED)
  set_target_properties(Gmsh::gmsh PROPERTIES
    IMPORTED_LOCATION "${GMSH_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${GMSH_INCLUDE_DIR}")
endif()
mark_as_advanced(GMSH_INCLUDE_DIR GMSH_LIBRARY)
