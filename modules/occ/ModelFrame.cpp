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

base::Result<Model> Model::inFrame(const base::Vec3& origin, const base::Vec3& xAxis, const base::Vec3& zAxis) const
{
    if (!hasBRep())
        return base::makeError("a mesh (STL) model has no faces to work on in a tilted plane",
                               m_data ? m_data->path : std::string());
    if (std::abs(xAxis.length() - 1) > 1e-9 || std::abs(zAxis.length() - 1) > 1e-9 || std::abs(xAxis.dot(zAxis)) > 1e-9)
        return base::makeError("a frame needs unit x and z axes at right angles", m_data->path);
    const base::Vec3 yAxis = zAxis.cross(xAxis);
    // Workpiece -> frame: the rows of the rotation are the frame's axes, p' = R (p - origin).
    gp_Trsf toFrame;
    toFrame.SetValues(xAxis.x, xAxis.y, xAxis.z, -xAxis.dot(origin),  //
                      yAxis.x, yAxis.y, yAxis.z, -yAxis.dot(origin),  //
                      zAxis.x, zAxis.y, zAxis.z, -zAxis.dot(origin));
    auto data = std::make_shared<ModelData>();
    data->path = m_data->path;
    try {
        // Moved, not copied: the same faces and edges under a location, so the map order (the
        // indices a job refers to) stays what it is in the workpiece frame.
        data->shape = m_data->shape.Moved(TopLoc_Location(toFrame));
        describeShape(*data);
    } catch (const Standard_Failure& e) {
        return base::makeError(std::string("could not turn the model into the working plane: ") + e.GetMessageString(),
                               m_data->path);
    }
    if (data->faces.Extent() != m_data->faces.Extent() || data->edges.Extent() != m_data->edges.Extent())
        return base::makeError("turning the model into the working plane changed its faces", m_data->path);
    return Model(std::move(data));
}

std::optional<base::Vec3> Model::cylinderAxis(int faceIndex) const
{
    if (!hasBRep() || faceIndex < 1 || faceIndex > m_data->faces.Extent())
        return std::nullopt;
    try {
        BRepAdaptor_Surface surface(TopoDS::Face(m_data->faces(faceIndex)));
        if (surface.GetType() != GeomAbs_Cylinder)
            return std::nullopt;
        const gp_Dir d = surface.Cylinder().Axis().Direction();
        return base::Vec3{d.X(), d.Y(), d.Z()};
    } catch (const Standard_Failure&) {
        return std::nullopt;
    }
}

}  // namespace camwb::occ
