set(SIM_PART_SOURCES Checks.cpp StockRun.cpp Simulation.cpp)
