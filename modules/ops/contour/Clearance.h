// The finished contour and where its material is, for the gouge guard: every move a contour
// emits beside the loop itself (leads, helices, links, approach points) is checked to keep the
// tool clear of the part before anything is produced.
#pragma once

#include "base/Result.h"
#include "geom/Profile.h"
#include "ops/contour/Path.h"

#include <string>
#include <vector>

namespace camwb::ops::contour {

enum class MaterialSide { InsideLoop, OutsideLoop, LeftOfChain, RightOfChain, None };

class Material {
public:
    Material(geom::Profile contour, MaterialSide side);

    // Distance from the contour, negative on the material side (None: plain distance).
    double clearance(Vec2 p) const;
    MaterialSide side() const { return m_side; }

private:
    bool insideLoop(Vec2 p) const;

    geom::Profile m_contour;
    MaterialSide m_side;
    std::vector<Vec2> m_polygon;  // the loop, finely discretised, for inside tests
};

// Ok when every point of the pieces keeps clearance >= minimum - 1e-6 (sampled every `step` mm
// and at the ends); else an error "<what> ... at (x, y)".
base::Status checkClear(const Material& material, const std::vector<Segment>& pieces, double minimum, double step,
                        const std::string& what);

}  // namespace camwb::ops::contour
