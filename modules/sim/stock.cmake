# Stock removal (issue 14): revolved tools, the three-axis height field, the tri-dexel stock for
# tilted tools and undercuts, and the factory that picks one.
set(SIM_PART_SOURCES ToolShape.cpp MeshRays.cpp HeightField.cpp HeightFieldMesh.cpp TriDexel.cpp TriDexelMesh.cpp
    MakeStock.cpp MeshDistance.cpp)
