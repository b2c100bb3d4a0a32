# Runs clang-format in dry-run mode over every C++ file of the project (not the test inputs); `clang-format -i <file>`
# fixes what it reports.
file(GLOB_RECURSE files ${SOURCE_DIR}/modules/*.cpp ${SOURCE_DIR}/modules/*.h ${SOURCE_DIR}/app/*.cpp
     ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.h ${SOURCE_DIR}/resources/*.cpp)
# Test inputs are not C++: Heidenhain programs end in .h too.
list(FILTER files EXCLUDE REGEX "^${SOURCE_DIR}/tests/(data|golden)/")
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror ${files}
                WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "files differ from .clang-format (run clang-format -i on them):\n${err}")
endif()
list(LENGTH files count)
message(STATUS "${count} files follow .clang-format")
