# Sources of the iso interpreter, relative to this folder.
set(NC_PART_SOURCES IsoInterpreter.cpp)
