#include "geom/RegionOps.h"

#include "geom/detail/ClipperRegions.h"
#include "geom/detail/LoopQueries.h"
#include "geom/detail/PieceSnap.h"
#include "geom/detail/RawOffset.h"

#include <algorithm>
#include <cmath>

namespace camwb::geom {

namespace {

// Tolerances below this are raised to it: they would be lost in Clipper's 1 nm grid anyway.
constexpr double kMinTolerance = 1e-5;

double usable(double tolerance) { return tolerance >= kMinTolerance ? tolerance : kMinTolerance; }  // NaN too

// Clipper 6.4 rounds the number of steps of a round join, so its last step can span 1.5 nominal
// steps and its chord error 1.5^2 times ArcTolerance.
constexpr double kRoundJoinWorstStep = 2.25;

std::vector<Region> booleanOp(const std::vector<Region>& a, const std::vector<Region>& b, ClipperLib::ClipType type,
                              double tolerance)
{
    const double tol = usable(tolerance);
    bool ok = true;
    const ClipperLib::Paths subject = detail::regionPaths(a, tol / 2, ok);
    const ClipperLib::Paths clip = detail::regionPaths(b, tol / 2, ok);
    if (!ok)
        return {};
    try {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(subject, ClipperLib::ptSubject, true);
        clipper.AddPaths(clip, ClipperLib::ptClip, true);
        ClipperLib::PolyTree tree;
        clipper.Execute(type, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
        return detail::regionsFromTree(tree, tol / 2);
    } catch (...) {
        return {};
    }
}

}  // namespace

double offsetSafetyMargin(double tolerance)
{
    const double tol = usable(tolerance);
    return tol + kRoundJoinWorstStep * offsetArcTolerance(tol) + 4 / kClipperScale;
}

double offsetArcTolerance(double tolerance) { return usable(tolerance) / 8; }

std::vector<Region> offsetRegions(const std::vector<Region>& regions, double delta, double tolerance)
{
    if (regions.empty() || !std::isfinite(delta))
        return {};
    std::vector<Region> normalized;
    for (const Region& region : regions)
        normalized.push_back(region.normalized());
    if (delta == 0)
        return normalized;
    if (std::abs(delta) >= detail::kMaxCoordinate)
        return {};
    const double tol = usable(tolerance);
    // The raw offset in exact lines and arcs, discretised only for Clipper to decide where loops
    // cross, merge, split or vanish; the union's loops are then put back onto the exact pieces.
    const double distance = delta < 0 ? -delta + offsetSafetyMargin(tol) : delta;
    const detail::RawLoops raw = detail::rawOffset(normalized, distance, delta < 0, tol / 2);
    const detail::PieceSnap snap(raw, tol / 2);
    if (!snap.inRange())
        return {};
    try {
        ClipperLib::Clipper clipper;
        clipper.AddPaths(snap.paths(), ClipperLib::ptSubject, true);
        ClipperLib::PolyTree tree;
        clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftPositive, ClipperLib::pftPositive);
        // A contour that cannot be placed on the pieces (a crossing too shallow to find again) is
        // fitted instead, as booleans are: within the margin the shrink adds.
        return detail::regionsFromTree(tree, [&](const ClipperLib::Path& contour) {
            std::optional<Profile> exact = snap.snap(contour);
            return exact ? std::move(*exact) : detail::fitContour(contour, tol / 2);
        });
    } catch (...) {
        return {};
    }
}

std::vector<Region> unite(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance)
{
    return booleanOp(a, b, ClipperLib::ctUnion, tolerance);
}

std::vector<Region> subtract(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance)
{
    return booleanOp(a, b, ClipperLib::ctDifference, tolerance);
}

std::vector<Region> intersect(const std::vector<Region>& a, const std::vector<Region>& b, double tolerance)
{
    return booleanOp(a, b, ClipperLib::ctIntersection, tolerance);
}

std::vector<Region> sweptArea(const std::vector<std::vector<Vec2>>& paths, double radius, double tolerance)
{
    if (!(radius > 0) || radius >= detail::kMaxCoordinate)
        return {};
    const double tol = usable(tolerance);
    try {
        ClipperLib::ClipperOffset offsetter;
        offsetter.ArcTolerance = std::max(offsetArcTolerance(tol) * kClipperScale, 0.25);
        for (const std::vector<Vec2>& path : paths) {
            if (path.empty() || !detail::inRange(path))
                continue;
            ClipperLib::Path clipperPath;
            clipperPath.reserve(path.size());
            for (const Vec2& p : path)
                clipperPath.push_back(detail::toClipper(p));
            offsetter.AddPath(clipperPath, ClipperLib::jtRound, ClipperLib::etOpenRound);
        }
        ClipperLib::PolyTree tree;
        offsetter.Execute(tree, radius * kClipperScale);
        return detail::regionsFromTree(tree, tol / 2);
    } catch (...) {
        return {};
    }
}

}  // namespace camwb::geom
