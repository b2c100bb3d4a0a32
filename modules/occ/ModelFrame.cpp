// The model seen in a tilted frame (3+2 machining) and the axis of a cylindrical face.
#include "occ/Model.h"
#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>
#include <gp_Trsf.hxx>

#include <cmath>

namespace camwb::occ {

base::Result<std::shared_ptr<const ModelImpl>> ModelData::inFrame(const base::Vec3& origin, const base::Vec3& xAxis,
                                                                  const base::Vec3& zAxis) const
{
    if (!hasBRep())
        return base::makeError("a mesh (STL) model has no faces to work on in a tilted plane", path);
    if (std::abs(xAxis.length() - 1) > 1e-9 || std::abs(zAxis.length() - 1) > 1e-9 || std::abs(xAxis.dot(zAxis)) > 1e-9)
        return base::makeError("a frame needs unit x and z axes at right angles", path);
    const base::Vec3 yAxis = zAxis.cross(xAxis);
    // Workpiece -> frame: the rows of the rotation are the frame's axes, p' = R (p - origin).
    gp_Trsf toFrame;
    toFrame.SetValues(xAxis.x, xAxis.y, xAxis.z, -xAxis.dot(origin),  //
                      yAxis.x, yAxis.y, yAxis.z, -yAxis.dot(origin),  //
                      zAxis.x, zAxis.y, zAxis.z, -zAxis.dot(origin));
    auto data = std::make_shared<ModelData>();
    data->path = path;
    try {
        // Moved, not copied: the same faces and edges under a location, so the map order (the
        // indices a job refers to) stays what it is in the workpiece frame.
        data->shape = shape.Moved(TopLoc_Location(toFrame));
        describeShape(*data);
    } catch (const Standard_Failure& e) {
        return base::makeError(std::string("could not turn the model into the working plane: ") + e.GetMessageString(),
                               path);
    }
    if (data->faces.Extent() != faces.Extent() || data->edges.Extent() != edges.Extent())
        return base::makeError("turning the model into the working plane changed its faces", path);
    return std::shared_ptr<const ModelImpl>(std::move(data));
}

std::optional<base::Vec3> ModelData::cylinderAxis(int faceIndex) const
{
    if (!hasBRep() || faceIndex < 1 || faceIndex > faces.Extent())
        return std::nullopt;
    try {
        BRepAdaptor_Surface surface(TopoDS::Face(faces(faceIndex)));
        if (surface.GetType() != GeomAbs_Cylinder)
            return std::nullopt;
        const gp_Dir d = surface.Cylinder().Axis().Direction();
        return base::Vec3{d.X(), d.Y(), d.Z()};
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

}  // namespace camwb::occ
