# Package test, run by ctest:
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DCONSUMER_DIR=... -DC_COMPILER=... -DCXX_COMPILER=...
#         -DINSTALL_LIBDIR=... -P run_package_test.cmake
# 1. installs the build tree into WORK_DIR/prefix;
# 2. configures and builds tests/package/consumer against it with
#    find_package(pednav): a plugin with the installed SDK and a C program;
# 3. runs the program on the plugin (10 steps expected) and checks the
#    plugin exports only pnp_entry_v1;
# 4. compiles the same C program with `pkg-config --cflags --libs pednav`;
# 5. runs the installed CLI: it finds the installed plugins and presets;
# 6. checks that no test fixture plugin was installed.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(run_out "${out}" PARENT_SCOPE)
endfunction()

set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")

run("${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${WORK_DIR}/consumer" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/consumer_app" "${WORK_DIR}/consumer/plugins")
if(NOT run_out MATCHES "consumer: 10 steps")
  message(FATAL_ERROR "unexpected consumer output: ${run_out}")
endif()
message(STATUS "find_package consumer: ${run_out}")

run(nm -D --defined-only "${WORK_DIR}/consumer/plugins/libpnp_consumer_steps.so")
string(REGEX MATCHALL " [A-Za-z] [^\n]+" symbols "${run_out}")
list(FILTER symbols EXCLUDE REGEX " A ")
if(NOT symbols STREQUAL " T pnp_entry_v1")
  message(FATAL_ERROR "consumer plugin exports [${symbols}], expected only pnp_entry_v1")
endif()

find_program(PKG_CONFIG NAMES pkg-config pkgconf)
if(PKG_CONFIG)
  run("${CMAKE_COMMAND}" -E env "PKG_CONFIG_PATH=${prefix}/${INSTALL_LIBDIR}/pkgconfig"
      "${PKG_CONFIG}" --cflags --libs pednav)
  string(STRIP "${run_out}" pc_flags)
  separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
  run("${C_COMPILER}" -std=c99 -Wall -Wextra -pedantic -Werror "${CONSUMER_DIR}/consumer_app.c" ${pc_flags}
      -o "${WORK_DIR}/consumer_app_pc")
  run("${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${prefix}/${INSTALL_LIBDIR}"
      "${WORK_DIR}/consumer_app_pc" "${WORK_DIR}/consumer/plugins")
  if(NOT run_out MATCHES "consumer: 10 steps")
    message(FATAL_ERROR "unexpected pkg-config consumer output: ${run_out}")
  endif()
  message(STATUS "pkg-config consumer: ${run_out}")
endif()

# The installed CLI finds the installed first-party plugins and presets with no flag.
run("${prefix}/bin/pednav" plugins --json)
if(NOT run_out MATCHES "org.pednav.foot.ekf15" OR NOT run_out MATCHES "\"rejected\": \\[\\]")
  message(FATAL_ERROR "installed pednav plugins: ${run_out}")
endif()
run("${prefix}/bin/pednav" demo --out "${WORK_DIR}/demo")
if(NOT run_out MATCHES "loop closes")
  message(FATAL_ERROR "installed pednav demo: ${run_out}")
endif()
message(STATUS "installed CLI: plugins and presets found")

foreach(fixture good throws emits_nan duplicate_id wrong_major wrong_major_field no_entry too_small
                too_small_descriptor old_minor new_minor)
  if(EXISTS "${prefix}/${INSTALL_LIBDIR}/pednav/plugins/libpnp_${fixture}.so")
    message(FATAL_ERROR "test fixture ${fixture} was installed")
  endif()
endforeach()
if(EXISTS "${prefix}/test-plugins")
  message(FATAL_ERROR "test fixtures were installed")
endif()
