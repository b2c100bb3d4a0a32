camwb_add_gtest(camwb_sim_run_tests SOURCES RunTest.cpp DEPS camwb_sim LABELS sim)
