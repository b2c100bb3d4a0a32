#include "sim/TurningCheck.h"

#include "base/NumberFormat.h"
#include "geom/RegionOps.h"
#include "sim/Moves.h"
#include "toolpath/Toolpath.h"

#include <optional>

namespace camwb::sim {

namespace {

std::string mm(double v) { return base::formatFixed(v, 4) + " mm"; }
std::string point(Vec2 p) { return "Z" + base::formatFixed(p.x, 3) + " X" + base::formatFixed(p.y, 3); }

// The deepest of one kind among a record's moves (an arc is several).
struct Worst {
    double mm = 0;
    Vec2 at;
    void take(double depth, Vec2 where)
    {
        if (depth > mm) {
            mm = depth;
            at = where;
        }
    }
};

class Checker {
public:
    Checker(const toolpath::Toolpath& program, TurningReport& report, double tolerance) :
        m_program(program),
        m_report(report),
        m_tolerance(tolerance)
    {
    }

    void add(const Move& move, const TurningCut& cut)
    {
        if (m_record && *m_record != move.record)
            flush();
        m_record = move.record;
        if (move.kind == MoveKind::Rapid)
            m_rapid.take(cut.depthMm, cut.depthAt);
        m_gouge.take(cut.gougeMm, cut.gougeAt);
        if (move.kind == MoveKind::Feed && move.lengthMm() > 0 && cut.depthMm < m_tolerance) {
            if (m_report.feedsInAir++ == 0)
                m_firstFeedInAir = move.record;
        }
    }

    void finish()
    {
        flush();
        if (m_report.feedsInAir > 0)
            push(CheckKind::AirCutting, base::Severity::Note, m_firstFeedInAir, 0, {},
                 std::to_string(m_report.feedsInAir) + " feed moves cut no material (the first here)");
    }

private:
    void flush()
    {
        if (!m_record)
            return;
        if (m_rapid.mm > m_tolerance) {
            ++m_report.rapidsInStock;
            push(CheckKind::RapidInStock, base::Severity::Error, *m_record, m_rapid.mm, m_rapid.at,
                 "rapid through stock, " + mm(m_rapid.mm) + " deep at " + point(m_rapid.at));
        }
        if (m_gouge.mm > m_tolerance) {
            ++m_report.gouges;
            push(CheckKind::Gouge, base::Severity::Error, *m_record, m_gouge.mm, m_gouge.at,
                 "gouge: " + mm(m_gouge.mm) + " below the design contour at " + point(m_gouge.at));
        }
        m_rapid = {};
        m_gouge = {};
    }

    void push(CheckKind kind, base::Severity severity, std::size_t record, double depth, Vec2 at, std::string message)
    {
        Check c;
        c.kind = kind;
        c.severity = severity;
        c.record = static_cast<std::int64_t>(record);
        c.valueMm = depth;
        c.at = {at.y, 0, at.x};  // (Z, X) in the plane: X radius, Z along the spindle
        c.message = std::move(message);
        m_report.findings.push_back(std::move(c));
    }

    const toolpath::Toolpath& m_program;
    TurningReport& m_report;
    double m_tolerance;
    std::optional<std::uint32_t> m_record;
    std::size_t m_firstFeedInAir = 0;
    Worst m_rapid, m_gouge;
};

}  // namespace

toolpath::Toolpath inTurningPlane(const toolpath::Toolpath& program)
{
    toolpath::Toolpath out = program;
    const auto onPlane = [](toolpath::Vec3& to, toolpath::AxisMask& axes) {
        if (!axes.has(1)) {
            to.y = 0;
            axes.bits |= toolpath::AxisMask::kY;
        }
    };
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (auto* r = std::get_if<toolpath::Rapid>(&out.record(i)))
            onPlane(r->to, r->axes);
        else if (auto* l = std::get_if<toolpath::Linear>(&out.record(i)))
            onPlane(l->to, l->axes);
        else if (auto* u = std::get_if<toolpath::UnknownAxes>(&out.record(i)))
            u->axes.bits &= static_cast<unsigned char>(~toolpath::AxisMask::kY);  // Y stays 0 wherever X and Z went
    }
    return out;
}

TurningReport checkTurning(const toolpath::Toolpath& program, TurningRegion stock, TurningRegion design,
                           const TurningOptions& options)
{
    TurningReport report;
    // Finer than the check's tolerance, so that the booleans' fitting cannot make a touch a hit.
    TurningStock cutter(std::move(stock), std::move(design), options.toleranceMm / 10);
    Checker checker(program, report, options.toleranceMm);
    const double xScale = options.xIsDiameter ? 0.5 : 1.0;
    for (const Move& move : buildMoves(inTurningPlane(program)).moves) {
        if (!move.moves() || !move.positionKnown)
            continue;
        const TurningCut cut = cutter.cut(turningPoint(move.from.x * xScale, move.from.z),
                                          turningPoint(move.to.x * xScale, move.to.z), options.insert);
        ++report.moves;
        report.removedMm2 += cut.removedMm2;
        if (cut.gougeMm > report.maxGougeMm) {
            report.maxGougeMm = cut.gougeMm;
            report.maxGougeAt = cut.gougeAt;
        }
        if (move.kind == MoveKind::Rapid)
            report.maxRapidDepthMm = std::max(report.maxRapidDepthMm, cut.depthMm);
        checker.add(move, cut);
    }
    checker.finish();
    report.stock = cutter.stock();
    if (!cutter.design().empty()) {
        const TurningRegion leftover = geom::subtract(report.stock, cutter.design(), options.toleranceMm / 10);
        report.leftoverMm2 = geom::totalArea(leftover);
        report.maxLeftoverMm = radialDepth(leftover, report.stock, options.toleranceMm, report.maxLeftoverAt);
    }
    return report;
}

}  // namespace camwb::sim
