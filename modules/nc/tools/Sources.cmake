# Sources of the NC text tools, relative to this folder.
set(NC_PART_SOURCES BlockNumbers.h BlockNumbers.cpp LineDiff.h LineDiff.cpp ErrorRecords.h ErrorRecords.cpp)
