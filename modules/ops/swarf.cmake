# Swarf milling (SwarfOp.h): the simultaneous five-axis operation along a ruled face.
set(OPS_PART_SOURCES SwarfOp.cpp)
