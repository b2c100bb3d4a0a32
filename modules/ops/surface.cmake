# What the 3D operations share (surface/): their input and the silhouette of selected faces.
set(OPS_PART_SOURCES surface/Silhouette.cpp)
