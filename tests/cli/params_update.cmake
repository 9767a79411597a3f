# SPDX-License-Identifier: Apache-2.0
# cmake -DCLI=<pednav> -DSTALE=<file with a stale table> -DCOPY=<scratch file> -P params_update.cmake
# `--update` regenerates a stale table, after which `--check` finds no difference.
configure_file(${STALE} ${COPY} COPYONLY)
execute_process(COMMAND ${CLI} plugins --params --markdown --update ${COPY} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message(STATUS "update: rc=${rc}\n${out}${err}")
if(NOT rc EQUAL 0 OR NOT out MATCHES "parameter tables regenerated")
  message(FATAL_ERROR "--update did not regenerate ${COPY}")
endif()
execute_process(COMMAND ${CLI} plugins --params --check ${COPY} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message(STATUS "check: rc=${rc}\n${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--check still finds differences after --update")
endif()
file(READ ${STALE} stale)
file(READ ${COPY} updated)
if(stale STREQUAL updated)
  message(FATAL_ERROR "--update left the stale table as it was")
endif()
