// Helpers of the compensation tests: a CutterCompensation in front of a recorder, fed records
// by hand as an interpreter would, and the distance from a point to a programmed contour.
#pragma once

#include "nc/CutterCompensation.h"
#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace camwb::nc::test {

using namespace camwb::toolpath;
using base::Vec2;

struct Compensated {
    InterpretResult result;
    ToolpathRecorder recorder;
    CutterCompensation comp;

    explicit Compensated(CompensationRules rules = {}) : comp(recorder, rules, result, 1000)
    {
        result.files.push_back("test.nc");
    }

    // One programmed block: its source line, then the record.
    template <class R> void block(int line, const R& record)
    {
        comp.setSource(SourceRef{-1, -1, line, 0});
        dispatch(Record(record), comp);
    }
    void finish() { comp.end(); }
    const Toolpath& path() const { return recorder.toolpath(); }
    std::string diagnostics() const
    {
        std::string out;
        for (const Diagnostic& d : result.diagnostics)
            out += std::to_string(d.line) + ": " + severityName(d.severity) + ": " + d.message + "\n";
        return out;
    }
    template <class T> std::vector<T> all() const
    {
        std::vector<T> out;
        for (const auto& r : path().records())
            if (const T* t = std::get_if<T>(&r))
                out.push_back(*t);
        return out;
    }
};

// A programmed element of a contour in XY.
struct Piece {
    bool arc = false;
    Vec2 start, end, center;
    bool clockwise = false;
};

inline double angleOf(Vec2 v) { return std::atan2(v.y, v.x); }

// Distance from `p` to a line segment or an arc (the arc's sweep from start to end in its direction).
inline double distanceTo(const Piece& piece, Vec2 p)
{
    if (!piece.arc) {
        const Vec2 d = piece.end - piece.start;
        const double len2 = d.dot(d);
        const double t = len2 > 0 ? std::clamp((p - piece.start).dot(d) / len2, 0.0, 1.0) : 0.0;
        return distance(piece.start + d * t, p);
    }
    const double twoPi = 2 * std::numbers::pi;
    auto travel = [&](Vec2 from, Vec2 to) {
        double a = angleOf(to - piece.center) - angleOf(from - piece.center);
        if (piece.clockwise)
            a = -a;
        while (a < 0)
            a += twoPi;
        while (a >= twoPi)
            a -= twoPi;
        return a;
    };
    const double sweep = piece.start == piece.end ? twoPi : travel(piece.start, piece.end);
    const double radius = distance(piece.start, piece.center);
    if (distance(p, piece.center) > 1e-12 && travel(piece.start, p) <= sweep)
        return std::abs(distance(p, piece.center) - radius);
    return std::min(distance(p, piece.start), distance(p, piece.end));
}

inline double distanceTo(const std::vector<Piece>& contour, Vec2 p)
{
    double best = 1e300;
    for (const Piece& piece : contour)
        best = std::min(best, distanceTo(piece, p));
    return best;
}

}  // namespace camwb::nc::test
