# tests of the stock part: camwb_add_gtest(camwb_sim_stock_tests ...)
