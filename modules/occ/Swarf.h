// Swarf milling's questions to the model: a face as a ruled, developable surface driven along one
// of its edges (the ruling and the normal at each point of that edge), and the gouge check of tool
// poses against the whole model. OCCT-free: the evaluator hides the surface behind a function.
#pragma once

#include "base/Vec.h"
#include "geom/Ruling.h"

#include <functional>
#include <string>

namespace camwb::occ {

using geom::RulingPoint;

// A face that swarf milling can follow: its rulings known along the drive edge's parameter range.
struct SwarfFace {
    int face = 0;
    int edge = 0;
    std::string surface;  // "plane", "cylinder", "cone", "extrusion"
    double t0 = 0, t1 = 1;
    bool closed = false;  // the drive edge is closed (t0 and t1 are the same point)
    std::function<RulingPoint(double t)> at;
};

// A tool pose for the gouge check: tip and unit axis (from the tip towards the spindle).
struct ToolPose {
    base::Vec3 tip;
    base::Vec3 axis;
};

// Where a tool pose enters the model: the pose's index, a point of the tool inside the material,
// and the face nearest to it.
struct Gouge {
    int pose = -1;
    base::Vec3 point;
    int face = 0;
};

}  // namespace camwb::occ
