# camwb_add_module(<name> SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Creates the static library camwb_<name>. Headers are included as "<module>/<Header>.h" with
# modules/ on the include path; dependencies are declared per target so the graph stays one-way.
function(camwb_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(camwb_${name} STATIC ${ARG_SOURCES})
  target_include_directories(camwb_${name} PUBLIC ${PROJECT_SOURCE_DIR}/modules ${PROJECT_BINARY_DIR}/generated)
  target_link_libraries(camwb_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  target_compile_options(camwb_${name} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  set_target_properties(camwb_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# camwb_add_gtest(<name> SOURCES ... DEPS ... [LABELS ...]): one GoogleTest binary, tests discovered by ctest.
function(camwb_add_gtest name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE CAMWB_TEST_DATA_DIR="${PROJECT_SOURCE_DIR}")
  include(GoogleTest)
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
  # Labels through gtest_discover_tests' PROPERTIES lose all but the first (CMake 3.25 splits the
  # list there); a directory label reaches every test the directory's binaries add.
  set_property(DIRECTORY APPEND PROPERTY LABELS unit ${ARG_LABELS})
endfunction()

# camwb_add_plugin(<target> SOURCES ... LINK ... LOADER <target> PLACE <NAME> [UNORDERED]): a library
# the programs load on use (base/PluginLibrary.h), with one exported C entry point and the static
# libraries' copies inside it kept its own; installed in <libdir>/camwb/. The loader target gets
# <NAME>_BUILT (where the build put it) and <NAME>_FROM_BINDIR (where the package puts it, from the
# program's folder); it is built before the loader, unless UNORDERED (when the library itself links
# the loader: then the programs that load it add the dependency).
function(camwb_add_plugin target)
  cmake_parse_arguments(ARG "UNORDERED" "LOADER;PLACE" "SOURCES;LINK" ${ARGN})
  add_library(${target} MODULE ${ARG_SOURCES})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/modules ${PROJECT_BINARY_DIR}/generated)
  target_link_libraries(${target} PRIVATE ${ARG_LINK})
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  set_target_properties(${target} PROPERTIES CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${target} PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/camwb)
  file(RELATIVE_PATH from_bindir /${CMAKE_INSTALL_BINDIR} /${CMAKE_INSTALL_LIBDIR}/camwb)
  target_compile_definitions(${ARG_LOADER} PRIVATE
    ${ARG_PLACE}_BUILT="$<TARGET_FILE:${target}>"
    ${ARG_PLACE}_FROM_BINDIR="${from_bindir}/$<TARGET_FILE_NAME:${target}>")
  if(NOT ARG_UNORDERED)
    add_dependencies(${ARG_LOADER} ${target})
  endif()
endfunction()
