# Hole operations: helix (hole milling) and drilling, with the shared hole order.
set(OPS_PART_SOURCES HelixOp.cpp DrillOp.cpp HoleOrder.cpp)
