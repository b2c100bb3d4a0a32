# The turning stock and its checks. The seed-001 tests read the groove programs through the
# SINUMERIK interpreter, so this binary links camwb_nc (a test, not a module: no module edge).
camwb_add_gtest(camwb_sim_turning_tests SOURCES TurningStockTest.cpp TurningSeedTest.cpp GrooveSubprogramsTest.cpp GrooveSweepTest.cpp DEPS camwb_sim camwb_nc
                LABELS sim)
