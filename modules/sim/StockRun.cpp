#include "sim/StockRun.h"

#include "base/NumberFormat.h"

#include <cmath>

namespace camwb::sim {

namespace {

std::string mm(double value) { return base::formatFixed(value, 3) + " mm"; }

// Steeper than this along the tool axis, a move into material is a plunge: a tool that does not
// cut at its centre may ramp in at a shallow angle (its edges sweep the core away) but not drill.
constexpr double kPlungeSlope = 1.0;  // 45 degrees

}  // namespace

StockRun::StockRun(const MoveList& moves, Stock& stock) : m_moves(moves), m_stock(stock) {}

double StockRun::noiseMm3() const
{
    const double r = m_stock.resolutionMm();
    return 1e-3 * r * r * r;
}

const ToolShape* StockRun::shapeOf(int tool)
{
    auto it = m_shapes.find(tool);
    if (it == m_shapes.end()) {
        const toolpath::Tool* cl = m_moves.tool(tool);
        if (!cl)
            return nullptr;
        it = m_shapes.emplace(tool, std::make_unique<ToolShape>(*cl)).first;
    }
    return it->second.get();
}

std::size_t StockRun::cutTo(std::size_t endMove, const std::atomic<bool>* cancel)
{
    const std::vector<Move>& moves = m_moves.moves;
    endMove = std::min(endMove, moves.size());
    while (m_next < endMove) {
        // Every move: a five-axis move can take a good part of a second (the five-axis example:
        // 335 moves in about 25 s, so every 64th move let Cancel wait 15 s); a load is nothing
        // beside a cut.
        if (cancel && cancel->load(std::memory_order_relaxed))
            break;
        const Move& move = moves[m_next];
        if (!move.moves()) {
            ++m_next;
            continue;
        }
        const ToolShape* shape = shapeOf(move.tool);
        if (!shape || shape->radiusMm() <= 0) {
            // Nothing known to cut with: say so at the first such move of each tool rather than
            // report a clean run.
            if (m_shapeless.insert(move.tool).second) {
                Check c;
                c.kind = CheckKind::NoToolShape;
                c.severity = base::Severity::Warning;
                c.record = move.record;
                c.move = static_cast<std::int64_t>(m_next);
                c.at = move.from;
                c.message = move.tool == 0 ? "moves before any tool change: not cut"
                                           : "tool " + std::to_string(move.tool) +
                                                 " has no diameter (the program gives none; a tool table can): "
                                                 "its moves are not cut";
                m_checks.add(std::move(c));
            }
            ++m_next;
            continue;
        }
        // A run: this move and the pieces of the same arc or helix after it. The stock cuts a
        // whole run in one pass; its pieces are marked as its first and judged together, so a
        // run cut piece by piece (cutTo stopping inside it) leaves the same stock and findings.
        if (m_next >= m_runEnd) {
            m_runStart = m_next;
            m_runEnd = m_next + 1;
            while (m_runEnd < moves.size() && continuesArc(moves[m_runEnd - 1], moves[m_runEnd]))
                ++m_runEnd;
            m_runCut = {};
        }
        const std::size_t stop = std::min(m_runEnd, endMove);
        if (m_next == m_runStart && stop == m_runEnd)
            m_runCut = m_stock.cutArcRun(&moves[m_next], stop - m_next, m_runStart, *shape);
        else
            for (std::size_t k = m_next; k < stop; ++k)
                m_runCut.add(m_stock.cut(moves[k], m_runStart, *shape));
        m_next = stop;
        if (m_next == m_runEnd)
            judge(m_runStart, m_runEnd, m_runCut, *shape);
    }
    return m_next;
}

void StockRun::judge(std::size_t first, std::size_t end, const CutResult& cut, const ToolShape& shape)
{
    const Move& move = m_moves.moves[first];
    const Vec3 to = m_moves.moves[end - 1].to;
    double length = 0;
    for (std::size_t k = first; k < end; ++k)
        length += m_moves.moves[k].lengthMm();
    const bool removed = cut.removedMm3 > noiseMm3();
    auto check = [&](CheckKind kind, base::Severity severity, double value, const Vec3& at) {
        Check c;
        c.removedMm3 = removed ? cut.removedMm3 : 0;
        c.kind = kind;
        c.severity = severity;
        c.record = move.record;
        c.move = static_cast<std::int64_t>(first);
        c.moves = int(end - first);
        c.valueMm = value;
        c.at = at;
        m_checks.add(std::move(c));
    };
    if (removed)
        m_removedMm3 += cut.removedMm3;
    if (move.kind == MoveKind::Rapid && removed)
        check(CheckKind::RapidInStock, base::Severity::Error, 0, to);
    if (move.kind == MoveKind::Feed) {
        if (removed)
            m_cuttingMm += length;
        else {
            m_airMm += length;
            check(CheckKind::AirCutting, base::Severity::Note, length, to);
        }
    }
    if (cut.gougeMm > 0)
        check(CheckKind::Gouge, base::Severity::Error, cut.gougeMm, cut.gougeAt);
    if (cut.holderInterferenceMm > 0)
        check(CheckKind::HolderCollision, base::Severity::Error, cut.holderInterferenceMm, cut.holderAt);
    if (removed && move.spindleRpm <= 0)
        check(CheckKind::SpindleOffCutting, base::Severity::Error, 0, to);
    if (removed && cut.removedOnAxis && !shape.tool().centreCutting) {
        const Vec3 d = to - move.from;
        const double down = -d.dot(move.fromAxis());
        const double across = (d + move.fromAxis() * down).length();
        if (down > 0 && down > kPlungeSlope * across)
            check(CheckKind::PlungeNotCentre, base::Severity::Error, down, to);
    }
}

std::vector<Check> StockRun::checks() const
{
    std::vector<Check> out = m_checks.checks();
    for (Check& c : out)
        c.message = describe(c);
    return out;
}

std::optional<Check> finishedStockGouge(const Deviation& deviation, const MoveList& moves,
                                        const std::vector<Check>& checks)
{
    if (deviation.maxGougeMm <= 0)
        return std::nullopt;
    for (const Check& c : checks)
        if (c.kind == CheckKind::Gouge)
            return std::nullopt;  // the cuts reported their gouges, the deepest among them
    Check c;
    c.kind = CheckKind::Gouge;
    c.severity = base::Severity::Error;
    c.valueMm = deviation.maxGougeMm;
    c.at = deviation.gougeAt;
    const bool known = deviation.gougeMove >= 0 && std::size_t(deviation.gougeMove) < moves.moves.size();
    if (known) {
        c.move = deviation.gougeMove;
        c.record = moves.moves[std::size_t(deviation.gougeMove)].record;
        c.moves = 1;
        c.message = "gouge in the finished stock: " + mm(c.valueMm) + " into the part, last cut there by this block";
    } else {
        c.message = "the stock lies " + mm(c.valueMm) +
                    " inside the part where no move cut: the stock or blank is smaller than the part there";
    }
    return c;
}

std::string describe(const Check& check)
{
    if (!check.message.empty())
        return check.message;
    const std::string moves = check.moves > 1 ? " (" + std::to_string(check.moves) + " moves)" : "";
    switch (check.kind) {
    case CheckKind::RapidInStock:
        return "rapid through stock: " + base::formatFixed(check.removedMm3, 3) + " mm³ removed at rapid" + moves;
    case CheckKind::Gouge:
        return "gouge: the cutter goes " + mm(check.valueMm) + " into the part" + moves;
    case CheckKind::HolderCollision:
        return "shank or holder " + mm(check.valueMm) + " into the stock" + moves +
               ": the tool sticks out too little for this depth";
    case CheckKind::PlungeNotCentre:
        return "plunge of " + mm(check.valueMm) + " into material with a tool that does not cut at its centre" + moves;
    case CheckKind::SpindleOffCutting:
        return "cutting with the spindle stopped" + moves;
    case CheckKind::MachineLimit:
        return "machine limit";
    case CheckKind::AirCutting:
        return "feed move in air: " + mm(check.valueMm) + " cut nothing" + moves;
    case CheckKind::NoToolShape:
        return "a tool without a shape: its moves are not cut";
    case CheckKind::UnknownPosition:
        return "a feed move from an unknown position: not simulated";
    }
    return {};
}

}  // namespace camwb::sim
