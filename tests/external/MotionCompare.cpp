#include "MotionCompare.h"

#include "LinuxCncModel.h"

#include "toolpath/KnownPosition.h"
#include "toolpath/MachineSink.h"
#include "toolpath/TraceWriter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace camwb::external {

using namespace toolpath;

namespace {

struct Item {
    const Record* record;
    std::size_t index;  // in its toolpath
    Vec3 start;         // position before the record
    Vec3 end;           // and after it (a move that gives only some axes keeps the others)
    // The move after a rapid left to the machine that does not move in the CL's coordinates:
    // LinuxCNC moves there only when the new tool's length changed the height under the rapid.
    bool stillUnlessLengthChanged = false;
};

bool sameWritten(const Vec3& a, const Vec3& b)
{
    return written(a.x) == written(b.x) && written(a.y) == written(b.y) && written(a.z) == written(b.z);
}

// Records that count, each with its start point: no comments, no moves that the post would not
// write (all axes equal at 3 decimals) and that rs274 prints as a repeat of the position.
std::vector<Item> items(const Toolpath& path)
{
    std::vector<Item> result;
    Vec3 position;  // rs274 starts at the origin
    bool leftToMachine = false;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Record& record = path.record(i);
        if (std::holds_alternative<Comment>(record))
            continue;
        const Vec3 start = position;
        // A rapid that leaves an axis to the machine (X/Y after a tool change, at the height G43
        // left) always counts, and so does the move after it: LinuxCNC's Z moved under them in
        // program coordinates.
        const bool fromMachineHeight = std::exchange(leftToMachine, false);
        if (const auto* rapid = std::get_if<Rapid>(&record)) {
            position = *endOf(KnownPosition(position), rapid->to, rapid->axes);
            leftToMachine = !rapid->axes.all();
            if (!leftToMachine && !fromMachineHeight && sameWritten(start, position))
                continue;
        } else if (const auto* linear = std::get_if<Linear>(&record)) {
            position = *endOf(KnownPosition(position), linear->to, linear->axes);
            if (!fromMachineHeight && sameWritten(start, position))
                continue;
        } else if (const auto* arc = std::get_if<Arc>(&record)) {
            position = arc->to;
        }
        const bool still = fromMachineHeight && !std::holds_alternative<Arc>(record) && sameWritten(start, position);
        result.push_back({&record, i, start, position, still});
    }
    return result;
}

std::string describe(const Item& item)
{
    std::string text;
    TraceWriter writer(text);
    dispatch(*item.record, writer);
    while (!text.empty() && text.back() == '\n')
        text.pop_back();
    return "[" + std::to_string(item.index) + "] " + text;
}

bool closeFeed(double expected, double actual, double relative)
{
    return std::abs(expected - actual) <= relative * std::max(1.0, std::abs(expected));
}

double axisDistance(const Vec3& a, const Vec3& b)
{
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// Largest axis difference of two arc centres in the arc's plane (a CL centre's axial coordinate is free).
double inPlaneDistance(const Vec3& a, const Vec3& b, const Vec3& normal)
{
    const Vec3 d = a - b;
    return axisDistance(d - normal * d.dot(normal), Vec3{});
}

class Comparison {
public:
    Comparison(const Toolpath& expected, const Toolpath& actual, const MotionTolerance& tolerance) :
        m_expected(items(expected)),
        m_actual(items(actual)),
        m_tol(tolerance)
    {
    }
    std::optional<std::string> run();

private:
    std::optional<std::string> arcs(const Item& expected);
    std::optional<std::string> same(const Item& expected, const Item& actual) const;
    std::string differ(const Item& expected, const Item& actual, const std::string& what) const
    {
        return what + ": expected " + describe(expected) + ", LinuxCNC " + describe(actual);
    }

    std::vector<Item> m_expected, m_actual;
    MotionTolerance m_tol;
    std::size_t m_j = 0;
    bool m_inverseTime = false;
};

std::optional<std::string> Comparison::run()
{
    for (const Item& e : m_expected) {
        if (m_j >= m_actual.size())
            return "LinuxCNC's motion ends before expected " + describe(e);
        if (std::holds_alternative<Arc>(*e.record)) {
            if (auto difference = arcs(e))
                return difference;
            continue;
        }
        if (auto difference = same(e, m_actual[m_j])) {
            if (e.stillUnlessLengthChanged)
                continue;
            return difference;
        }
        if (const auto* mode = std::get_if<FeedModeChange>(e.record))
            m_inverseTime = mode->mode == FeedMode::InverseTime;
        ++m_j;
    }
    if (m_j < m_actual.size())
        return "LinuxCNC does more than expected, from " + describe(m_actual[m_j]);
    return std::nullopt;
}

std::optional<std::string> Comparison::same(const Item& e, const Item& a) const
{
    if (e.record->index() != a.record->index())
        return differ(e, a, "different kind");
    const double feedTolerance = m_inverseTime ? m_tol.inverseTimeRelative : m_tol.feedRelative;
    if (const auto* rapid = std::get_if<Rapid>(e.record)) {
        for (int axis = 0; axis < 3; ++axis) {  // the axes the expected move gives
            if (rapid->axes.has(axis) && std::abs(axisValue(e.end, axis) - axisValue(a.end, axis)) > m_tol.axisMm)
                return differ(e, a, "rapid end point");
        }
    } else if (const auto* linear = std::get_if<Linear>(e.record)) {
        const auto& other = std::get<Linear>(*a.record);
        if (axisDistance(e.end, a.end) > m_tol.axisMm)
            return differ(e, a, "feed move end point");
        if (!closeFeed(linear->feedMmPerMin, other.feedMmPerMin, feedTolerance))
            return differ(e, a, "feed rate");
    } else if (const auto* dwell = std::get_if<Dwell>(e.record)) {
        if (std::abs(dwell->seconds - std::get<Dwell>(*a.record).seconds) > m_tol.secondsAbs)
            return differ(e, a, "dwell time");
    } else if (const auto* spindle = std::get_if<Spindle>(e.record)) {
        const auto& other = std::get<Spindle>(*a.record);
        if (!closeFeed(spindle->rpm, other.rpm, 1e-6) || (spindle->rpm > 0 && spindle->clockwise != other.clockwise))
            return differ(e, a, "spindle");
    } else if (const auto* coolant = std::get_if<Coolant>(e.record)) {
        if (coolant->mode != std::get<Coolant>(*a.record).mode)
            return differ(e, a, "coolant");
    } else if (const auto* tool = std::get_if<ToolChange>(e.record)) {
        if (tool->tool.number != std::get<ToolChange>(*a.record).tool.number)
            return differ(e, a, "tool number");
    } else if (const auto* offset = std::get_if<WorkOffset>(e.record)) {
        if (offset->index != std::get<WorkOffset>(*a.record).index)
            return differ(e, a, "work offset");
    } else if (const auto* mode = std::get_if<FeedModeChange>(e.record)) {
        if (mode->mode != std::get<FeedModeChange>(*a.record).mode)
            return differ(e, a, "feed mode");
    } else if (const auto* stop = std::get_if<ProgramStop>(e.record)) {
        if (stop->optional != std::get<ProgramStop>(*a.record).optional)
            return differ(e, a, "program stop");
    }
    return std::nullopt;
}

// One expected arc against as many arc pieces of LinuxCNC as it takes to cover its sweep.
std::optional<std::string> Comparison::arcs(const Item& e)
{
    const Arc arc = canonicalArc(std::get<Arc>(*e.record));
    const Vec3 n = arc.normal * (1.0 / arc.normal.length());
    const double expectedSweep = arcSweepDeg(e.start, arc);
    const Vec3 radial = e.start - arc.center;
    const double radius = (radial - n * radial.dot(n)).length();
    // Written end points and centre move the angles by about (point + centre tolerance) / radius.
    const double sweepTolerance =
        std::max(1e-3, 4 * m_tol.axisMm * std::sqrt(2.0) / std::max(radius, 1e-9) * 180 / std::numbers::pi);
    const double feedTolerance = m_inverseTime ? m_tol.inverseTimeRelative : m_tol.feedRelative;
    double sweep = 0;
    const Item* last = nullptr;
    while (sweep < expectedSweep - sweepTolerance) {
        if (m_j >= m_actual.size())
            return "LinuxCNC's motion ends inside expected " + describe(e);
        const Item& a = m_actual[m_j];
        const auto* piece = std::get_if<Arc>(a.record);
        if (!piece)
            return differ(e, a, "arc expected");
        if (piece->normal.dot(n) < 1 - 1e-9 || piece->clockwise != arc.clockwise)
            return differ(e, a, "arc plane or direction");
        if (inPlaneDistance(piece->center, arc.center, n) > m_tol.axisMm)
            return differ(e, a, "arc centre");
        if (!closeFeed(arc.feedMmPerMin, piece->feedMmPerMin, feedTolerance))
            return differ(e, a, "arc feed rate");
        sweep += arcSweepDeg(a.start, *piece);
        last = &a;
        ++m_j;
    }
    if (!last)
        return "expected " + describe(e) + " has no sweep";
    if (axisDistance(std::get<Arc>(*last->record).to, arc.to) > m_tol.axisMm)
        return differ(e, *last, "arc end point");
    if (std::abs(sweep - expectedSweep) > sweepTolerance)
        return differ(e, *last,
                      "arc sweep " + std::to_string(sweep) + " deg instead of " + std::to_string(expectedSweep));
    return std::nullopt;
}

}  // namespace

std::optional<std::string> compareMotion(const Toolpath& expected, const Toolpath& actual,
                                         const MotionTolerance& tolerance)
{
    return Comparison(expected, actual, tolerance).run();
}

}  // namespace camwb::external
