# `camwb-cli nc trace <case input> -o <file>` on an NC golden case: the file holds exactly the case's
# expected.trace (the trace is streamed into a temporary file while the program runs, then
# renamed), nothing goes to stdout and no temporary file is left beside it. An existing file is
# replaced.
file(GLOB inputs RELATIVE ${CASE} ${CASE}/input.*)
get_filename_component(dir ${OUT} DIRECTORY)
file(REMOVE_RECURSE ${dir})
file(MAKE_DIRECTORY ${dir})
file(WRITE ${OUT} "an older trace\n")
execute_process(COMMAND ${CLI} nc trace ${inputs} --dialect ${DIALECT} -o ${OUT} WORKING_DIRECTORY ${CASE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc MATCHES "^[01]$")
  message(FATAL_ERROR "camwb-cli nc trace crashed or failed to start (${rc}):\n${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "with -o nothing belongs on stdout, got:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${CASE}/expected.trace RESULT_VARIABLE different)
if(different)
  execute_process(COMMAND diff -u ${CASE}/expected.trace ${OUT} OUTPUT_VARIABLE diff)
  message(FATAL_ERROR "${OUT} differs from ${CASE}/expected.trace:\n${diff}")
endif()
file(GLOB leftovers ${dir}/*.tmp-*)
if(leftovers)
  message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
