# Regions (line/arc loops with holes): queries, arc fitting, Clipper offsets/booleans, exact clipping.
set(GEOM_PART_SOURCES Region.cpp RegionIndex.cpp ArcFit.cpp RegionOps.cpp detail/LoopQueries.cpp detail/ClipperRegions.cpp
                      detail/ExactClip.cpp
                      detail/RegionLocator.cpp detail/RawOffset.cpp detail/PieceSnap.cpp)
