# Installation and the CMake package config, so that another project can
#
#   find_package(dyncontact 0.1 REQUIRED)
#   target_link_libraries(app PRIVATE dyncontact::nlp)      # or dyncontact::dyncontact_nlp
#
# `cmake --install build --prefix P` installs
#   P/lib/libdyncontact_{core,nlp,dynamics}.a   (shared with -DBUILD_SHARED_LIBS=ON)
#   P/lib/libdyncontact_{fe,finite,finite_dynamics}.a  (with DYNCONTACT_WITH_FE: finite-element bodies)
#   P/lib/dyncontact/libdyncontact_gmsh.so      (the Gmsh plugin, loaded when a body is meshed)
#   P/include/dyncontact/LAYER/*.hpp            (by layer: #include <dyncontact/nlp/normal_problem.hpp>;
#                                                core, nlp, dynamics, core/fe, nlp/finite, dynamics/finite)
#   P/bin/dyncontact                            (install rule in apps/CMakeLists.txt)
#   P/lib/cmake/dyncontact/                     (config, version, targets, find modules)
#
# Target names: the exported targets keep their build names under the namespace
# `dyncontact::` (dyncontact::dyncontact_core, ::dyncontact_nlp, ::dyncontact_dynamics).
# The config adds the short names dyncontact::core, ::nlp, ::dynamics (INTERFACE IMPORTED
# targets linking to the long ones), so code written against the in-tree ALIAS targets
# builds unchanged against an installed package.
#
# The libraries are static by default and link FFTW3, Ipopt and NLopt PRIVATE; the exported
# link interface still names them ($<LINK_ONLY:...>), so the config re-finds them: FFTW3 and
# Ipopt through the find modules installed next to the config (pkg-config), NLopt and Eigen3
# through their own CMake configs. No installed header includes nlohmann/json (the case layer,
# apps/case/, is not installed).
include(CMakePackageConfigHelpers)

set(DYNCONTACT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/dyncontact
    CACHE STRING "Where the dyncontact CMake package files are installed (relative to the prefix)")
mark_as_advanced(DYNCONTACT_INSTALL_CMAKEDIR)

# Each library with the folder its headers are installed in (by layer: include/dyncontact/nlp/...).
set(_dyncontact_libraries dyncontact_core dyncontact_nlp dyncontact_dynamics)
set(_dyncontact_header_dirs core nlp dynamics)
set(_dyncontact_find_modules ${CMAKE_CURRENT_LIST_DIR}/FindFFTW3.cmake ${CMAKE_CURRENT_LIST_DIR}/FindIpopt.cmake)
if(DYNCONTACT_WITH_FE)  # finite-element bodies: dyncontact_fe (CHOLMOD; Gmsh as a plugin), dyncontact_finite and its dynamics
  list(APPEND _dyncontact_libraries dyncontact_fe dyncontact_finite dyncontact_finite_dynamics)
  list(APPEND _dyncontact_header_dirs core/fe nlp/finite dynamics/finite)
  list(APPEND _dyncontact_find_modules ${CMAKE_CURRENT_LIST_DIR}/FindCHOLMOD.cmake)
endif()

foreach(_dyncontact_library _dyncontact_header_dir IN ZIP_LISTS _dyncontact_libraries _dyncontact_header_dirs)
  install(TARGETS ${_dyncontact_library}
    EXPORT dyncontactTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dyncontact/${_dyncontact_header_dir})
endforeach()
# (The include directory comes from each target's $<INSTALL_INTERFACE:...> entry.)

install(EXPORT dyncontactTargets
  NAMESPACE dyncontact::
  FILE dyncontactTargets.cmake
  DESTINATION ${DYNCONTACT_INSTALL_CMAKEDIR})

configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/dyncontactConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/dyncontactConfig.cmake
  INSTALL_DESTINATION ${DYNCONTACT_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_BINDIR)

# 0.x: minor versions may break the API, so a request for 0.1 accepts 0.1.* only.
write_basic_package_version_file(
  ${CMAKE_CURRENT_BINARY_DIR}/dyncontactConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)

install(FILES
  ${CMAKE_CURRENT_BINARY_DIR}/dyncontactConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/dyncontactConfigVersion.cmake
  ${_dyncontact_find_modules}
  DESTINATION ${DYNCONTACT_INSTALL_CMAKEDIR})

unset(_dyncontact_libraries)
unset(_dyncontact_find_modules)
