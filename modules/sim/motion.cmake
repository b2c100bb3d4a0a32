# Motion in time (the plan on a machine, fixed-step samples), seed 003's path analysis and
# measured traces (issue 14).
set(SIM_PART_SOURCES MachineAxes.cpp MotionPlan.cpp MotionSamples.cpp PathAnalysis.cpp MeasuredTrace.cpp PathDistance.cpp)
