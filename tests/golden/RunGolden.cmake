# Runs camwb-cli on a job and compares the output with the expected file byte for byte: the NC
# (`run`, the default) or the CL trace (-DCOMMAND=cl), or `post` with -DARGS (a list, e.g. another
# post: "--post;heidenhain-itnc530"). With CAMWB_UPDATE_GOLDEN=1 in the
# environment it rewrites the expected file instead.
if(NOT COMMAND)
  set(COMMAND run)
endif()
execute_process(COMMAND ${CLI} ${COMMAND} ${JOB} ${ARGS} -o ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "camwb-cli failed (${rc}):\n${out}${err}")
endif()
if("$ENV{CAMWB_UPDATE_GOLDEN}" STREQUAL "1")
  file(COPY_FILE ${OUT} ${EXPECTED})
  message(STATUS "updated ${EXPECTED}: review the diff before committing")
  return()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${EXPECTED} RESULT_VARIABLE different)
if(different)
  execute_process(COMMAND diff -u ${EXPECTED} ${OUT} OUTPUT_VARIABLE diff)
  message(FATAL_ERROR "${COMMAND} output differs from ${EXPECTED}:\n${diff}")
endif()
