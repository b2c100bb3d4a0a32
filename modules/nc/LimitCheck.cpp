#include "nc/LimitCheck.h"

#include "base/NumberFormat.h"
#include "kinematics/Machine.h"

#include <algorithm>

namespace camwb::nc {

using namespace camwb::toolpath;

namespace {

std::string num(double v) { return base::formatFixed(v, 3); }

double& component(Vec3& v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }

}  // namespace

LimitCheck::LimitCheck(const kinematics::Machine& machine, MachineSink& next) : m_machine(machine), m_next(next) {}

void LimitCheck::setSource(const SourceRef& source)
{
    m_source = source;
    m_next.setSource(source);
}

void LimitCheck::warnOnce(const std::string& key, std::string message)
{
    if (std::find(m_keys.begin(), m_keys.end(), key) != m_keys.end())
        return;
    m_keys.push_back(key);
    m_findings.push_back({m_source, std::move(message)});
}

void LimitCheck::reach(const Vec3& p)
{
    Vec3 point = p;
    for (int i = 0; i < 3; ++i) {
        const double v = component(point, i);
        if (!m_any || v < component(m_min, i)) {
            component(m_min, i) = v;
            m_minAt[i] = m_source;
        }
        if (!m_any || v > component(m_max, i)) {
            component(m_max, i) = v;
            m_maxAt[i] = m_source;
        }
    }
    m_any = true;
}

void LimitCheck::checkFeed(double feed)
{
    if (m_perMinute && m_machine.maxCuttingFeedMmPerMin > 0 && feed > m_machine.maxCuttingFeedMmPerMin)
        warnOnce("feed", "feed " + num(feed) + " mm/min is above " + m_machine.name + "'s " +
                             num(m_machine.maxCuttingFeedMmPerMin) + " mm/min");
}

void LimitCheck::rapid(const Rapid& r)
{
    reach(r.to);
    m_next.rapid(r);
}

void LimitCheck::linear(const Linear& r)
{
    reach(r.to);
    checkFeed(r.feedMmPerMin);
    m_next.linear(r);
}

void LimitCheck::arc(const Arc& r)
{
    // The end point only: the circle's own extremes are within the span of its ends plus its
    // radius, which the travel check below treats as close enough for a warning.
    reach(r.to);
    checkFeed(r.feedMmPerMin);
    m_next.arc(r);
}

void LimitCheck::cycle(const Cycle& r)
{
    for (const Vec3& hole : r.holes) {
        reach({hole.x, hole.y, r.bottomZ});
        reach({hole.x, hole.y, std::max(r.clearanceZ, r.retractZ)});
    }
    checkFeed(r.feedMmPerMin);
    m_next.cycle(r);
}

void LimitCheck::toolAxisMove(const ToolAxisMove& r)
{
    reach(r.tip);
    m_next.toolAxisMove(r);
}

void LimitCheck::feedMode(const FeedModeChange& r)
{
    m_perMinute = r.mode == FeedMode::PerMinute;
    m_next.feedMode(r);
}

void LimitCheck::toolChange(const ToolChange& r)
{
    if (m_machine.toolStations > 0 && (r.tool.number < 0 || r.tool.number > m_machine.toolStations))
        warnOnce("tool" + std::to_string(r.tool.number), "tool " + std::to_string(r.tool.number) + " is not one of " +
                                                             m_machine.name + "'s " +
                                                             std::to_string(m_machine.toolStations) + " stations");
    m_next.toolChange(r);
}

void LimitCheck::spindle(const Spindle& r)
{
    if (r.rpm > 0 && m_machine.spindleMaxRpm > 0 && r.rpm > m_machine.spindleMaxRpm)
        warnOnce("rpm-max", "spindle speed " + num(r.rpm) + " rpm is above " + m_machine.name + "'s " +
                                num(m_machine.spindleMaxRpm) + " rpm");
    if (r.rpm > 0 && r.rpm < m_machine.spindleMinRpm)
        warnOnce("rpm-min", "spindle speed " + num(r.rpm) + " rpm is below " + m_machine.name + "'s " +
                                num(m_machine.spindleMinRpm) + " rpm");
    m_next.spindle(r);
}

std::vector<Diagnostic> LimitCheck::diagnostics(const std::vector<std::string>& files) const
{
    auto fileOf = [&files](const SourceRef& s) {
        return s.file >= 0 && s.file < static_cast<int>(files.size()) ? files[s.file] : std::string();
    };
    std::vector<Diagnostic> out;
    for (const Finding& f : m_findings)
        out.push_back({Severity::Warning, fileOf(f.where), std::max(f.where.line, 0), 0, f.message});
    if (!m_any)
        return out;
    // The work offset is not known here, so only the span can be checked: a program longer than
    // the axis travel cannot run whatever the set-up.
    static const char* const names[] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        const kinematics::Axis* axis = m_machine.axis(names[i]);
        if (!axis || axis->max <= axis->min)
            continue;
        Vec3 min = m_min, max = m_max;
        const double span = component(max, i) - component(min, i);
        if (span > axis->max - axis->min + 1e-9) {
            const SourceRef& at = m_maxAt[i].line > m_minAt[i].line ? m_maxAt[i] : m_minAt[i];
            out.push_back({Severity::Warning, fileOf(at), std::max(at.line, 0), 0,
                           std::string("the program spans ") + num(span) + " mm in " + names[i] + " (" +
                               num(component(min, i)) + " to " + num(component(max, i)) + "), more than " +
                               m_machine.name + "'s " + num(axis->max - axis->min) + " mm travel"});
        }
    }
    return out;
}

}  // namespace camwb::nc
