// A point of a ruled surface's drive edge with the surface's ruling and normal there: what the
// model (occ/Swarf.h) tells swarf milling (ops/SwarfOp.h) about a face, without either knowing
// the other.
#pragma once

#include "base/Vec.h"

namespace camwb::geom {

// The ruling through `point` (unit, from the edge across the face), its length across the face,
// and the face's unit normal there (pointing away from the material, square to the ruling).
struct RulingPoint {
    base::Vec3 point;
    base::Vec3 ruling;
    base::Vec3 normal;
    double lengthMm = 0;
};

}  // namespace camwb::geom
