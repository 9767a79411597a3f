# SPDX-License-Identifier: Apache-2.0
# The third-party plugin example as an outsider builds and runs it, run by ctest:
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DEXAMPLE_DIR=... -DCXX_COMPILER=... -DINSTALL_LIBDIR=... -P run_example_test.cmake
# 1. installs the build tree into WORK_DIR/prefix;
# 2. configures examples/third_party_plugin against that prefix only (no
#    package registry; pednav_DIR must be the prefix's) and builds it;
# 3. the INSTALLED `pednav validate` passes the plugin;
# 4. the installed `pednav sim` simulates a chest walk of the corridor loop
#    (120 m, exact truth), the installed `pednav run` runs it with
#    --plugin-dir on the built plugin and the example's config naming it, and
#    `pednav eval` scores it against the truth: the step count within 3 of
#    the truth's, the distance within -10 %..+15 % of the truth's, the loop
#    closing within 5 m.
include("${CMAKE_CURRENT_LIST_DIR}/package_common.cmake")
set(prefix "${WORK_DIR}/prefix")
install_into_prefix("${BUILD_DIR}" "${WORK_DIR}" "${prefix}")
set(pednav "${prefix}/bin/pednav")

set(build "${WORK_DIR}/example")
run("${CMAKE_COMMAND}" -S "${EXAMPLE_DIR}" -B "${build}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
file(STRINGS "${build}/CMakeCache.txt" pednav_dir REGEX "^pednav_DIR:")
if(NOT pednav_dir STREQUAL "pednav_DIR:PATH=${prefix}/${INSTALL_LIBDIR}/cmake/pednav")
  message(FATAL_ERROR "the example found pednav elsewhere than the prefix: ${pednav_dir}")
endif()
run("${CMAKE_COMMAND}" --build "${build}")
set(plugin "${build}/plugins/libpnp_example_steps.so")
foreach(f "${plugin}" "${build}/plugins/libpnp_example_steps.json")
  if(NOT EXISTS "${f}")
    message(FATAL_ERROR "the example's build did not make ${f}")
  endif()
endforeach()

run("${pednav}" validate "${plugin}" --json)
string(JSON passed GET "${run_out}" passed)
string(JSON checks_run GET "${run_out}" checks_run)
if(NOT passed OR NOT checks_run EQUAL 14)  # load, manifest, 6 checks in each of chest and handheld
  message(FATAL_ERROR "the installed pednav validate: passed ${passed}, ${checks_run} checks:\n${run_out}")
endif()
message(STATUS "installed pednav validate: ${checks_run} checks passed")

run("${pednav}" sim --route corridor_loop --mount chest --out "${WORK_DIR}/walk")
run("${pednav}" run --mount chest --input "${WORK_DIR}/walk/input.csv"
    --config "${EXAMPLE_DIR}/chest_example_steps.json" --plugin-dir "${build}/plugins"
    --output "${WORK_DIR}/track.csv" --steps "${WORK_DIR}/steps.csv" --summary "${WORK_DIR}/summary.json")
file(READ "${WORK_DIR}/summary.json" summary)
string(JSON detector GET "${summary}" pipeline stages 0 plugin)
string(JSON detector_out GET "${summary}" pipeline stages 0 records_out)
if(NOT detector STREQUAL "com.example.steps.peak")
  message(FATAL_ERROR "the pipeline's step detector is ${detector}, not the example's")
endif()
run("${pednav}" eval --track "${WORK_DIR}/track.csv" --truth "${WORK_DIR}/walk" --steps "${WORK_DIR}/steps.csv" --json)
string(JSON steps GET "${run_out}" step_count)
string(JSON truth_steps GET "${run_out}" truth_step_count)
string(JSON distance GET "${run_out}" distance_m)
string(JSON truth_distance GET "${run_out}" truth_distance_m)
string(JSON closure GET "${run_out}" loop_closure horizontal_m)
math(EXPR step_error "${steps} - ${truth_steps}")
if(step_error LESS -3 OR step_error GREATER 3 OR NOT detector_out EQUAL steps)
  message(FATAL_ERROR "${steps} steps (the detector emitted ${detector_out}), the truth has ${truth_steps}")
endif()
# if(LESS/GREATER) compare decimals as numbers, math() is integer only: the
# bounds are whole metres from the truth's distance.
string(REGEX REPLACE "\\..*" "" truth_m_int "${truth_distance}")
math(EXPR low "${truth_m_int} * 90 / 100")
math(EXPR high "(${truth_m_int} + 1) * 115 / 100")
if(distance LESS low OR distance GREATER high OR closure GREATER 5.0)
  message(FATAL_ERROR "distance ${distance} m (bounds ${low}..${high} m from the truth's ${truth_distance} m), "
                      "loop closure ${closure} m (at most 5 m)")
endif()
message(STATUS "example plugin on a simulated chest walk: ${steps} steps (truth ${truth_steps}), "
               "${distance} m (truth ${truth_distance} m), loop closes within ${closure} m")
