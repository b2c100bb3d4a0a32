# Sources of the heidenhain interpreter, relative to this folder.
set(NC_PART_SOURCES HeidenhainInterpreter.cpp)
