# Sources of the sinumerik interpreter, relative to this folder.
set(NC_PART_SOURCES SinumerikInterpreter.cpp)
