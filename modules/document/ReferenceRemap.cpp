#include "document/ReferenceRemap.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace camwb::document {

namespace {

// Re-exported models of the same part agree to far better than this; different features differ
// by far more.
constexpr double kSameMm = 1e-4;
constexpr double kSameAreaMm2 = 1e-3;

bool near(double a, double b, double tolerance = kSameMm) { return std::abs(a - b) <= tolerance; }
bool near(const base::Vec2& a, const base::Vec2& b) { return near(a.x, b.x) && near(a.y, b.y); }
bool near(const base::Vec3& a, const base::Vec3& b) { return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z); }

struct Box {
    base::Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
    void add(const base::Vec2& p)
    {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
};

// Where a horizontal planar face lies in XY: the box of its outer loop's vertices and arc middles.
std::optional<Box> faceBox(const occ::Model& model, int index)
{
    auto outline = model.planarFaceOuterProfile(index);
    if (!outline)
        return std::nullopt;
    Box box;
    for (const geom::Segment& s : outline->segments) {
        box.add(s.start);
        if (s.isArc())
            box.add(s.pointAt(0.5));
    }
    return box;
}

// Of the candidates, the one with the old number when it is among them, else the only one; 0 when
// none or several (a symmetric part: which of two equal faces was meant cannot be told).
int choose(const std::vector<int>& candidates, int oldIndex)
{
    if (std::find(candidates.begin(), candidates.end(), oldIndex) != candidates.end())
        return oldIndex;
    return candidates.size() == 1 ? candidates.front() : 0;
}

class Matcher {
public:
    Matcher(const occ::Model& from, const occ::Model& to) : m_from(from), m_to(to) {}

    int face(int index)
    {
        const occ::FaceInfo old = m_from.face(index);
        if (old.index == 0)
            return 0;
        const bool horizontal = old.planar && std::abs(std::abs(old.normal.z) - 1.0) < 1e-9;
        const std::optional<Box> oldBox = horizontal ? faceBox(m_from, index) : std::nullopt;
        std::vector<int> candidates;
        for (int i = 1; i <= m_to.faceCount(); ++i) {
            const occ::FaceInfo f = m_to.face(i);
            if (f.planar != old.planar || !near(f.areaMm2, old.areaMm2, kSameAreaMm2))
                continue;
            if (!old.planar) {
                // Nothing but the area to compare: only the same number is taken.
                if (i == index)
                    candidates.push_back(i);
                continue;
            }
            if (!near(f.normal, old.normal) || !near(f.planeZ, old.planeZ))
                continue;
            if (oldBox) {
                const std::optional<Box> box = faceBox(m_to, i);
                if (!box || !near(box->lo, oldBox->lo) || !near(box->hi, oldBox->hi))
                    continue;
            }
            candidates.push_back(i);
        }
        return choose(candidates, index);
    }

    int edge(int index)
    {
        const occ::EdgeInfo old = m_from.edge(index);
        if (old.index == 0)
            return 0;
        std::vector<int> candidates;
        // Same direction too: a chain's direction (and so a contour's side) follows its edges.
        for (int i = 1; i <= m_to.edgeCount(); ++i) {
            const occ::EdgeInfo e = m_to.edge(i);
            if (e.curve == old.curve && near(e.start, old.start) && near(e.end, old.end) &&
                near(e.lengthMm, old.lengthMm))
                candidates.push_back(i);
        }
        return choose(candidates, index);
    }

    int hole(int faceIndex)
    {
        if (!m_holes) {
            m_holes = std::make_pair(m_from.holes(), m_to.holes());
        }
        const auto& [oldHoles, newHoles] = *m_holes;
        const auto old = std::find_if(oldHoles.begin(), oldHoles.end(),
                                      [&](const geom::Hole& h) { return h.faceIndex == faceIndex; });
        if (old == oldHoles.end())
            return 0;
        std::vector<int> candidates;
        for (const geom::Hole& h : newHoles)
            if (near(h.center, old->center) && near(h.diameterMm, old->diameterMm) && near(h.topZ, old->topZ) &&
                near(h.bottomZ, old->bottomZ) && h.through == old->through)
                candidates.push_back(h.faceIndex);
        return choose(candidates, faceIndex);
    }

private:
    const occ::Model& m_from;
    const occ::Model& m_to;
    std::optional<std::pair<std::vector<geom::Hole>, std::vector<geom::Hole>>> m_holes;
};

}  // namespace

RemappedOperations remapReferences(const std::vector<Operation>& operations, const occ::Model& from,
                                   const occ::Model& to)
{
    RemappedOperations result;
    result.operations = operations;
    if (from.empty()) {
        result.checked = false;
        return result;
    }
    Matcher matcher(from, to);
    for (std::size_t i = 0; i < result.operations.size(); ++i) {
        GeometryRefs& refs = result.operations[i].geometry;
        auto remap = [&](std::vector<int>& indices, const char* what, auto&& find) {
            std::vector<int> kept;
            for (int index : indices) {
                const int found = find(index);
                if (found > 0)
                    kept.push_back(found);
                else
                    result.lost.push_back({static_cast<int>(i), std::string(what) + " " + std::to_string(index)});
            }
            indices = std::move(kept);
        };
        remap(refs.faces, "face", [&](int index) { return matcher.face(index); });
        remap(refs.edges, "edge", [&](int index) { return matcher.edge(index); });
        remap(refs.holes, "hole", [&](int index) { return matcher.hole(index); });
    }
    return result;
}

std::string describeLost(const std::vector<LostReference>& lost, const std::vector<Operation>& operations)
{
    std::string text;
    for (const LostReference& l : lost) {
        const Operation& op = operations.at(static_cast<std::size_t>(l.operation));
        text += std::string(kindLabel(op.kind())) + " \"" + op.name() + "\": " + l.reference + "\n";
    }
    if (!text.empty())
        text.pop_back();
    return text;
}

}  // namespace camwb::document
