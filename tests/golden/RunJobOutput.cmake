# `camwb-cli run <job>` without -o writes the job's own output (Job::outputName in outputFolder,
# relative to the job file, the post's extension added): the example job copied into WORK_DIR
# with "output": {"name": "PART1", "folder": "nc"} must give WORK_DIR/nc/PART1.mpf, the same
# program as `run -o` to a file of that name elsewhere.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/nc ${WORK_DIR}/ref)
file(READ ${EXAMPLE_JOB} job)
get_filename_component(example_dir ${EXAMPLE_JOB} DIRECTORY)
string(REPLACE "\"model\": \"example-block.step\"" "\"model\": \"${example_dir}/example-block.step\"" job "${job}")
string(REPLACE "\"version\": 3," "\"version\": 6, \"output\": {\"name\": \"PART1\", \"folder\": \"nc\"}," job "${job}")
file(WRITE ${WORK_DIR}/job.camwb "${job}")
execute_process(COMMAND ${CLI} run ${WORK_DIR}/job.camwb RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK_DIR}/nc/PART1.mpf)
  message(FATAL_ERROR "run without -o: exit ${rc}, no ${WORK_DIR}/nc/PART1.mpf\n${err}")
endif()
execute_process(COMMAND ${CLI} run ${WORK_DIR}/job.camwb -o ${WORK_DIR}/ref/PART1.mpf RESULT_VARIABLE rc)
file(READ ${WORK_DIR}/nc/PART1.mpf own)
file(READ ${WORK_DIR}/ref/PART1.mpf given)
if(NOT rc EQUAL 0 OR NOT own STREQUAL given)
  message(FATAL_ERROR "run without -o and run -o give different programs (exit ${rc})")
endif()
