# Parallel (raster) and waterline finishing, the drop-cutter under both and the waterline's contours
# of its heights (surface/DropContours.h) (issue 16).
set(OPS_PART_SOURCES surface/CutterProfile.cpp surface/TriangleGrid.cpp surface/DropCutter.cpp surface/CutLine.cpp
  surface/DropContours.cpp WaterlineOp.cpp
  ParallelGrid.cpp ParallelOp.cpp)
