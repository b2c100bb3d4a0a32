set(OPS_PART_SOURCES ContourOp.cpp contour/Path.cpp contour/Clearance.cpp contour/Emitter.cpp contour/Leads.cpp
    contour/Checks.cpp contour/Plan.cpp)
