// Tilted working planes in Klartext (iTNC 530 User's Manual, "The PLANE function" and cycle 19
// WORKING PLANE): PLANE SPATIAL / VECTOR / AXIAL / RESET and CYCL DEF 19 become WorkingPlane
// records, and the moves after them are 3-axis moves in the plane's frame. The plane turns about
// the datum: a datum shift (CYCL DEF 7) programmed before the tilt moves the plane's origin in the
// untilted frame, one programmed after it shifts within the tilted frame (the manual's order:
// datum shift, then tilt; reset in the reverse order). TURN and MOVE turn the rotary axes of a
// five-axis machine onto the plane (SEQ picks the branch); STAY leaves them and sets Q120..Q122.
#include "nc/heidenhain/Machine.h"

#include "toolpath/PlaneFrames.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camwb::nc::heidenhain {

using namespace camwb::toolpath;

namespace {

// The tool may stand this far (degrees) off the plane's Z: rotary angles are written to 3 decimals.
constexpr double kPlaneAxisToleranceDeg = 0.005;

std::string formName(const Block& b) { return b.flag ? "PLANE RESET" : "PLANE " + std::string(b.name); }

}  // namespace

void Machine::planeFunction(const Block& b)
{
    m_planeAngles.reset();
    std::array<std::optional<double>, kPlaneWordCount> v;
    std::optional<double> mb;  // nullopt with mbMax false: no retract
    bool mbMax = false;
    const Program& p = program();
    for (int i = 0; i < b.wordCount; ++i) {
        const Word& word = p.words[static_cast<std::size_t>(b.firstWord + i)];
        if (word.key == Key::Mb && word.param == 1) {
            mbMax = true;
            continue;
        }
        const auto value = eval(word.expr);
        if (!value)
            return;
        if (word.key == Key::Mb)
            mb = *value;
        else
            v[static_cast<std::size_t>(word.param)] = *value;
    }
    std::optional<WorkingPlane> plane;
    if (b.flag) {
        plane = WorkingPlane{};
    } else if (equalsIgnoreCase(b.name, "SPATIAL")) {
        plane = planeFromSpatialAngles(v[kPlaneSpa].value_or(0), v[kPlaneSpb].value_or(0), v[kPlaneSpc].value_or(0));
    } else if (equalsIgnoreCase(b.name, "VECTOR")) {
        plane = planeOfVectors(b, v);
        if (!plane)
            return;
    } else if (equalsIgnoreCase(b.name, "AXIAL")) {
        plane = planeOfAxisAngles(b, {v[kPlaneAxisA], v[kPlaneAxisB], v[kPlaneAxisC]}, "PLANE AXIAL");
        if (!plane)
            return;
    } else {
        report(Severity::Warning, b.line, b.column,
               formName(b) + " is not traced: the tilted working plane is left as it was");
        return;
    }
    if (mb || mbMax)
        retract(b, mbMax ? std::nullopt : mb, formName(b) + " MB");
    tilt(b, *plane);
    positionForPlane(b, *plane);
}

// PLANE VECTOR: the base vector is the plane's X, the normal its Z (the control normalises both and
// takes X square to Z).
std::optional<WorkingPlane> Machine::planeOfVectors(const Block& b,
                                                    const std::array<std::optional<double>, kPlaneWordCount>& v)
{
    const Vec3 base{v[kPlaneBx].value_or(0), v[kPlaneBy].value_or(0), v[kPlaneBz].value_or(0)};
    const Vec3 normal{v[kPlaneNx].value_or(0), v[kPlaneNy].value_or(0), v[kPlaneNz].value_or(0)};
    if (normal.length() < 1e-9 || base.length() < 1e-9) {
        report(Severity::Error, b.line, b.column, "PLANE VECTOR needs a base vector BX BY BZ and a normal NX NY NZ");
        return std::nullopt;
    }
    const Vec3 z = normal * (1 / normal.length());
    const Vec3 x = base - z * base.dot(z);
    if (x.length() < 1e-6) {
        report(Severity::Error, b.line, b.column, "PLANE VECTOR: the base vector lies along the normal");
        return std::nullopt;
    }
    WorkingPlane plane;
    plane.xAxis = x * (1 / x.length());
    plane.zAxis = z;
    return plane;
}

// The plane the machine's axis angles set (CYCL DEF 19, PLANE AXIAL): all angles 0 is the untilted
// plane on any machine; otherwise it takes a five-axis machine's kinematics.
std::optional<WorkingPlane> Machine::planeOfAxisAngles(const Block& b, const std::array<std::optional<double>, 3>& abc,
                                                       const std::string& what)
{
    bool tilted = false;
    for (const auto& a : abc)
        tilted = tilted || (a && std::abs(*a) > 1e-9);
    if (!tilted)
        return WorkingPlane{};
    if (!m_five.active()) {
        report(Severity::Error, b.line, b.column,
               what + " gives the machine's rotary axis positions: its working plane needs a five-axis machine "
                      "(--machine, or the NC inspector's Machine) to be known; the moves after it are traced untilted");
        return std::nullopt;
    }
    std::array<double, 2> deg{0, 0};  // an axis the block does not name stands at 0
    for (int i = 0; i < 3; ++i) {
        if (!abc[static_cast<std::size_t>(i)])
            continue;
        const char axis = "ABC"[i];
        int joint = -1;
        const RotaryAxisUse use = m_five.use(axis, &joint);
        if (use != RotaryAxisUse::Traced) {
            if (std::abs(*abc[static_cast<std::size_t>(i)]) > 1e-9) {
                report(Severity::Error, b.line, b.column, what + ": " + m_five.useMessage(axis, use));
                return std::nullopt;
            }
            continue;
        }
        deg[static_cast<std::size_t>(joint)] = *abc[static_cast<std::size_t>(i)];
    }
    m_planeAngles = deg;
    return m_five.planeOfAngles(deg);
}

// CYCL DEF 19.1 with A, B, C (the machine's axis angles: the control set for axis angles, MP7500
// bit 1 = 0); all 0 resets the tilt.
void Machine::workingPlaneCycle(const Block& b, const BlockWords& w)
{
    for (int i = 12; i <= 14; ++i) {
        if (w.axes[static_cast<std::size_t>(i)]) {
            report(Severity::Error, b.line, b.column, "CYCL DEF 19 takes absolute angles A, B, C, not IA, IB, IC");
            return;
        }
    }
    m_planeAngles.reset();
    const auto plane = planeOfAxisAngles(b, {w.axes[3], w.axes[4], w.axes[5]}, "CYCL DEF 19");
    if (plane)
        tilt(b, *plane);
}

// Sets the tilt (`rotation` about the datum; the untilted plane resets it), turned by the
// CYCL DEF 10 rotation in force, and writes the record. The position stays where the tool is, in
// the new frame's coordinates, when it is known.
void Machine::tilt(const Block& b, const WorkingPlane& rotation)
{
    if (m_comp != CutterCompSide::Off) {
        report(Severity::Error, b.line, b.column,
               "a working plane changed with radius compensation RL/RR on: the plane is not changed");
        return;
    }
    m_tilt = rotation;
    const WorkingPlane old = m_plane;
    WorkingPlane next = rotation;
    if (m_rotationDeg != 0) {  // the frame's X and Y turned about its Z, counter-clockwise seen from +Z
        const double r = m_rotationDeg * std::acos(-1.0) / 180;
        next.xAxis = rotation.xAxis * std::cos(r) + rotation.yAxis() * std::sin(r);
    }
    if (next.tilted()) {
        // The first tilt turns about the datum the shift set; a shift made in the tilted frame stays there.
        next.origin = old.tilted() ? old.origin : m_shift;
        if (!old.tilted())
            m_shift = Vec3{};
    } else {
        m_shift = old.toWorkpiece(m_shift);  // the datum the tilt turned about, in the untilted frame
        next = WorkingPlane{};
    }
    if (m_known.complete())
        m_pos = m_five.reframe(old, next, m_pos);
    else
        m_known.forget();
    m_tangents = {};
    m_programmed = kNoAxes;
    m_plane = next;
    m_planeChecked = false;
    m_five.setInPlane(next.tilted());
    source(b);
    m_sink.workingPlane(next);
}

// CYCL DEF 10 ROTATION (iTNC 530 User's Manual, cycle 10): the coordinates turn about the working
// plane's tool axis through the datum, ROT absolute, IROT added to the rotation in force; 0 undoes
// it. The working plane written is the tilt turned so.
void Machine::rotationCycle(const Block& b)
{
    if (b.b == 0 || b.wordCount != 1)
        return;
    const Word& word = program().words[static_cast<std::size_t>(b.firstWord)];
    const auto value = eval(word.expr);
    if (!value)
        return;
    m_rotationDeg = word.param == 1 ? m_rotationDeg + *value : *value;
    m_rotationDeg = std::remainder(m_rotationDeg, 360.0);
    tilt(b, m_tilt);
}

// TURN and MOVE turn a five-axis machine's rotary axes onto the plane (on the branch SEQ names);
// STAY leaves them and gives their angles in Q120..Q122 (A, B, C) for the program to move them.
void Machine::positionForPlane(const Block& b, const WorkingPlane& plane)
{
    if (!m_five.active() || (b.a != kPlaneTurn && b.a != kPlaneMove && b.a != kPlaneStay))
        return;
    const JointAngles before = m_five.angles();
    if (!plane.tilted()) {
        JointAngles home;
        home.known = {true, true};
        m_five.setAngles(b.a == kPlaneStay ? before : home);
        return;
    }
    if (m_planeAngles) {  // AXIAL: the angles are given
        JointAngles given;
        given.deg = *m_planeAngles;
        given.known = {true, true};
        m_five.setAngles(given);
    } else if (const auto problem = m_five.orientPlane(plane.zAxis, b.b)) {
        report(Severity::Error, b.line, b.column, formName(b) + ": " + *problem);
        return;
    }
    const JointAngles turned = m_five.angles();
    const kinematics::KinematicChain& chain = m_five.machine()->kinematics;
    for (std::size_t j = 0; j < chain.joints.size() && j < 2; ++j) {
        const std::string& axis = chain.joints[j].axis;
        if (axis.size() == 1 && axis[0] >= 'A' && axis[0] <= 'C')
            m_params.q[static_cast<std::size_t>(120 + (axis[0] - 'A'))] = turned.deg[j];
    }
    if (b.a == kPlaneStay)
        m_five.setAngles(before);
}

// A move in a tilted plane with the rotary angles known: the tool must stand along the plane's Z,
// or the machine cuts another plane than the program's frame says (once per plane).
void Machine::checkToolAlongPlane(const Block& b)
{
    if (m_planeChecked || !m_five.active() || !m_five.inPlane() || !m_five.angles().complete())
        return;
    const Vec3 axis = m_five.toolAxis();
    const double cosine = std::clamp(axis.dot(m_plane.zAxis), -1.0, 1.0);
    const double offDeg = std::acos(cosine) * 180 / std::numbers::pi;
    m_planeChecked = true;  // until the angles change
    if (offDeg <= kPlaneAxisToleranceDeg)
        return;
    report(Severity::Error, b.line, b.column,
           "the rotary axes point the tool " + base::formatFixed(offDeg, 3) +
               " degrees off the tilted working plane's Z axis: the moves are traced in the plane as programmed");
}

}  // namespace camwb::nc::heidenhain
