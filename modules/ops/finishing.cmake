# Parallel (raster) finishing and the drop-cutter under it (issue 16).
set(OPS_PART_SOURCES surface/CutterProfile.cpp surface/TriangleGrid.cpp surface/DropCutter.cpp surface/CutLine.cpp
  ParallelGrid.cpp ParallelOp.cpp)
