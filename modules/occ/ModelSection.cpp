// ModelData::sectionLoops: OCCT's exact section of the solid by a horizontal plane
// (BRepAlgoAPI_Section), its edges discretised within a tolerance and chained into closed loops.
// The slow reference that the mesh slicer (ops/surface/MeshSlicer.h) is held against.
#include "occ/Model.h"

#include "occ/detail/ModelData.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <string>
#include <vector>

namespace camwb::occ {
namespace {

// Ends of section edges closer than this are one point (section vertices are far closer).
constexpr double kJoinMm = 1e-4;

using Polyline = std::vector<base::Vec2>;

Polyline edgePoints(const TopoDS_Edge& edge, double toleranceMm)
{
    const BRepAdaptor_Curve curve(edge);
    const GCPnts_QuasiUniformDeflection points(curve, toleranceMm);
    Polyline line;
    if (!points.IsDone())
        return line;
    for (int i = 1; i <= points.NbPoints(); ++i) {
        const gp_Pnt p = points.Value(i);
        line.push_back({p.X(), p.Y()});
    }
    return line;
}

// Chains polylines end to end (either direction) into closed loops; false when one stays open.
bool chain(std::vector<Polyline> pieces, std::vector<Polyline>& loops)
{
    std::vector<char> used(pieces.size(), 0);
    for (std::size_t first = 0; first < pieces.size(); ++first) {
        if (used[first])
            continue;
        used[first] = 1;
        Polyline loop = pieces[first];
        while (distance(loop.back(), loop.front()) > kJoinMm || loop.size() < 3) {
            std::size_t next = pieces.size();
            bool reversed = false;
            for (std::size_t i = 0; i < pieces.size() && next == pieces.size(); ++i) {
                if (used[i])
                    continue;
                if (distance(pieces[i].front(), loop.back()) <= kJoinMm)
                    next = i;
                else if (distance(pieces[i].back(), loop.back()) <= kJoinMm)
                    next = i, reversed = true;
            }
            if (next == pieces.size())
                return false;
            used[next] = 1;
            Polyline piece = std::move(pieces[next]);
            if (reversed)
                std::reverse(piece.begin(), piece.end());
            loop.insert(loop.end(), piece.begin() + 1, piece.end());
        }
        loop.pop_back();  // the first point, repeated
        loops.push_back(std::move(loop));
    }
    return true;
}

double signedArea(const Polyline& loop)
{
    double twice = 0;
    for (std::size_t i = 0; i < loop.size(); ++i)
        twice += loop[i].cross(loop[(i + 1) % loop.size()]);
    return twice / 2;
}

bool inside(base::Vec2 p, const Polyline& loop)
{
    bool in = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const base::Vec2 a = loop[i], b = loop[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
            in = !in;
    }
    return in;
}

// Outer loops counter-clockwise, holes clockwise (even-odd nesting), as the mesh slicer gives them.
void orient(std::vector<Polyline>& loops)
{
    for (std::size_t i = 0; i < loops.size(); ++i) {
        int depth = 0;
        for (std::size_t j = 0; j < loops.size(); ++j)
            depth += j != i && inside(loops[i].front(), loops[j]);
        if ((signedArea(loops[i]) > 0) != (depth % 2 == 0))
            std::reverse(loops[i].begin(), loops[i].end());
    }
}

}  // namespace

base::Result<std::vector<std::vector<base::Vec2>>> ModelData::sectionLoops(double z, double toleranceMm) const
{
    if (!hasBRep())
        return base::makeError("a mesh (STL) model has no exact section; slice its mesh", path);
    if (!(toleranceMm > 0))
        return base::makeError("the section's tolerance must be above 0 mm", path);
    std::vector<Polyline> pieces;
    try {
        BRepAlgoAPI_Section section(shape, gp_Pln(gp_Pnt(0, 0, z), gp_Dir(0, 0, 1)), Standard_False);
        section.Build();
        if (!section.IsDone())
            return base::makeError("OCCT could not section the model at Z " + std::to_string(z), path);
        for (TopExp_Explorer e(section.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
            const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
            if (BRep_Tool::Degenerated(edge))
                continue;
            Polyline line = edgePoints(edge, toleranceMm);
            if (line.size() < 2)
                return base::makeError("a section edge at Z " + std::to_string(z) + " could not be discretised", path);
            pieces.push_back(std::move(line));
        }
    } catch (const Standard_Failure& failure) {
        return base::makeError(
            "OCCT failed to section the model at Z " + std::to_string(z) + ": " + failure.GetMessageString(), path);
    }
    std::vector<Polyline> loops;
    if (!chain(std::move(pieces), loops))
        return base::makeError("the section at Z " + std::to_string(z) + " has an open chain of edges", path);
    orient(loops);
    return loops;
}

}  // namespace camwb::occ
