# SPDX-License-Identifier: Apache-2.0
# What the package tests share (run_package_test.cmake, run_example_test.cmake).

# run(<command> <args>...): runs it, fails the test with its output unless it
# exits 0; its stdout in run_out.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(run_out "${out}" PARENT_SCOPE)
endfunction()

# install_into_prefix(<build dir> <work dir> <prefix>): a fresh work dir, and
# the whole build tree installed into <prefix> beneath it.
function(install_into_prefix build_dir work_dir prefix)
  file(REMOVE_RECURSE "${work_dir}")
  file(MAKE_DIRECTORY "${work_dir}")
  run("${CMAKE_COMMAND}" --install "${build_dir}" --prefix "${prefix}")
endfunction()
