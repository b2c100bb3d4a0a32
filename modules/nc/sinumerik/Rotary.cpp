// Five-axis SINUMERIK through the machine's kinematic chain (nc/FiveAxis.h): TRAORI / TRAFOOF
// (X Y Z the tool tip in the workpiece frame, or the machine's axes), rotary words A B C as machine
// axis positions (AC, IC, DC, ACP, ACN), and the tool vector A3= B3= C3= under TRAORI (Programming
// Manual Job Planning, "Three, four and five axis transformation (TRAORI)": components not
// programmed are 0, the length does not matter, and it does not mix with axis positions).
#include "nc/sinumerik/Machine.h"

#include <cmath>

namespace camwb::nc::sinumerik {

using namespace camwb::toolpath;

namespace {

RotaryMode modeOf(ValueMode mode, bool modalIncremental)
{
    switch (mode) {
    case ValueMode::Incremental:
        return RotaryMode::Incremental;
    case ValueMode::Shortest:
        return RotaryMode::Shortest;
    case ValueMode::Positive:
        return RotaryMode::Positive;
    case ValueMode::Negative:
        return RotaryMode::Negative;
    case ValueMode::Modal:
        return modalIncremental ? RotaryMode::Incremental : RotaryMode::Absolute;
    case ValueMode::Absolute:
        break;
    }
    return RotaryMode::Absolute;
}

std::string rotaryUnknownMessage(char axis, std::string_view need)
{
    const std::string name(1, axis);
    return name + " is unknown here: no absolute " + name + " has been programmed yet, and " + std::string(need) +
           " needs it; nothing moves";
}

}  // namespace

void Machine::applyTransformation(const Program&, const BlockWords& w)
{
    if (w.transform < 0 || !m_five.active())
        return;
    m_modal.traori = w.transform == 1;
    m_five.setTcpm(m_modal.traori, m_pos, m_known.complete());
}

// The block's rotary words: the angles the chain's joints take, with the diagnostics of words the
// machine cannot read. False: the block is left out.
bool Machine::rotaryTarget(const Program& p, const BlockWords& w, RotaryMove& r)
{
    r.angles = m_five.angles();
    bool ok = true, changed = false;
    for (std::size_t i = 3; i < 6; ++i) {
        if (!w.axis[i])
            continue;
        const char axis = "ABC"[i - 3];
        int joint = -1;
        const RotaryAxisUse use = m_five.use(axis, &joint);
        if (use == RotaryAxisUse::NoMachine) {
            warning(p, w.axisPos[i],
                    "rotary axes A B C need a five-axis machine (--machine, or the NC inspector's Machine) to be "
                    "traced: their values are ignored");
            continue;
        }
        if (use != RotaryAxisUse::Traced) {
            diag(use == RotaryAxisUse::Missing ? Severity::Error : Severity::Warning, p, w.axisPos[i],
                 m_five.useMessage(axis, use));
            ok = ok && use != RotaryAxisUse::Missing;
            continue;
        }
        if (m_modal.motion >= 2) {
            error(p, w.axisPos[i],
                  std::string(1, axis) + " in a G2/G3 block: arcs are traced with the rotary axes standing still");
            ok = false;
            continue;
        }
        const auto angle = m_five.angleFor(joint, *w.axis[i], modeOf(w.axisMode[i], m_modal.incremental));
        if (!angle) {
            error(p, w.axisPos[i], rotaryUnknownMessage(axis, "an incremental move"));
            ok = false;
            continue;
        }
        const auto j = static_cast<std::size_t>(joint);
        changed = changed || !r.angles.known[j] || std::abs(r.angles.deg[j] - *angle) > 1e-12;
        r.angles.deg[j] = *angle;
        r.angles.known[j] = true;
    }
    if (ok && !toolVector(p, w, r))
        ok = false;
    if (ok && r.angles.turned() && !r.angles.complete()) {
        const std::size_t missing = r.angles.known[0] ? 1 : 0;
        error(p, {w.line, 0},
              rotaryUnknownMessage(m_five.machine()->kinematics.joints[missing].axis[0],
                                   "the tool axis with the other rotary axis turned"));
        ok = false;
    }
    // From an unknown angle to 0 the tool is where a 3-axis program has it: no move of its own.
    r.moves = r.vector || (changed && (r.angles.turned() || m_five.fiveAxisMove()));
    return ok;
}

bool Machine::toolVector(const Program& p, const BlockWords& w, RotaryMove& r)
{
    const auto& v = w.toolVector;
    if (!v[0] && !v[1] && !v[2])
        return true;
    if (!m_five.active()) {
        warning(p, w.toolVectorPos,
                "A3= B3= C3= (tool vector) need a five-axis machine (--machine, or the NC inspector's Machine) to be "
                "traced: ignored");
        return true;
    }
    if (!m_modal.traori) {
        error(p, w.toolVectorPos, "A3= B3= C3= (tool vector) need TRAORI: the block is left out");
        return false;
    }
    if (w.axis[3] || w.axis[4] || w.axis[5]) {
        error(p, w.toolVectorPos, "the tool vector A3= B3= C3= and rotary axis positions in one block: left out");
        return false;
    }
    r.axis = {v[0].value_or(0), v[1].value_or(0), v[2].value_or(0)};
    if (r.axis.length() < 1e-9) {
        error(p, w.toolVectorPos, "the tool vector A3= B3= C3= is zero: the block is left out");
        return false;
    }
    r.vector = true;
    return true;
}

// A five-axis move needs the whole tip (a ToolAxisMove carries no axis mask) and, for a head
// without TRAORI, the tool's length.
bool Machine::fiveAxisReady(const Program& p, const BlockWords& w, const RotaryMove& r, AxisMask given, bool& traced)
{
    using Trace = FiveAxisState::BlockTrace;
    traced = true;
    const bool tipKnown = m_known.missing(kNoAxes, AxisMask{}, given) < 0;
    switch (m_five.blockTrace(r.angles, r.vector, tipKnown, given.bits != 0)) {
    case Trace::ThreeAxis:
        return true;
    case Trace::HomeUntraced:
        traced = false;
        return true;
    case Trace::TipUnknown:
        if (r.vector)
            return needKnown(p, w, kNoAxes, AxisMask{}, given, "the tool vector (solved at the tip)", {w.line, 0});
        warning(p, {w.line, 0},
                "a move with the rotary axes turned while X, Y or Z is unknown is not traced (the tool tip is "
                "unknown); the trace goes on once a block gives every axis");
        traced = false;
        return true;
    case Trace::NeedsToolLength:
        error(p, {w.line, 0},
              "the machine's head turns the tool about a pivot above its tip: without TRAORI the tool length "
              "is needed (the tool table); the block is left out");
        return false;
    case Trace::FiveAxis:
        break;
    }
    return true;
}

// The angles of the block: as its words give them, or solved for its tool vector at the target.
bool Machine::turnTo(const Program& p, const BlockWords& w, const RotaryMove& r, const Vec3& target)
{
    if (!m_five.active())
        return true;
    if (!r.vector) {
        m_five.setAngles(r.angles);
        return true;
    }
    if (const auto problem = m_five.orient(target, r.axis)) {
        error(p, w.toolVectorPos, "the tool vector A3= B3= C3=: " + *problem + "; the block is left out");
        return false;
    }
    return true;
}

bool Machine::moveFiveAxis(const Program& p, const BlockWords& w, const Vec3& target)
{
    const bool rapid = m_modal.motion == 0;
    if (!rapid && m_feed <= 0)
        error(p, {w.line, 0}, "G1 without a feed (F)");
    if (m_modal.comp != CutterCompSide::Off)
        warning(p, {w.line, 0}, "G41/G42 with the rotary axes turned is not traced: the programmed path is");
    setSource(w.line);
    m_sink.toolAxisMove(m_five.move(target, rapid ? 0 : m_feed));
    m_pos = target;
    return true;
}

}  // namespace camwb::nc::sinumerik
