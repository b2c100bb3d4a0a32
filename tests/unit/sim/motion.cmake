# tests of the motion part: camwb_add_gtest(camwb_sim_motion_tests ...)
