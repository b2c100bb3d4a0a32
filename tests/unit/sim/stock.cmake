# Tests of stock removal (issue 14): revolved tools, the height field, the tri-dexel stock.
camwb_add_gtest(camwb_sim_stock_tests SOURCES HeightFieldTest.cpp HeightFieldArcTest.cpp TriDexelTest.cpp MeshDistanceTest.cpp DEPS camwb_sim LABELS sim)
