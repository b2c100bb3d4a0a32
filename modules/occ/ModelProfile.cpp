// Model::planarFaceOuterProfile and Model::planarFaceRegion: the wires of a face lying in an XY
// plane as geom profiles (the edge-to-segment rules live in EdgeProfile.cpp).
#include "occ/Model.h"

#include "occ/detail/EdgeProfile.h"
#include "occ/detail/ModelData.h"

#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <string>

namespace camwb::occ {
namespace {

std::string faceName(int faceIndex) { return "face " + std::to_string(faceIndex); }

// Counter-clockwise seen from +Z (or clockwise when `ccw` is false), whatever way the wire ran.
geom::Profile oriented(geom::Profile profile, bool ccw)
{
    if ((profile.signedArea() > 0) != ccw)
        profile = profile.reversed();
    return profile;
}

base::Result<geom::Profile> outerProfile(const TopoDS_Face& face, double toleranceMm)
{
    const TopoDS_Wire wire = BRepTools::OuterWire(face);
    if (wire.IsNull())
        return base::makeError("the face has no outer wire");
    base::Result<geom::Profile> profile = wireProfile(wire, face, toleranceMm);
    if (!profile)
        return profile;
    return oriented(std::move(profile.value()), true);
}

base::Result<geom::Region> region(const TopoDS_Face& face, double toleranceMm)
{
    const TopoDS_Wire outerWire = BRepTools::OuterWire(face);
    if (outerWire.IsNull())
        return base::makeError("the face has no outer wire");
    geom::Region result;
    for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next()) {
        const TopoDS_Wire& wire = TopoDS::Wire(it.Current());
        const bool outer = wire.IsSame(outerWire);
        base::Result<geom::Profile> profile = wireProfile(wire, face, toleranceMm);
        if (!profile)
            return profile.error();
        if (outer)
            result.outer = oriented(std::move(profile.value()), true);
        else
            result.holes.push_back(oriented(std::move(profile.value()), false));
    }
    return result;
}

// Runs `make` on a face normal to Z, turning the checks and OCCT failures into errors naming the face.
template <class T, class Make>
base::Result<T> withZFace(const ModelData& model, int faceIndex, double toleranceMm, Make make)
{
    if (faceIndex < 1 || faceIndex > model.faceCount())
        return base::makeError(faceName(faceIndex) + " does not exist (the model has " +
                               std::to_string(model.faceCount()) + " faces)");
    const FaceInfo info = model.face(faceIndex);
    if (!info.planar)
        return base::makeError(faceName(faceIndex) + " is not planar");
    if (1 - std::abs(info.normal.z) >= kZAxisTolerance)
        return base::makeError(faceName(faceIndex) + " is not normal to Z");
    if (!(toleranceMm > 0))
        return base::makeError("the tolerance must be positive");
    try {
        base::Result<T> result = make(TopoDS::Face(model.faces(faceIndex)), toleranceMm);
        if (!result)
            return base::makeError(faceName(faceIndex) + ": " + result.error().message);
        return result;
    } catch (const Standard_Failure& e) {
        return base::makeError(faceName(faceIndex) + ": OCCT failure: " + e.GetMessageString());
    }
}

}  // namespace

base::Result<geom::Profile> ModelData::planarFaceOuterProfile(int faceIndex, double toleranceMm) const
{
    return withZFace<geom::Profile>(*this, faceIndex, toleranceMm, outerProfile);
}

base::Result<geom::Region> ModelData::planarFaceRegion(int faceIndex, double toleranceMm) const
{
    return withZFace<geom::Region>(*this, faceIndex, toleranceMm, region);
}

}  // namespace camwb::occ
