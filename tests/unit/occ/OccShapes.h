// Small OCCT solids for the occ tests (boxes, rounded boxes and vertical cylinders as the example
// part makes them, booleans) and a way to load them through Model::load (written as BREP into the
// scratch folder).
#pragma once

#include "OccTestUtil.h"

#include "occ/Model.h"
#include "occ/detail/PartBuilders.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace camwb::occ::test {

inline TopoDS_Shape box(double x0, double y0, double z0, double x1, double y1, double z1)
{
    return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), gp_Pnt(x1, y1, z1)).Shape();
}

// A box with its vertical edges rounded to `radius`.
inline TopoDS_Shape roundedBox(double x0, double y0, double z0, double x1, double y1, double z1, double radius)
{
    return parts::roundedBox(gp_Pnt(x0, y0, z0), gp_Pnt(x1, y1, z1), radius);
}

inline TopoDS_Shape cylinder(double x, double y, double radius, double z0, double z1)
{
    return parts::verticalCylinder(x, y, radius, z0, z1);
}

inline TopoDS_Shape cut(const TopoDS_Shape& from, const TopoDS_Shape& tool)
{
    BRepAlgoAPI_Cut result(from, tool);
    if (!result.IsDone())
        throw std::runtime_error("boolean cut failed");
    return result.Shape();
}

inline TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b)
{
    BRepAlgoAPI_Fuse result(a, b);
    if (!result.IsDone())
        throw std::runtime_error("boolean fuse failed");
    return result.Shape();
}

// Writes the shape as BREP and loads it as a Model (so the tests go through the real loader).
inline Model loadShape(const TopoDS_Shape& shape, const std::string& name)
{
    const std::string path = (scratchDir() / (name + ".brep")).string();
    if (!BRepTools::Write(shape, path.c_str()))
        throw std::runtime_error("could not write " + path);
    base::Result<Model> model = Model::load(path);
    if (!model)
        throw std::runtime_error(model.error().toString());
    return model.value();
}

// The planar face with the given normal Z (+1 or -1) at plane Z; with several, the largest. 0 if none.
inline int zFace(const Model& model, double normalZ, double z)
{
    int best = 0;
    for (int i = 1; i <= model.faceCount(); ++i) {
        const FaceInfo f = model.face(i);
        if (f.planar && std::abs(f.normal.z - normalZ) < 1e-9 && std::abs(f.planeZ - z) < 1e-9 &&
            (best == 0 || f.areaMm2 > model.face(best).areaMm2))
            best = i;
    }
    return best;
}

struct SegmentCounts {
    int lines = 0;
    int arcs = 0;
};

inline SegmentCounts countSegments(const geom::Profile& profile)
{
    SegmentCounts counts;
    for (const geom::Segment& s : profile.segments)
        (s.isArc() ? counts.arcs : counts.lines)++;
    return counts;
}

}  // namespace camwb::occ::test
