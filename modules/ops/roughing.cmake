# The 3D pocket (z-level roughing, Pocket3dOp.h) and waterline finishing (WaterlineOp.h) with the
# tool-centre regions they share (surface/ToolCentre.h, surface/MeshShadow.h), rest material and
# the check of the regions against the model's sections (surface/SectionCheck.h).
set(OPS_PART_SOURCES surface/AllCores.cpp surface/MeshShadow.cpp surface/BallReach.cpp surface/ToolCentre.cpp surface/RestMaterial.cpp surface/SectionCheck.cpp
                     Pocket3dOp.cpp
                     WaterlineOp.cpp)
