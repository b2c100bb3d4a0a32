# Mesh slicing (issue 16): sections of a triangle mesh at Z levels and its flat levels.
set(OPS_PART_SOURCES surface/MeshSlicer.cpp)
