# tests of the run part: camwb_add_gtest(camwb_sim_run_tests ...)
