# Makes the DEB as `cpack -G DEB` in the build folder does (into a scratch folder) and checks what
# a user installs: both programs are in it and stripped, so are the libraries they load on use
# (the OCCT kernel, the setup sheet's painter) and the installed program finds them, and the
# installed size stays small.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${CPACK} -G DEB --config ${BUILD_DIR}/CPackConfig.cmake -B ${WORK}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cpack failed (${rc}):\n${out}${err}")
endif()
file(GLOB debs ${WORK}/*.deb)
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one .deb in ${WORK}, found: ${debs}")
endif()
execute_process(COMMAND dpkg-deb -f ${debs} Installed-Size OUTPUT_VARIABLE kib OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT kib MATCHES "^[0-9]+$" OR kib GREATER 20000)
  message(FATAL_ERROR "installed size ${kib} KiB: more than 20 MB (unstripped binaries?)")
endif()
execute_process(COMMAND dpkg-deb -x ${debs} ${WORK}/root RESULT_VARIABLE rc)
# The libraries the programs load on use are installed beside them: the OCCT kernel (modules/occ)
# with the first model, the post engine (post/PostProcessor.cpp) with the first post, the setup
# sheet's painter (sheet/SheetPainter.h) with the CLI's first sheet.
set(plugins "")
foreach(name IN ITEMS libcamwb_occ_kernel.so libcamwb_post_engine.so libcamwb_sheet_painter.so)
  file(GLOB_RECURSE found RELATIVE ${WORK}/root ${WORK}/root/usr/lib/*/${name})
  list(LENGTH found count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "expected one usr/lib/.../camwb/${name} in the package, found: ${found}")
  endif()
  list(APPEND plugins ${found})
endforeach()
foreach(binary IN ITEMS usr/bin/camwb usr/bin/camwb-cli ${plugins})
  if(NOT EXISTS ${WORK}/root/${binary})
    message(FATAL_ERROR "the package has no ${binary}")
  endif()
  execute_process(COMMAND file -b ${WORK}/root/${binary} OUTPUT_VARIABLE kind)
  if(NOT kind MATCHES ", stripped")
    message(FATAL_ERROR "${binary} is not stripped: ${kind}")
  endif()
endforeach()
# The installed program finds the installed libraries, not the build tree's (the variables that
# would name others cleared): the example's setup sheet reads the model, posts it and draws.
set(examples ${WORK}/root/usr/share/camwb/examples)
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=CAMWB_OCC_KERNEL --unset=CAMWB_SHEET_PAINTER
                        --unset=CAMWB_POST_ENGINE LD_DEBUG=files
                        ${WORK}/root/usr/bin/camwb-cli setup-sheet ${examples}/example-block.camwb --no-sim
                        -o ${WORK}/sheet/example.html
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORK}/sheet/example.html OR NOT EXISTS ${WORK}/sheet/example-images/part.png)
  message(FATAL_ERROR "the installed camwb-cli could not draw the installed example's setup sheet (${rc}):\n${out}${err}")
endif()
# The loader's trace (LD_DEBUG=files) names each library as it opens it.
foreach(plugin IN LISTS plugins)
  string(FIND "${err}" "file=${WORK}/root/${plugin} " found)
  if(found EQUAL -1)
    message(FATAL_ERROR "the installed camwb-cli did not load the installed ${WORK}/root/${plugin}:\n${err}")
  endif()
endforeach()
# Every library an installed post includes is installed beside it (posts/include/<name>.js).
file(GLOB installed_posts ${WORK}/root/usr/share/camwb/posts/*.js)
if(NOT installed_posts)
  message(FATAL_ERROR "the package has no post scripts in usr/share/camwb/posts")
endif()
foreach(post IN LISTS installed_posts)
  file(STRINGS ${post} includes REGEX "^include\\(\"[a-z0-9_-]+\"\\)")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^include\\(\"([a-z0-9_-]+)\"\\).*" "\\1" name "${line}")
    if(NOT EXISTS ${WORK}/root/usr/share/camwb/posts/include/${name}.js)
      message(FATAL_ERROR "${post} includes '${name}', which the package lacks (usr/share/camwb/posts/include/${name}.js)")
    endif()
  endforeach()
endforeach()
message(STATUS "package ${debs}: ${kib} KiB installed, binaries stripped")
