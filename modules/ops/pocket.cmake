# The pocket operation (PocketOp.h) and its parts under pocket/.
set(OPS_PART_SOURCES PocketOp.cpp pocket/CutPath.cpp pocket/OffsetPattern.cpp pocket/ZigZagPattern.cpp
                     pocket/Cleanup.cpp pocket/Entry.cpp pocket/PathWriter.cpp pocket/Program.cpp)
