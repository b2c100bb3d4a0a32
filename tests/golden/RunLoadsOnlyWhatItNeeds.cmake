# Runs the CLI under the dynamic loader's trace (LD_DEBUG=files, which names every library as it
# is opened) and checks that the command succeeds without loading OCCT (and the OCCT kernel), Qt Qml
# (and the post engine) or Qt Gui (and the setup sheet's painter): commands that read no model, post
# nothing and draw no setup sheet start without them (modules/occ/Kernel.cpp,
# post/PostProcessor.cpp, sheet/SheetPainter.h). The trace must name Qt's core library, which the CLI links, so that a
# trace that stopped working fails the test.
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${CLI} ${ARGS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "file=libQt6Core")
  message(FATAL_ERROR "the loader's trace does not name libQt6Core (LD_DEBUG not honoured?):\n${err}")
endif()
if(err MATCHES "file=[^ ]*(libTK[A-Za-z0-9]*|libcamwb_occ_kernel|libQt6Qml|libcamwb_post_engine|libQt6Gui|libcamwb_sheet_painter)[.]so")
  message(FATAL_ERROR "the command loaded ${CMAKE_MATCH_1}, though it reads no model, posts nothing and draws no sheet:\n${err}")
endif()
