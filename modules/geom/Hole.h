// A cylindrical hole of the model, as the drilling and helix operations need it: vertical axis,
// centre in XY, diameter, top and bottom Z, through or blind.
#pragma once

#include "base/Vec.h"

namespace camwb::geom {

struct Hole {
    int faceIndex = 0;  // the model's cylindrical face (1-based): identifies the hole in a job
    base::Vec2 center;
    double diameterMm = 0;
    double topZ = 0;
    double bottomZ = 0;
    bool through = false;
};

}  // namespace camwb::geom
