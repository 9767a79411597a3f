# SPDX-License-Identifier: Apache-2.0
# cmake -DPYTHON=<python3> -DGEN=<make_input.py> -DKIND=<kind> -DDIR=<work dir> [-DPRESET=<foot.json>]
#       -DCLI=<pednav> -DARGS="a|%DIR%/file|..." -DEXPECT_RC=<n> [-DEXPECT_OUT=..] [-DEXPECT_ERR=..]
#       [-DEXPECT_FILE=%DIR%/out -DEXPECT_FILE_REGEX=..] -P run_case.cmake
# One case of the bad-input catalogue: writes its input, then runs the CLI
# on it and checks as run_cli.cmake does (%DIR% in ARGS and EXPECT_FILE is the work dir).
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
if(KIND)
  execute_process(COMMAND ${PYTHON} ${GEN} ${KIND} ${DIR} ${PRESET} RESULT_VARIABLE gen_rc)
  if(NOT gen_rc EQUAL 0)
    message(FATAL_ERROR "make_input.py ${KIND} failed: ${gen_rc}")
  endif()
endif()
string(REPLACE "|" ";" ARGS "${ARGS}")
string(REPLACE "%DIR%" "${DIR}" ARGS "${ARGS}")
if(DEFINED EXPECT_FILE)
  string(REPLACE "%DIR%" "${DIR}" EXPECT_FILE "${EXPECT_FILE}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/../cli/run_cli.cmake)
file(REMOVE_RECURSE "${DIR}")
