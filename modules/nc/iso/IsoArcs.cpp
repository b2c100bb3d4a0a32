// G2/G3 of the ISO machine in G17 (XY, I/J), G18 (ZX, K/I) and G19 (YZ, J/K): centre words
// relative to the start (G91.1) or absolute (G90.1), or R (negative: more than 180 degrees), P
// for whole turns, the third axis making a helix. G2 is clockwise seen from the positive axis
// normal to the plane, as LinuxCNC draws it.
#include "nc/iso/IsoMachine.h"

#include "base/NumberFormat.h"
#include "nc/detail/PlaneAxes.h"

#include <cmath>
#include <string>

namespace camwb::nc::iso {

using namespace camwb::toolpath;
using detail::component;
using detail::setComponent;

namespace {

struct PlaneAxes {
    int a, b;           // in-plane axes (0 x, 1 y, 2 z), a x b = normal
    char wordA, wordB;  // centre words along a and b
    char other;         // the centre word that belongs to no axis of this plane
    Vec3 normal;
};

PlaneAxes axesOf(int plane)
{
    switch (plane) {
    case 180:
        return {2, 0, 'K', 'I', 'J', {0, 1, 0}};
    case 190:
        return {1, 2, 'J', 'K', 'I', {1, 0, 0}};
    default:
        return {0, 1, 'I', 'J', 'K', {0, 0, 1}};
    }
}

std::string mm(double v) { return base::formatFixed(v, 4); }

}  // namespace

void Machine::arc(const Block& block, bool clockwise, const Vec3& to)
{
    const PlaneAxes p = axesOf(m_state.plane);
    const Vec3& from = m_state.position;
    const double unit = m_state.unit;
    const double sa = component(from, p.a), sb = component(from, p.b);
    const double ea = component(to, p.a), eb = component(to, p.b);
    const char* name = clockwise ? "G2" : "G3";
    double ca = 0, cb = 0;

    int turns = 0;
    if (block.has('P')) {
        const double pw = block.get('P');
        if (pw < 1 || pw != std::floor(pw) || pw > 1e6) {
            error(block, 'P', std::string(name) + " P (turns) must be a whole number >= 1");
            return;
        }
        turns = static_cast<int>(pw) - 1;
    }
    if (block.has('R')) {
        if (block.has(p.wordA) || block.has(p.wordB)) {
            error(block, 'R', std::string(name) + " with both R and centre words");
            return;
        }
        const double radius = block.get('R') * unit;
        const double da = ea - sa, db = eb - sb;
        const double chord = std::sqrt(da * da + db * db);
        if (chord < 1e-9) {
            error(block, 'R', std::string(name) + " with R cannot make a full circle: its start and end coincide");
            return;
        }
        const double half = chord / 2;
        const double r = std::abs(radius);
        if (r == 0 || half > r + m_arcTolerance) {
            error(block, 'R',
                  std::string(name) + " radius " + mm(r) + " is too small for the chord " + mm(chord) +
                      " (at most 2R)");
            return;
        }
        const double h = half >= r ? 0.0 : std::sqrt(r * r - half * half);
        // Right of the chord for a clockwise arc of at most 180 degrees; the other side otherwise.
        const double side = (clockwise ? 1.0 : -1.0) * (radius > 0 ? 1.0 : -1.0);
        ca = sa + da / 2 + side * h * (db / chord);
        cb = sb + db / 2 - side * h * (da / chord);
    } else {
        if (!block.has(p.wordA) && !block.has(p.wordB)) {
            m_reporter.error(
                m_line, 0, std::string(name) + " needs " + p.wordA + " or " + p.wordB + " (centre) or R in this plane");
            return;
        }
        if (block.has(p.other))
            m_reporter.warning(m_line, block.col(p.other),
                               std::string(1, p.other) + " is no centre word in this plane: ignored");
        const double ia = block.has(p.wordA) ? block.get(p.wordA) * unit : 0.0;
        const double ib = block.has(p.wordB) ? block.get(p.wordB) * unit : 0.0;
        if (m_state.arcAbsolute) {
            ca = block.has(p.wordA) ? ia : sa;
            cb = block.has(p.wordB) ? ib : sb;
        } else {
            ca = sa + ia;
            cb = sb + ib;
        }
        const double r1 = std::sqrt((sa - ca) * (sa - ca) + (sb - cb) * (sb - cb));
        const double r2 = std::sqrt((ea - ca) * (ea - ca) + (eb - cb) * (eb - cb));
        if (r1 < 1e-9) {
            m_reporter.error(m_line, block.has(p.wordA) ? block.col(p.wordA) : block.col(p.wordB),
                             std::string(name) + " with zero radius: the centre is the start point");
            return;
        }
        if (std::abs(r1 - r2) > m_arcTolerance)
            m_reporter.error(m_line, block.has(p.wordA) ? block.col(p.wordA) : block.col(p.wordB),
                             std::string(name) + " radius differs at start (" + mm(r1) + ") and end (" + mm(r2) +
                                 ") by more than " + mm(m_arcTolerance) + " mm");
    }
    Vec3 centre = from;  // the third axis of the centre is the start's
    setComponent(centre, p.a, ca);
    setComponent(centre, p.b, cb);
    const double feed = feedFor(block, name);
    source();
    m_sink.arc(Arc{to, centre, p.normal, clockwise, turns, feed});
    m_state.position = to;
}

}  // namespace camwb::nc::iso
