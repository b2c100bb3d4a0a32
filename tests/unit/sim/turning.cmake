# tests of the turning part: camwb_add_gtest(camwb_sim_turning_tests ...)
