# SPDX-License-Identifier: Apache-2.0
# Installs the build tree into WORK_DIR/prefix and runs SCRIPT with the Debian
# python on the installed package only: no PEDNAV_* variable, the source
# tree not on the path.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=PEDNAV_PREFIX --unset=PEDNAV_LIBRARY
                        "PYTHONPATH=${WORK_DIR}/prefix/${PYTHON_DIR}" PYTHONDONTWRITEBYTECODE=1
                        "${PYTHON}" "${SCRIPT}" "${WORK_DIR}/prefix" "${DATA_DIR}" "${WORK_DIR}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed package failed (${rc})")
endif()
