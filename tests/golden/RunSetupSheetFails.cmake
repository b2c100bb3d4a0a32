# A setup sheet that cannot be finished (its PDF goes into a folder that does not exist) exits 1
# with the reason and leaves the old sheet exactly as it was: no new pictures folder, no
# temporary files.
file(REMOVE_RECURSE ${OUT_DIR})
file(MAKE_DIRECTORY ${OUT_DIR})
file(WRITE ${OUT_DIR}/sheet.html "previous sheet\n")
execute_process(COMMAND ${CLI} setup-sheet ${JOB} -o ${OUT_DIR}/sheet.html --pdf ${OUT_DIR}/no-such-folder/sheet.pdf
                --no-sim RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT err MATCHES "camwb-cli: error: .*no-such-folder/sheet.pdf")
  message(FATAL_ERROR "expected exit 1 naming the PDF, got ${rc}:\n${err}")
endif()
file(READ ${OUT_DIR}/sheet.html kept)
file(GLOB written RELATIVE ${OUT_DIR} ${OUT_DIR}/* ${OUT_DIR}/.*)
if(NOT kept STREQUAL "previous sheet\n" OR NOT written STREQUAL "sheet.html")
  message(FATAL_ERROR "the old sheet was changed or files were left: ${written}\n${kept}")
endif()
