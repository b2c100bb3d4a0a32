# Turning: the groove roughing of seed-001 (Šolar 2015) made safe; its sweeps apart from the records.
set(OPS_PART_SOURCES GrooveOp.cpp turning/GrooveSweeps.cpp)
