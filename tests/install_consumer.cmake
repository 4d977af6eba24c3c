# ctest `install_consumer` (label slow): installs this build into a fresh prefix, then
# configures, builds and runs tests/consumer, a downstream project that only sees the
# installed package (find_package(dyncontact)). The same file is the test's driver script:
# included from tests/CMakeLists.txt it registers the test; run with `cmake -P` it does it.
if(NOT CMAKE_SCRIPT_MODE_FILE)
  set(_consumer_flags "")
  if(DYNCONTACT_SANITIZE)
    set(_consumer_flags "-fsanitize=${DYNCONTACT_SANITIZE} -fno-omit-frame-pointer")
  endif()
  add_test(NAME install_consumer
    COMMAND ${CMAKE_COMMAND}
      -DBUILD_DIR=${PROJECT_BINARY_DIR}
      -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/install_consumer
      -DCONSUMER_SOURCE=${CMAKE_CURRENT_LIST_DIR}/consumer
      -DCONFIG=$<CONFIG>
      -DGENERATOR=${CMAKE_GENERATOR}
      -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
      -DCXX_FLAGS=${_consumer_flags}
      -P ${CMAKE_CURRENT_LIST_FILE})
  set_tests_properties(install_consumer PROPERTIES LABELS slow TIMEOUT 900)
  unset(_consumer_flags)
  return()
endif()

# ---- script mode -------------------------------------------------------------------------
foreach(var BUILD_DIR WORK_DIR CONSUMER_SOURCE GENERATOR)
  if(NOT ${var})
    message(FATAL_ERROR "install_consumer: -D${var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

function(run_step what)
  message(STATUS "install_consumer: ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message("${out}")
    message(FATAL_ERROR "install_consumer: ${what} failed (exit ${rc})")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

run_step("install into ${prefix}"
  ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

# The package must be complete: config, version, targets, find modules, headers, libraries.
file(GLOB_RECURSE config_file ${prefix}/*/dyncontactConfig.cmake)
if(NOT config_file)
  message(FATAL_ERROR "install_consumer: no dyncontactConfig.cmake under ${prefix}")
endif()
get_filename_component(config_dir "${config_file}" DIRECTORY)
foreach(f dyncontactConfigVersion.cmake dyncontactTargets.cmake FindFFTW3.cmake FindIpopt.cmake)
  if(NOT EXISTS ${config_dir}/${f})
    message(FATAL_ERROR "install_consumer: ${config_dir}/${f} not installed")
  endif()
endforeach()
foreach(h core/grid.hpp core/material.hpp core/profile.hpp core/hertz.hpp nlp/normal_problem.hpp
          dynamics/dynamic_simulation.hpp)
  if(NOT EXISTS ${prefix}/include/dyncontact/${h})
    message(FATAL_ERROR "install_consumer: header ${prefix}/include/dyncontact/${h} not installed")
  endif()
endforeach()

# The installed libraries leave the process alone: no definition of MUMPS's dmumps_c, no
# mallopt (both are the program's, nlp/process_tuning/), no test-only fault source.
file(GLOB_RECURSE installed_libraries ${prefix}/lib*/libdyncontact_*)
find_program(NM_PROGRAM nm)
foreach(library ${installed_libraries})
  file(STRINGS ${library} fault_strings REGEX "DYNCONTACT_FAULT")
  if(fault_strings)
    message(FATAL_ERROR "install_consumer: ${library} reads DYNCONTACT_FAULT (test-only)")
  endif()
  if(NM_PROGRAM)
    execute_process(COMMAND ${NM_PROGRAM} ${library} OUTPUT_VARIABLE symbols ERROR_QUIET)
    if(symbols MATCHES "[TW] dmumps_c\n" OR symbols MATCHES "U mallopt\n")
      message(FATAL_ERROR "install_consumer: ${library} defines dmumps_c or calls mallopt (the program's only)")
    endif()
  endif()
endforeach()
if(NOT installed_libraries)
  message(FATAL_ERROR "install_consumer: no libdyncontact_* installed under ${prefix}")
endif()

# Test-only and internal headers stay in the build tree.
foreach(h nlp/fault_injection.hpp fault_injection.hpp grid.hpp normal_problem.hpp)
  if(EXISTS ${prefix}/include/dyncontact/${h})
    message(FATAL_ERROR "install_consumer: ${prefix}/include/dyncontact/${h} installed (test-only, or not by layer)")
  endif()
endforeach()

# The installed command line runs.
if(EXISTS ${prefix}/bin/dyncontact)
  run_step("installed dyncontact --help" ${prefix}/bin/dyncontact --help)
else()
  message(FATAL_ERROR "install_consumer: ${prefix}/bin/dyncontact not installed")
endif()
# With finite-element bodies: their headers, and the installed command solves a finite case
# (Gmsh meshes it, CHOLMOD factorises it: nothing else is needed at run time).
file(STRINGS ${config_file} with_fe REGEX "^set\\(dyncontact_WITH_FE ON\\)")
if(with_fe)
  foreach(h nlp/finite/finite_contact.hpp core/fe/elastic_body.hpp dynamics/finite/finite_body_contact.hpp)
    if(NOT EXISTS ${prefix}/include/dyncontact/${h})
      message(FATAL_ERROR "install_consumer: header ${prefix}/include/dyncontact/${h} not installed")
    endif()
  endforeach()
  run_step("installed dyncontact example finite-hemisphere" ${prefix}/bin/dyncontact example finite-hemisphere)
  file(WRITE ${WORK_DIR}/finite.json "${step_output}")
  run_step("installed dyncontact solves a finite case" ${prefix}/bin/dyncontact solve ${WORK_DIR}/finite.json
           --out ${WORK_DIR}/finite-out -q --set output.plots=false --set grid.nx=12 --set grid.ny=12)
  if(NOT EXISTS ${WORK_DIR}/finite-out/body.vtu)
    message(FATAL_ERROR "install_consumer: the installed dyncontact wrote no body.vtu")
  endif()
endif()

set(configure_args -S ${CONSUMER_SOURCE} -B ${consumer_build} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=${CONFIG}
    -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    -DDYNCONTACT_EXPECTED_DIR=${config_dir})
if(CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(CXX_FLAGS)
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CXX_FLAGS}")
endif()
run_step("configure the consumer" ${CMAKE_COMMAND} ${configure_args})
run_step("build the consumer" ${CMAKE_COMMAND} --build ${consumer_build} --config ${CONFIG})

file(GLOB_RECURSE consumer_exe LIST_DIRECTORIES false
     ${consumer_build}/dyncontact_consumer ${consumer_build}/dyncontact_consumer.exe)
if(NOT consumer_exe)
  message(FATAL_ERROR "install_consumer: consumer executable not found under ${consumer_build}")
endif()
list(GET consumer_exe 0 consumer_exe)
run_step("run the consumer" ${consumer_exe})
message("${step_output}")
message(STATUS "install_consumer: passed")
