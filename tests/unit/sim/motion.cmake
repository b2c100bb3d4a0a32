# Motion in time, the path analysis and measured traces.
camwb_add_gtest(camwb_sim_motion_tests SOURCES MotionPlanTest.cpp PathAnalysisTest.cpp MeasuredTraceTest.cpp DEPS camwb_sim LABELS sim)
