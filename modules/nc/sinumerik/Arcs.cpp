// G2/G3 in the plane of G17 (XY), G18 (ZX) or G19 (YZ): centre by I J K (incremental from the
// start, or =AC(..) absolute), by CR= (negative: more than 180 degrees), or by AR= (opening angle,
// with an end point or with a centre); TURN= adds full turns. The axis normal to the plane makes
// a helix. Start and end radii that differ by more than the tolerance are an error.
#include "nc/sinumerik/Machine.h"

#include "base/NumberFormat.h"
#include "nc/detail/PlaneAxes.h"

#include <cmath>
#include <numbers>

namespace camwb::nc::sinumerik {

namespace {

using namespace camwb::toolpath;
using detail::component;
using detail::PlaneAxes;
using detail::planeAxes;
using detail::setComponent;

std::string mm(double v) { return base::formatFixed(v, 4); }

}  // namespace

bool Machine::arc(const Program& p, const Vec3& to, bool clockwise, const ArcWords& words, int line)
{
    const PlaneAxes axes = planeAxes(m_modal.plane);
    const Vec3 start = m_pos;
    Vec3 end = to;
    const double su = component(start, axes.u), sv = component(start, axes.v);
    double eu = component(end, axes.u), ev = component(end, axes.v);
    const double tol = m_options.arcRadiusToleranceMm;
    constexpr double kDeg = std::numbers::pi / 180.0;
    auto fail = [&](const std::string& message) {
        error(p, words.pos, message);
        m_pos = end;  // carry on from where the program meant to be
        return false;
    };
    // The centre word of a plane axis: I for X, J for Y, K for Z.
    auto centreOf = [&](int axis, double startValue) {
        const auto& value = words.centre[static_cast<std::size_t>(axis)];
        if (!value)
            return startValue;
        double v = toMm(*value);
        if (words.centreMode[static_cast<std::size_t>(axis)] == ValueMode::Absolute) {
            if (axis == 0 && m_modal.diameter)
                v /= 2;
            return v;
        }
        return startValue + v;
    };
    const bool hasCentre =
        words.centre[static_cast<std::size_t>(axes.u)] || words.centre[static_cast<std::size_t>(axes.v)];
    const bool endGiven = eu != su || ev != sv || component(end, axes.w) != component(start, axes.w);
    double cu = 0, cv = 0;
    if (hasCentre) {
        cu = centreOf(axes.u, su);
        cv = centreOf(axes.v, sv);
        if (words.ar && !endGiven) {
            // AR with a centre and no end: turn the start round the centre.
            const double a = (clockwise ? -*words.ar : *words.ar) * kDeg;
            const double du = su - cu, dv = sv - cv;
            eu = cu + du * std::cos(a) - dv * std::sin(a);
            ev = cv + du * std::sin(a) + dv * std::cos(a);
            setComponent(end, axes.u, eu);
            setComponent(end, axes.v, ev);
        }
    } else if (words.cr || words.ar) {
        const double du = eu - su, dv = ev - sv;
        const double chord = std::hypot(du, dv);
        if (chord < 1e-9)
            return fail(words.cr ? "CR= cannot make a full circle: start and end are the same point (use I J K)"
                                 : "AR= with the end at the start needs a centre (I J K)");
        const double nu = -dv / chord, nv = du / chord;  // left of the chord
        double h = 0;
        if (words.cr) {
            const double r = std::abs(*words.cr);
            if (r <= 0)
                return fail("CR=0 is no circle");
            const double h2 = r * r - chord * chord / 4;
            if (h2 < 0) {
                if (chord / 2 - r > tol)
                    return fail("CR=" + mm(r) + " is smaller than half the distance to the end point (" +
                                mm(chord / 2) + " mm)");
            } else {
                h = std::sqrt(h2);
            }
            if (*words.cr < 0)
                h = -h;  // more than a half circle: the centre on the other side
        } else {
            const double ar = *words.ar;
            if (!(ar > 0 && ar < 360))
                return fail("AR= must be between 0 and 360 degrees with an end point");
            h = chord / 2 / std::tan(ar * kDeg / 2);
        }
        if (clockwise)
            h = -h;
        cu = su + du / 2 + nu * h;
        cv = sv + dv / 2 + nv * h;
    } else {
        return fail(std::string(clockwise ? "G2" : "G3") + " needs a centre (I J K), CR= or AR=");
    }
    const double rs = std::hypot(su - cu, sv - cv);
    const double re = std::hypot(eu - cu, ev - cv);
    if (rs < 1e-9)
        return fail("the arc's centre is its start point");
    if (std::abs(rs - re) > tol)
        return fail("arc radius at the start " + mm(rs) + " mm and at the end " + mm(re) + " mm differ by " +
                    mm(std::abs(rs - re)) + " mm (more than " + mm(tol) + ")");
    Arc a;
    a.to = end;
    setComponent(a.center, axes.u, cu);
    setComponent(a.center, axes.v, cv);
    setComponent(a.center, axes.w, component(start, axes.w));
    a.normal = axes.normal;
    a.clockwise = clockwise;
    a.turns = words.turn;
    a.feedMmPerMin = m_feed;
    setSource(line);
    if (m_five.active() && m_five.fiveAxisMove())
        a = m_five.arcInWorkpiece(a);  // the axes move on the circle, the table turned (TRAFOOF)
    m_sink.arc(a);
    m_pos = end;
    return true;
}

}  // namespace camwb::nc::sinumerik
