# SPDX-License-Identifier: Apache-2.0
# cmake -DCLI=<pednav> -DREADME=<README.md> -DSTALE=<scratch file> -P params_stale.cmake
# A copy of the README with one default changed in its tables: `--check` names the plugin, the
# key and both values, prints the command that regenerates the tables and exits 1; `--update`
# then regenerates them and `--check` finds no difference.
file(READ ${README} readme)
string(REGEX REPLACE "(\\| `swing_propagation_s` \\| [^|]*\\| [^|]*\\| [^|]*\\| )[^ |]+" "\\1999" stale "${readme}")
if(stale STREQUAL readme)
  message(FATAL_ERROR "${README} has no swing_propagation_s row to change")
endif()
file(WRITE ${STALE} "${stale}")

execute_process(COMMAND ${CLI} plugins --params --check ${STALE} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message(STATUS "check: rc=${rc}\n${out}${err}")
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "--check of a stale table exited ${rc}, expected 1")
endif()
set(expected "[^\n]*:[0-9]+: org.pednav.foot.ekf15, org.pednav.foot.ekf15.dense \\(position_filter\\), swing_propagation_s: default is \"999\" in the file, \"[0-9.e+-]+\" in the schema\n1 difference [^\n]*\n  [^\n]*/pednav plugins --params --markdown --update [^\n]*\n$")
if(NOT err MATCHES "^${expected}")
  message(FATAL_ERROR "stderr does not match ${expected}")
endif()

execute_process(COMMAND ${CLI} plugins --params --markdown --update ${STALE} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message(STATUS "update: rc=${rc}\n${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "parameter tables regenerated")
  message(FATAL_ERROR "--update did not regenerate ${STALE}")
endif()
execute_process(COMMAND ${CLI} plugins --params --check ${STALE} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message(STATUS "check after update: rc=${rc}\n${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--check still finds differences after --update")
endif()
file(READ ${STALE} updated)
if(NOT updated STREQUAL readme)
  message(FATAL_ERROR "--update did not give back the README's own text")
endif()
