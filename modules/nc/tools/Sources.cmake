# Sources of the NC text tools, relative to this folder.
set(NC_PART_SOURCES)
