set(GEOM_PART_SOURCES ChainOffset.cpp CarrierIntersection.cpp detail/OffsetCore.cpp)
