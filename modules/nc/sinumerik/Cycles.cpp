// Drilling cycles CYCLE81..89 with the parameter lists of the 828D/840D (RTP, RFP, SDIS, DP, DPR,
// then per cycle) as one Cycle record per hole: clearance = RTP, R plane = RFP + SDIS, top = RFP,
// bottom = DP (or RFP - DPR, which wins when both are given, as the manual says).
#include "nc/sinumerik/Machine.h"

#include "toolpath/CycleExpansion.h"

#include <cmath>

namespace camwb::nc::sinumerik {

namespace {

using namespace camwb::toolpath;

}  // namespace

bool Machine::runCycle(const Program& p, int number, const std::vector<std::optional<double>>& args, Pos pos, int line)
{
    auto arg = [&](std::size_t i) -> std::optional<double> { return i < args.size() ? args[i] : std::nullopt; };
    const std::string name = "CYCLE" + std::to_string(number);
    if (number < 81 || number > 89) {
        warning(p, pos, name + " is not interpreted: its motion is missing from the trace");
        return false;
    }
    if (const int axis = m_known.missing(kXyAxes); axis >= 0) {
        error(p, pos, unknownAxisMessage(axis, "the drilling cycle (the tool is over the hole)"));
        return false;
    }
    if (m_modal.plane != 17)
        warning(p, pos, name + " in G18/G19 is traced along Z as in G17");
    const auto rtp = arg(0), rfp = arg(1), sdis = arg(2), dp = arg(3), dpr = arg(4);
    if (!rtp) {
        error(p, pos, name + ": RTP (return plane) is missing");
        return false;
    }
    const double top = toMm(rfp.value_or(0));
    double bottom = 0;
    if (dpr) {
        bottom = top - toMm(std::abs(*dpr));
        if (dp && std::abs(toMm(*dp) - bottom) > 1e-6)
            warning(p, pos, name + ": both DP and DPR given; the depth follows DPR as on the control");
    } else if (dp) {
        bottom = toMm(*dp);
    } else {
        error(p, pos, name + ": no depth (DP or DPR)");
        return false;
    }
    Cycle c;
    c.clearanceZ = toMm(*rtp);
    c.topZ = top;
    c.retractZ = top + toMm(sdis.value_or(0));
    c.bottomZ = bottom;
    c.feedMmPerMin = m_feed;
    c.returnToClearance = true;
    if (bottom > top) {
        error(p, pos, name + ": the final depth lies above the reference plane");
        return false;
    }
    // Dwell: positive seconds, negative revolutions of the spindle.
    auto dwellSeconds = [&](std::optional<double> v) -> double {
        if (!v || *v == 0)
            return 0;
        if (*v > 0)
            return *v;
        const double rpm = m_modal.constantSurfaceSpeed ? m_lims : m_speed;
        if (rpm <= 0) {
            error(p, pos, name + ": dwell in revolutions with no spindle speed");
            return 0;
        }
        return -*v * 60.0 / rpm;
    };
    switch (number) {
    case 81:
        c.kind = CycleKind::Drill;
        break;
    case 82:
        c.kind = CycleKind::DrillDwell;
        c.dwellSeconds = dwellSeconds(arg(5));
        break;
    case 83: {
        // FDEP 5, FDPR 6, DAM 7, DTB 8, DTS 9, FRF 10, VARI 11, _AXN 12, _MDEP 13, _VRT 14, _DTD 15, _DIS1 16
        const auto vari = arg(11);
        c.kind = vari && *vari == 0 ? CycleKind::ChipBreak : CycleKind::Peck;
        double first = bottom;
        if (arg(6))
            first = top - toMm(std::abs(*arg(6)));
        else if (arg(5))
            first = toMm(*arg(5));
        if (first > bottom + 1e-9)
            c.peckMm = top - first;
        else if (arg(13) && *arg(13) > 0)
            c.peckMm = toMm(*arg(13));  // one infeed to the bottom: the minimum depth keeps the peck size
        else
            c.peckMm = top - bottom;
        const auto dtd = arg(15);
        c.dwellSeconds = dtd && *dtd != 0 ? dwellSeconds(dtd) : dwellSeconds(arg(8));
        break;
    }
    case 84: {
        // DTB 5, SDAC 6, MPIT 7, PIT 8, POSS 9, SST 10, SST1 11
        c.kind = CycleKind::Tap;
        c.dwellSeconds = dwellSeconds(arg(5));
        const auto pitch = arg(8);
        if (!pitch) {
            error(p, pos, name + ": no thread pitch (PIT)");
            return false;
        }
        const double pit = toMm(std::abs(*pitch));
        const double rpm = arg(10).value_or(m_speed);
        c.feedMmPerMin = m_modal.feedMode == FeedMode::PerRevolution ? pit : pit * rpm;
        break;
    }
    case 85:
    case 89:
        c.kind = CycleKind::Bore;
        c.dwellSeconds = dwellSeconds(arg(5));
        if (number == 85 && arg(6))
            c.feedMmPerMin = feedToInternal(*arg(6));
        break;
    default:
        c.kind = CycleKind::Bore;
        c.dwellSeconds = dwellSeconds(arg(5));
        warning(p, pos, name + " is traced as boring: its spindle stop and lift-off are not shown");
        break;
    }
    if (c.feedMmPerMin <= 0)
        error(p, pos, name + " without a feed (F)");
    if (const std::optional<std::string> why = toolpath::tooManyPecks(c))
        error(p, pos, name + ": " + *why);
    c.holes.push_back(Vec3{m_pos.x, m_pos.y, top});
    setSource(line);
    m_sink.cycle(c);
    m_pos = Vec3{m_pos.x, m_pos.y, cycleReturnZ(c)};
    m_known.give(AxisMask{});  // X and Y were known, the cycle returns to a programmed Z
    return true;
}

}  // namespace camwb::nc::sinumerik
