# Runs the CLI under the dynamic loader's trace (LD_DEBUG=files, which names every library as it
# is opened) and checks that the command succeeds without loading Qt at all, OCCT (and the OCCT
# kernel), the post engine or the setup sheet's painter: commands that read no model, post nothing
# and draw no setup sheet start without them (modules/occ/Kernel.cpp, post/PostProcessor.cpp,
# sheet/SheetPainter.h). The trace must name the C++ library, which the CLI links, so that a trace
# that stopped working fails the test.
execute_process(COMMAND ${CMAKE_COMMAND} -E env LD_DEBUG=files ${CLI} ${ARGS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT err MATCHES "file=libstdc[+][+]")
  message(FATAL_ERROR "the loader's trace does not name libstdc++ (LD_DEBUG not honoured?):\n${err}")
endif()
if(err MATCHES "file=[^ ]*(libTK[A-Za-z0-9]*|libcamwb_occ_kernel|libQt6[A-Za-z]*|libcamwb_post_engine|libcamwb_sheet_painter)[.]so")
  message(FATAL_ERROR "the command loaded ${CMAKE_MATCH_1}, though it reads no model, posts nothing and draws no sheet:\n${err}")
endif()
