// Private to modules/occ (and its tests): the few OCCT solids the example part is made of, so that
// the generator and the tests build their blocks the same way.
#pragma once

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>

#include "base/Result.h"

#include <cmath>
#include <functional>
#include <string>

namespace camwb::occ::parts {

// A box from (x0, y0, z0) to (x1, y1, z1) with its vertical edges rounded to `radius`.
inline TopoDS_Shape roundedBox(gp_Pnt lo, gp_Pnt hi, double radius)
{
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(lo, hi).Shape();
    BRepFilletAPI_MakeFillet fillet(box);
    for (TopExp_Explorer it(box, TopAbs_EDGE); it.More(); it.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
        const gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge));
        const gp_Pnt b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
        if (std::abs(a.X() - b.X()) < 1e-9 && std::abs(a.Y() - b.Y()) < 1e-9)
            fillet.Add(radius, edge);  // the explorer meets each edge twice; Add ignores repeats
    }
    return fillet.Shape();
}

// A cylinder around the vertical axis through (x, y), from z0 up to z1.
inline TopoDS_Shape verticalCylinder(double x, double y, double radius, double z0, double z1)
{
    return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp::DZ()), radius, z1 - z0).Shape();
}

// A drilled blind hole's volume: the cylinder from the shoulder z0 up to z1 and below it the
// drill's point, a cone of `pointAngleDeg` included angle, as a twist drill leaves it.
inline TopoDS_Shape drilledHole(double x, double y, double radius, double z0, double z1, double pointAngleDeg)
{
    const double pointDepth = radius / std::tan(pointAngleDeg * M_PI / 360);
    const TopoDS_Shape point =
        BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(x, y, z0 - pointDepth), gp::DZ()), 0, radius, pointDepth).Shape();
    BRepAlgoAPI_Fuse hole(verticalCylinder(x, y, radius, z0, z1), point);
    if (!hole.IsDone())
        throw Standard_Failure("fusing a drilled hole's point failed");
    return hole.Shape();
}

// `from` minus `tool`; throws Standard_Failure naming `what` when the boolean fails.
inline TopoDS_Shape cut(const TopoDS_Shape& from, const TopoDS_Shape& tool, const char* what)
{
    BRepAlgoAPI_Cut result(from, tool);
    if (!result.IsDone())
        throw Standard_Failure((std::string("cutting ") + what + " failed").c_str());
    return result.Shape();
}

}  // namespace camwb::occ::parts

namespace camwb::occ::detail {

// Builds the part and writes it as AP214 STEP in mm with a fixed header (name, time stamp), so
// that regenerating gives the same file; written beside the target and renamed (ExamplePart.cpp).
base::Status writeStep(const std::function<TopoDS_Shape()>& build, const char* name, const std::string& stepPath);

}  // namespace camwb::occ::detail
