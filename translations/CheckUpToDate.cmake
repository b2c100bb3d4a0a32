# Runs lupdate on a copy of the committed .ts and fails when the result differs, i.e. when the
# GUI's strings changed and `cmake --build build --target update_translations` was not run.
string(REPLACE "|" ";" sources "${SOURCES}")
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
get_filename_component(name ${TS} NAME)
file(COPY_FILE ${TS} ${WORK}/${name})
execute_process(COMMAND ${LUPDATE} -locations none -no-obsolete -silent -I ${INCLUDE_DIR} ${sources} -ts ${WORK}/${name}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "lupdate failed: ${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${TS} ${WORK}/${name} RESULT_VARIABLE different)
if(different)
  execute_process(COMMAND diff -u ${TS} ${WORK}/${name} OUTPUT_VARIABLE diff)
  message(FATAL_ERROR "${TS} is behind the sources; run the update_translations target:\n${diff}")
endif()
