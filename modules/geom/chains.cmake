set(GEOM_PART_SOURCES ChainOffset.cpp detail/OffsetCore.cpp)
