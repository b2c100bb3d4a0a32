// CYCLE800 (swivel plane, SINUMERIK 840D sl Programming Manual Cycles, "Swiveling - CYCLE800"):
// CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR, _FR_I, _DMODE)
// becomes a WorkingPlane record, and the moves after it are 3-axis moves in the swivelled frame.
// The frame: shifted to X0 Y0 Z0 (in the frame before it), turned, then shifted by X1 Y1 Z1 in the
// turned frame. _MODE bits 7-6 give the swivel mode: 00 axis by axis (bits 1-0, 3-2, 5-4 name the
// axis of A, B, C: 01 X, 10 Y, 11 Z; each turn about the axis the turns before it left, so 57 is
// X, then Y', then Z'' and 27 Z, Y', X'' — the spatial angles of PLANE SPATIAL), 11 direct (A and B
// the positions of rotary axes 1 and 2, through the machine's kinematics); solid and projection
// angles are not traced. _ST's units digit: 0 a new plane, 1 additive to the one in force. _DIR
// +1/-1 swivels the rotary axes on that branch of rotary axis 1, 0 sets the frame only. _FR > 0
// retracts first to where the machine data says (the position is then unknown). CYCLE800() resets.
#include "nc/sinumerik/Machine.h"

#include "nc/KnownAxes.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::sinumerik {

using namespace camwb::toolpath;

namespace {

// Rotation by `deg` about axis 1 X, 2 Y, 3 Z, as the columns of a frame.
WorkingPlane turnAbout(int axis, double deg)
{
    const double r = deg * std::numbers::pi / 180, c = std::cos(r), s = std::sin(r);
    WorkingPlane t;
    if (axis == 1) {
        t.zAxis = {0, -s, c};
    } else if (axis == 2) {
        t.xAxis = {c, 0, -s};
        t.zAxis = {s, 0, c};
    } else {
        t.xAxis = {c, s, 0};
    }
    return t;
}

// `outer` then `inner` in outer's frame: inner's axes and origin seen from outer's parent.
WorkingPlane compose(const WorkingPlane& outer, const WorkingPlane& inner)
{
    WorkingPlane r;
    r.origin = outer.toWorkpiece(inner.origin);
    r.xAxis = outer.direction(inner.xAxis);
    r.zAxis = outer.direction(inner.zAxis);
    return r;
}

// Exact zeros where rounding left a trace, so an untilted result compares equal to the default.
Vec3 tidy(Vec3 v)
{
    for (double* c : {&v.x, &v.y, &v.z})
        if (std::abs(*c) < 1e-15)
            *c = 0;
    return v;
}

}  // namespace

void Machine::swivel(const Program& p, const Block& b, const Word& word)
{
    const auto args = evalArgs(p, b);
    if (m_evalFailed)
        return;
    auto arg = [&](std::size_t i) { return i < args.size() && args[i] ? *args[i] : 0.0; };
    if (m_modal.comp != CutterCompSide::Off) {
        error(p, word.pos, "CYCLE800 with G41/G42 on: the swivel plane is not changed");
        return;
    }
    if (m_modal.traori) {
        error(p, word.pos, "CYCLE800 under TRAORI: the swivel plane is not changed");
        return;
    }
    if (args.empty()) {
        setPlane(b.line, WorkingPlane{});
        return;
    }
    const int mode = static_cast<int>(arg(3));
    const int kind = (mode >> 6) & 3;
    const Vec3 before{toMm(arg(4)), toMm(arg(5)), toMm(arg(6))};
    const Vec3 after{toMm(arg(10)), toMm(arg(11)), toMm(arg(12))};
    WorkingPlane turn;
    if (kind == 0) {
        for (int i = 0; i < 3; ++i) {
            const int axis = (mode >> (2 * i)) & 3;
            if (axis == 0) {
                error(p, word.pos,
                      "CYCLE800 _MODE " + std::to_string(mode) + ": bits " + std::to_string(2 * i + 1) + "-" +
                          std::to_string(2 * i) + " name no axis for " + std::string(1, "ABC"[i]) +
                          " (01 X, 10 Y, 11 Z)");
                return;
            }
            turn = compose(turn, turnAbout(axis, arg(7 + static_cast<std::size_t>(i))));
        }
    } else if (kind == 3) {
        if (!m_five.active()) {
            if (std::abs(arg(7)) > 1e-9 || std::abs(arg(8)) > 1e-9) {
                error(p, word.pos,
                      "CYCLE800 direct mode gives rotary axis positions: its plane needs a five-axis machine "
                      "(--machine, or the NC inspector's Machine); the swivel plane is not changed");
                return;
            }
        } else {
            turn = m_five.planeOfAngles({arg(7), arg(8)});
        }
    } else {
        error(p, word.pos,
              std::string("CYCLE800 swivel by ") + (kind == 1 ? "solid" : "projection") +
                  " angles is not traced: the swivel plane is not changed");
        return;
    }
    WorkingPlane plane =
        compose(WorkingPlane{before, {1, 0, 0}, {0, 0, 1}}, compose(turn, {after, {1, 0, 0}, {0, 0, 1}}));
    plane.origin = tidy(plane.origin);
    plane.xAxis = tidy(plane.xAxis);
    plane.zAxis = tidy(plane.zAxis);
    const int st = static_cast<int>(arg(2));
    if (st % 10 == 1)
        plane = compose(m_plane, plane);  // additive: on top of the plane in force
    else if (st % 10 != 0)
        warning(p, word.pos, "CYCLE800 _ST " + std::to_string(st) + ": taken as a new swivel plane");
    // _FR: retracted to the machine's retract position, which the trace does not know.
    if (arg(0) > 0) {
        setSource(b.line);
        m_known.lose(AxisMask{}, m_sink);
    }
    setPlane(b.line, plane);
    const int dir = static_cast<int>(arg(13));
    if (dir == 0 || !m_five.active())
        return;
    if (kind == 3 || !plane.tilted()) {  // the angles given, or home for the untilted plane
        JointAngles given;
        given.deg = kind == 3 ? std::array<double, 2>{arg(7), arg(8)} : std::array<double, 2>{0, 0};
        given.known = {true, true};
        m_five.setAngles(given);
    } else if (const auto problem = m_five.orientPlane(plane.zAxis, dir > 0 ? 1 : -1)) {
        error(p, word.pos, "CYCLE800: " + *problem);
    }
}

// The new plane's record; the position stays where the tool is, in the new frame, when it is known.
void Machine::setPlane(int line, const WorkingPlane& plane)
{
    if (m_known.complete())
        m_pos = m_five.reframe(m_plane, plane, m_pos);
    else
        m_known.forget();
    m_plane = plane;
    m_five.setInPlane(plane.tilted());
    setSource(line);
    m_sink.workingPlane(plane);
}

}  // namespace camwb::nc::sinumerik
