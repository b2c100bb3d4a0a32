# Registers the skip probe in a throw-away ctest project with the GUI tests' SKIP_REGULAR_EXPRESSION
# and runs ctest on it: each mode must come out as ctest reports it to a person (Passed, Skipped,
# Failed). Inputs: PROBE (the probe program), REGEX (CAMWB_GUI_SKIP_REGEX), WORK (a folder).
set(modes pass skip skip_fail fail_skip skip_class)
set(expected Passed Skipped Failed Failed Skipped)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(project "cmake_minimum_required(VERSION 3.20)\nproject(probe NONE)\nenable_testing()\n")
foreach(mode IN LISTS modes)
  string(APPEND project "add_test(NAME probe.${mode} COMMAND \"${PROBE}\" ${mode})\n"
                        "set_tests_properties(probe.${mode} PROPERTIES SKIP_REGULAR_EXPRESSION [=[${REGEX}]=])\n")
endforeach()
file(WRITE ${WORK}/CMakeLists.txt "${project}")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK} -B ${WORK}/build RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the probe project failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir ${WORK}/build RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE out)
message("${out}")
foreach(mode want IN ZIP_LISTS modes expected)
  if(NOT out MATCHES "probe\\.${mode} [.]+ *(\\*\\*\\*)?${want}")
    message(FATAL_ERROR "probe.${mode}: ctest did not report it ${want}")
  endif()
endforeach()
if(rc EQUAL 0)
  message(FATAL_ERROR "ctest passed although two probes failed")
endif()
