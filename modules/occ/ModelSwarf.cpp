// Model::swarfFace: a face as a ruled, developable surface for swarf milling. The rulings come from
// the surface's kind (a plane's line across the drive edge, a cylinder's axis, a cone's line to its
// apex, an extrusion's direction); their sense and length across the face from the face's own
// boundary (classified in its parameter space).
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <ShapeAnalysis_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <cmath>
#include <memory>
#include <optional>

namespace camwb::occ {

namespace {

base::Vec3 vec(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

std::string surfaceName(GeomAbs_SurfaceType type)
{
    switch (type) {
    case GeomAbs_Plane:
        return "plane";
    case GeomAbs_Cylinder:
        return "cylinder";
    case GeomAbs_Cone:
        return "cone";
    case GeomAbs_SurfaceOfExtrusion:
        return "extrusion";
    case GeomAbs_Sphere:
        return "sphere";
    case GeomAbs_Torus:
        return "torus";
    case GeomAbs_BSplineSurface:
        return "B-spline surface";
    case GeomAbs_BezierSurface:
        return "Bezier surface";
    case GeomAbs_SurfaceOfRevolution:
        return "surface of revolution";
    default:
        return "free-form surface";
    }
}

// Evaluates rulings of one face; shared by the SwarfFace's evaluator (copies of it share it).
class RulingEvaluator {
public:
    RulingEvaluator(const TopoDS_Face& face, const TopoDS_Edge& edge, double maxLength) :
        m_face(face),
        m_surface(face),
        m_analysis(BRep_Tool::Surface(face)),
        m_classifier(face, 1e-7),
        m_curve(edge),
        m_props(face),
        m_maxLength(maxLength)
    {
    }

    GeomAbs_SurfaceType type() const { return m_surface.GetType(); }
    const BRepAdaptor_Curve& curve() const { return m_curve; }

    // The ruling through p (either sense); nullopt at a cone's apex.
    std::optional<gp_Dir> rulingLine(const gp_Pnt& p, const gp_Vec& tangent, const gp_Dir& normal) const
    {
        switch (m_surface.GetType()) {
        case GeomAbs_Plane: {
            const gp_Vec across = gp_Vec(normal).Crossed(tangent);
            return across.Magnitude() < 1e-12 ? std::nullopt : std::optional<gp_Dir>(gp_Dir(across));
        }
        case GeomAbs_Cylinder:
            return m_surface.Cylinder().Axis().Direction();
        case GeomAbs_Cone: {
            const gp_Vec toApex(p, m_surface.Cone().Apex());
            return toApex.Magnitude() < 1e-9 ? std::nullopt : std::optional<gp_Dir>(gp_Dir(toApex));
        }
        case GeomAbs_SurfaceOfExtrusion:
            return m_surface.Direction();
        default:
            return std::nullopt;
        }
    }

    bool onFace(const gp_Pnt& q) const
    {
        const gp_Pnt2d uv = m_analysis.ValueOfUV(q, 1e-7);
        if (m_analysis.Gap() > 1e-5)
            return false;
        const TopAbs_State state = m_classifier.Perform(uv);
        return state == TopAbs_IN || state == TopAbs_ON;
    }

    gp_Dir normalAt(const gp_Pnt& p) const
    {
        const gp_Pnt2d uv = m_analysis.ValueOfUV(p, 1e-7);
        gp_Pnt at;
        gp_Vec n;
        m_props.Normal(uv.X(), uv.Y(), at, n);  // outward: the face's orientation in the solid
        return gp_Dir(n);
    }

    // How far the ruling from p in `dir` stays on the face (0: it leaves at once).
    double lengthAlong(const gp_Pnt& p, const gp_Dir& dir) const
    {
        const double step = 0.5;
        double in = 0, out = -1;
        for (double s = 0.01; s <= m_maxLength; s += step) {
            if (!onFace(p.Translated(gp_Vec(dir) * s))) {
                out = s;
                break;
            }
            in = s;
        }
        if (in == 0)
            return 0;
        if (out < 0)
            return in;
        for (int i = 0; i < 14; ++i) {
            const double mid = (in + out) / 2;
            (onFace(p.Translated(gp_Vec(dir) * mid)) ? in : out) = mid;
        }
        return in;
    }

    RulingPoint at(double t) const
    {
        gp_Pnt p;
        gp_Vec tangent;
        m_curve.D1(t, p, tangent);
        const gp_Dir normal = normalAt(p);
        RulingPoint out;
        out.point = vec(p.XYZ());
        const std::optional<gp_Dir> line = rulingLine(p, tangent, normal);
        if (!line)
            return out;
        const gp_Dir ruling = m_sense > 0 ? *line : line->Reversed();
        // The normal square to the ruling (it is on a developable face; this removes rounding).
        const gp_Vec n = gp_Vec(normal) - gp_Vec(ruling) * gp_Vec(normal).Dot(gp_Vec(ruling));
        out.ruling = vec(ruling.XYZ());
        out.normal = n.Magnitude() > 1e-12 ? vec(gp_Dir(n).XYZ()) : vec(normal.XYZ());
        out.lengthMm = lengthAlong(p, ruling);
        return out;
    }

    // The rulings' sense across the face: rulingLine's sense is continuous along the edge, so the
    // one that stays longer on the face at a few points holds all along (at the ends of an edge,
    // where the face narrows to a corner, both senses may leave the face at once).
    void chooseSense()
    {
        double balance = 0;
        for (int i = 0; i < 5; ++i) {
            const double t =
                m_curve.FirstParameter() + (m_curve.LastParameter() - m_curve.FirstParameter()) * (0.1 + 0.2 * i);
            gp_Pnt p;
            gp_Vec tangent;
            m_curve.D1(t, p, tangent);
            if (const std::optional<gp_Dir> line = rulingLine(p, tangent, normalAt(p)))
                balance += lengthAlong(p, *line) - lengthAlong(p, line->Reversed());
        }
        m_sense = balance >= 0 ? 1 : -1;
    }

private:
    TopoDS_Face m_face;
    BRepAdaptor_Surface m_surface;
    mutable ShapeAnalysis_Surface m_analysis;
    BRepTopAdaptor_FClass2d m_classifier;  // built once: classifying a point is then quick
    BRepAdaptor_Curve m_curve;
    mutable BRepGProp_Face m_props;
    double m_maxLength;
    int m_sense = 1;  // +1: rulingLine's sense points across the face
};

// Whether the edge runs along the face's rulings (a cone's seam, a plane's or cylinder's side).
bool alongRulings(const RulingEvaluator& e, double t)
{
    gp_Pnt p;
    gp_Vec tangent;
    e.curve().D1(t, p, tangent);
    if (tangent.Magnitude() < 1e-12)
        return true;
    const std::optional<gp_Dir> line = e.rulingLine(p, tangent, e.normalAt(p));
    return !line || std::abs(gp_Dir(tangent).Dot(*line)) > 1 - 1e-6;
}

double meanZ(const BRepAdaptor_Curve& c)
{
    double z = 0;
    for (int i = 0; i <= 8; ++i)
        z += c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / 8).Z();
    return z / 9;
}

}  // namespace

base::Result<SwarfFace> ModelData::swarfFace(int faceIndex, int edgeIndex) const
{
    const std::string name = "face " + std::to_string(faceIndex);
    if (!hasBRep() || faceIndex < 1 || faceIndex > faces.Extent())
        return base::makeError(name + " is not in the model");
    try {
        const TopoDS_Face face = TopoDS::Face(faces(faceIndex));
        const double maxLength = distance(boundsMin, boundsMax) + 1;
        const GeomAbs_SurfaceType type = BRepAdaptor_Surface(face).GetType();
        if (type != GeomAbs_Plane && type != GeomAbs_Cylinder && type != GeomAbs_Cone &&
            type != GeomAbs_SurfaceOfExtrusion)
            return base::makeError(name + " is a " + surfaceName(type) +
                                   ", not a ruled developable surface: swarf milling follows planes, cylinders, "
                                   "cones and linear extrusions");
        // The drive edge: the one given, else the lowest edge across the rulings.
        std::optional<TopoDS_Edge> drive;
        double lowest = 1e300;
        for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
            const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
            if (BRep_Tool::Degenerated(edge))
                continue;
            const int index = edges.FindIndex(edge);
            if (edgeIndex != 0) {
                if (index == edgeIndex)
                    drive = edge;
                continue;
            }
            if (BRep_Tool::IsClosed(edge, face))
                continue;  // a seam
            const RulingEvaluator e(face, edge, maxLength);
            const double mid = (e.curve().FirstParameter() + e.curve().LastParameter()) / 2;
            if (alongRulings(e, mid) || meanZ(e.curve()) >= lowest - 1e-9)
                continue;
            lowest = meanZ(e.curve());
            drive = edge;
        }
        if (!drive)
            return base::makeError(edgeIndex != 0 ? "edge " + std::to_string(edgeIndex) + " is not an edge of " + name
                                                  : name + " has no edge across its rulings to drive along");
        auto evaluator = std::make_shared<RulingEvaluator>(face, *drive, maxLength);
        evaluator->chooseSense();
        SwarfFace out;
        out.face = faceIndex;
        out.edge = edges.FindIndex(*drive);
        out.surface = surfaceName(type);
        out.t0 = evaluator->curve().FirstParameter();
        out.t1 = evaluator->curve().LastParameter();
        out.closed = evaluator->curve().Value(out.t0).Distance(evaluator->curve().Value(out.t1)) < 1e-7;
        for (int i = 0; i <= 4; ++i) {
            const double t = out.t0 + (out.t1 - out.t0) * (0.1 + 0.2 * i);
            if (alongRulings(*evaluator, t))
                return base::makeError("edge " + std::to_string(out.edge) + " runs along the rulings of " + name +
                                       ": pick an edge across them (the bottom edge)");
            if (evaluator->at(t).lengthMm <= 0)
                return base::makeError(name + ": the ruling at a point of edge " + std::to_string(out.edge) +
                                       " does not cross the face");
        }
        out.at = [evaluator](double t) { return evaluator->at(t); };
        return out;
    } catch (const Standard_Failure& failure) {
        return base::makeError(name + ": " + failure.GetMessageString());
    }
}

}  // namespace camwb::occ
