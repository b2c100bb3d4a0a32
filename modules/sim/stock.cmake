# Stock removal (issue 14): revolved tools, the three-axis height field, the tri-dexel stock for
# tilted tools and undercuts, and the factory that picks one.
set(SIM_PART_SOURCES ToolShape.cpp MeshRays.cpp HeightField.cpp HeightFieldArc.cpp HeightFieldMesh.cpp TriDexel.cpp TriDexelMesh.cpp
    MakeStock.cpp MeshDistance.cpp)
# The height field's sweep takes a square root or more a row: without errno to set, sqrt is one
# instruction with no branch to a library call beside it.
set_source_files_properties(HeightField.cpp HeightFieldArc.cpp PROPERTIES COMPILE_OPTIONS -fno-math-errno)
