# The 3D pocket (z-level roughing, Pocket3dOp.h) with its tool-centre regions (surface/ToolCentre.h,
# surface/MeshShadow.h), rest material and the check of the regions against the model's sections
# (surface/SectionCheck.h). AllCores (the levels on all cores) serves the finishing operations too.
set(OPS_PART_SOURCES surface/AllCores.cpp surface/MeshShadow.cpp surface/BallReach.cpp surface/ToolCentre.cpp surface/RestMaterial.cpp surface/SectionCheck.cpp
                     Pocket3dOp.cpp)
