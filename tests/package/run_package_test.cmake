# SPDX-License-Identifier: Apache-2.0
# Package test, run by ctest:
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DCONSUMER_DIR=... -DC_CONSUMER_DIR=... -DC_COMPILER=...
#         -DCXX_COMPILER=... -DINSTALL_LIBDIR=... -P run_package_test.cmake
# 1. installs the build tree into WORK_DIR/prefix; the exported targets a C
#    app loads do not mention nlohmann_json (only the SDK's do);
# 2. configures and builds tests/package/consumer against it with
#    find_package(pednav COMPONENTS sdk): a plugin with the installed SDK
#    (its manifest written by the installed pednav-manifest), a C program,
#    and, with the static engine, the same program linked statically;
# 3. runs both programs on the plugin (10 steps expected) and checks the
#    plugin exports only pnp_entry_v1;
# 4. installs the consumer plugin under the same prefix: the installed CLI
#    (`pednav plugins --json`) finds it, with its manifest;
# 5. compiles the same C program with `pkg-config --cflags --libs pednav`;
# 6. builds a C-only project (tests/package/c_consumer) with nlohmann_json
#    unfindable (CMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON) and runs it;
# 7. runs the installed CLI: it finds the installed plugins and presets;
# 8. checks that no test fixture plugin was installed.
include("${CMAKE_CURRENT_LIST_DIR}/package_common.cmake")
set(prefix "${WORK_DIR}/prefix")
install_into_prefix("${BUILD_DIR}" "${WORK_DIR}" "${prefix}")
set(cmake_dir "${prefix}/${INSTALL_LIBDIR}/cmake/pednav")
file(GLOB c_targets "${cmake_dir}/pednavTargets*.cmake")
foreach(f IN LISTS c_targets)
  file(READ "${f}" text)
  if(text MATCHES "nlohmann")
    message(FATAL_ERROR "${f}, which every find_package(pednav) loads, mentions nlohmann_json")
  endif()
endforeach()
if(NOT EXISTS "${cmake_dir}/pednavSdkTargets.cmake")
  message(FATAL_ERROR "pednavSdkTargets.cmake was not installed")
endif()

run("${CMAKE_COMMAND}" -S "${CONSUMER_DIR}" -B "${WORK_DIR}/consumer" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_INSTALL_PREFIX=${prefix}"
    "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
if(NOT run_out MATCHES "pednav_PLUGIN_DIR=${prefix}/${INSTALL_LIBDIR}/pednav/plugins\n"
   OR NOT run_out MATCHES "pednav_PLUGIN_INSTALL_DIR=${INSTALL_LIBDIR}/pednav/plugins\n")
  message(FATAL_ERROR "pednavConfig.cmake does not give the plugin directory:\n${run_out}")
endif()
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
set(manifest "${WORK_DIR}/consumer/plugins/libpnp_consumer_steps.json")
if(NOT EXISTS "${manifest}")
  message(FATAL_ERROR "the installed pednav-manifest wrote no manifest beside the consumer plugin")
endif()
file(READ "${manifest}" text)
if(NOT text MATCHES "\"format\": \"pednav-plugin-manifest/1\"" OR NOT text MATCHES "\"id\": \"com.example.consumer.every_n\""
   OR NOT text MATCHES "\"file\": \"libpnp_consumer_steps.so\"")
  message(FATAL_ERROR "unexpected consumer manifest:\n${text}")
endif()
run("${WORK_DIR}/consumer/consumer_app" "${WORK_DIR}/consumer/plugins")
if(NOT run_out MATCHES "consumer: 10 steps")
  message(FATAL_ERROR "unexpected consumer output: ${run_out}")
endif()
message(STATUS "find_package consumer: ${run_out}")
if(NOT EXISTS "${prefix}/${INSTALL_LIBDIR}/libpednav.a")
  message(FATAL_ERROR "libpednav.a was not installed")
endif()
run("${WORK_DIR}/consumer/consumer_static_app")
if(NOT run_out MATCHES "static consumer: 10 steps")
  message(FATAL_ERROR "unexpected static consumer output: ${run_out}")
endif()
message(STATUS "static consumer: ${run_out}")

run(nm -D --defined-only "${WORK_DIR}/consumer/plugins/libpnp_consumer_steps.so")
string(REGEX MATCHALL " [A-Za-z] [^\n]+" symbols "${run_out}")
list(FILTER symbols EXCLUDE REGEX " A ")
if(NOT symbols STREQUAL " T pnp_entry_v1")
  message(FATAL_ERROR "consumer plugin exports [${symbols}], expected only pnp_entry_v1")
endif()

# Installed under the same prefix, into pednav's plugin directory, with its manifest.
run("${CMAKE_COMMAND}" --install "${WORK_DIR}/consumer")
set(plugin_dir "${prefix}/${INSTALL_LIBDIR}/pednav/plugins")
foreach(f libpnp_consumer_steps.so libpnp_consumer_steps.json)
  if(NOT EXISTS "${plugin_dir}/${f}")
    message(FATAL_ERROR "the consumer plugin's ${f} was not installed into ${plugin_dir}")
  endif()
endforeach()
run("${prefix}/bin/pednav" plugins --json)
string(JSON n_warnings LENGTH "${run_out}" load_warnings)
string(JSON n_rejected LENGTH "${run_out}" rejected)
string(JSON n_libraries LENGTH "${run_out}" libraries)
set(found "")
math(EXPR last "${n_libraries} - 1")
foreach(i RANGE ${last})
  string(JSON path GET "${run_out}" libraries ${i} path)
  if(path STREQUAL "${plugin_dir}/libpnp_consumer_steps.so")
    string(JSON found GET "${run_out}" libraries ${i} manifest)
    string(JSON plugins GET "${run_out}" libraries ${i} plugins)
  endif()
endforeach()
if(NOT found STREQUAL "${plugin_dir}/libpnp_consumer_steps.json" OR NOT plugins MATCHES "com.example.consumer.every_n"
   OR NOT n_warnings EQUAL 0 OR NOT n_rejected EQUAL 0)
  message(FATAL_ERROR "the installed pednav plugins does not list the installed consumer plugin "
                      "with its manifest (manifest: '${found}', ${n_warnings} warnings, ${n_rejected} rejected):\n${run_out}")
endif()
message(STATUS "installed CLI: the consumer plugin installed under ${prefix} is found, with its manifest")

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

# A C-only project on the installed package, with nlohmann_json unfindable.
run("${CMAKE_COMMAND}" -S "${C_CONSUMER_DIR}" -B "${WORK_DIR}/c_consumer" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_C_COMPILER=${C_COMPILER}" -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON)
if(NOT run_out MATCHES "pednav_sdk_FOUND=FALSE")
  message(FATAL_ERROR "the C-only consumer found the SDK although nlohmann_json is disabled:\n${run_out}")
endif()
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/c_consumer")
run("${WORK_DIR}/c_consumer/c_consumer_app" "${plugin_dir}")
if(NOT run_out MATCHES "consumer: 10 steps")
  message(FATAL_ERROR "unexpected C-only consumer output: ${run_out}")
endif()
message(STATUS "C-only consumer without nlohmann_json: ${run_out}")

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
                too_small_descriptor old_minor new_minor lazy_a1 lazy_b5)
  if(EXISTS "${prefix}/${INSTALL_LIBDIR}/pednav/plugins/libpnp_${fixture}.so")
    message(FATAL_ERROR "test fixture ${fixture} was installed")
  endif()
endforeach()
if(EXISTS "${prefix}/test-plugins")
  message(FATAL_ERROR "test fixtures were installed")
endif()
