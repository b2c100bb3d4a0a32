#include "ops/turning/GrooveSweeps.h"

#include "ops/OpCommon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace camwb::ops::turning {

namespace {

// The subprograms' channel R-parameters, by the names of seed §2.3 (short names without m_, so
// that they read as the NC does), and the moves they make.
// Each method is one subprogram; the comments name the NC blocks they come from.
class Sweeps {
public:
    Sweeps(const GrooveSetup& setup, std::string what) :
        g(setup.geo),
        w(setup.widthMm),
        s(setup.widthMm * setup.stepFactor),
        i(setup.infeedMm),
        c(setup.safetyMm),
        xb(setup.geo.bottomOffsetX),
        m_limit(setup.iterationLimit),
        m_what(std::move(what))
    {
        rpx = g.r.y;
        rpz = g.r.x;
    }

    base::Status run(const std::function<bool(double)>& keepGoing);
    GrooveMoves take() { return std::move(m_out); }

private:
    // PODPROG_ZAPICH's L1 (Rov. 82 as the code has it, with -R9) and L2 (Rov. 83).
    double l1() const { return ((rpx - g.t.y) * g.tan5 + g.t.x - rpz - w) / (s + g.tan5 * i); }
    double l2() const { return (g.zLeft(bx) - bz + w) / (-g.tan6 * i - s); }
    // Retract after plunge n of a left-to-right sweep: in the first pass R30 over the surface at
    // the next plunge's right corner (Rov. 80), later R11 (2 + n) + R30 over the sweep's start.
    double retractZl(double n) const
    {
        return firstPass ? g.r.y + g.tan2 * (w + s + s * n) + c : rpx + i * (2 + n) + c;
    }

    void closeGap(double lastZ, double flankZ, double depth, double retractX);
    double riseForRapidZ(double toZ);
    void zl();
    void zp();
    void dnoZl();
    void dnoZp();
    void fallback();

    void rapidX(double x) { add({GrooveMove::Kind::RapidX, x, 0}); }
    void rapidZ(double z) { add({GrooveMove::Kind::RapidZ, 0, z}); }
    void feed(double x, double z) { add({GrooveMove::Kind::Feed, x, z}); }
    void feedX(double x) { feed(x, m_z); }
    void add(GrooveMove m)
    {
        if (m.kind != GrooveMove::Kind::RapidX)
            m_z = m.z;
        if (m.kind != GrooveMove::Kind::RapidZ)
            m_x = m.x;
        m_out.moves.push_back(m);
    }
    // One turn of any loop; false (and the error) past the iteration limit.
    bool turn()
    {
        if (++m_turns <= m_limit)
            return true;
        if (m_error.empty())
            m_error = "the groove strategy did not finish within " + std::to_string(m_limit) +
                      " steps (seed REQ-25); please report the parameters";
        return false;
    }

    const sim::GrooveGeometry& g;
    const double w, s, i, c, xb;  // R9, R9*R10, R11, R30, R0-R3+R7
    const long m_limit;
    std::string m_what;
    double rpx = 0, rpz = 0;  // R12, R13: Rp, start of the left-to-right sweep on the left offset flank
    double bx = 0, bz = 0;    // R21, R20: B, its end (right corner) on the right offset flank
    long r18 = 0;             // plunge counter of the last sweep
    long r27 = 0, r28 = 0;    // last regular plunge of ZL / ZP (ROUNDUP(L - 1))
    bool firstPass = true;    // the thesis' R12 == R23
    bool finished = false;    // fix F4: a bottom phase has run
    double m_x = 0, m_z = 0;  // where the insert is
    long m_turns = 0;
    std::string m_error;
    GrooveMoves m_out;
};

// PODPROG_ZAPICH N72..N90, with F4 (the loop ends when a bottom phase has run) and F5.
base::Status Sweeps::run(const std::function<bool(double)>& keepGoing)
{
    rapidZ(g.r.x);                   // N72 G0 Z=R24
    rapidX(g.r.y + g.tan2 * w + c);  // N73 G0 X=R23+TAN(R2)*R9+R30
    r27 = 0;
    r28 = 0;
    const double depth = g.r.y - xb;
    while (!finished) {
        if (!turn())
            return opError(m_what, m_error);
        if (keepGoing && !keepGoing(depth > 0 ? std::clamp((g.r.y - rpx) / depth, 0.0, 1.0) : 0))
            return cancelledError(m_what);
        const double L1 = l1();
        GroovePass pass;
        pass.l1 = L1;
        pass.l2 = pass.rpx = pass.rpz = std::nan("");
        m_out.passes.push_back(pass);
        if (L1 <= 1) {  // F5: no second plunge, the passes would never go deeper
            fallback();
            break;
        }
        zl();
        if (finished)
            break;
        r27 = static_cast<long>(std::ceil(L1 - 1));
        bx = rpx - r27 * i;
        bz = g.zRight(bx);
        m_out.passes.back().r27 = r27;
        m_out.passes.back().bx = bx;
        m_out.passes.back().bz = bz;
        if (!(bx > xb)) {  // fixes.md G2: ZL ended on the flank, yet B is at the bottom
            fallback();
            break;
        }
        zp();
        if (finished)
            break;
        const double L2 = l2();
        r28 = static_cast<long>(std::ceil(L2 - 1));
        rpx = bx - r28 * i;
        rpz = g.zLeft(rpx);
        firstPass = false;
        m_out.passes.back().l2 = L2;
        m_out.passes.back().r28 = r28;
        m_out.passes.back().rpx = rpx;
        m_out.passes.back().rpz = rpz;
    }
    if (!m_error.empty())
        return opError(m_what, m_error);
    return base::Status::success();
}

// Fix G1 (docs/groove-strategy.md): a sweep stops where its next plunge would cut the flank, and
// the plunge on the flank (left corner `flankZ`) may then lie more than an insert's width from the
// last plunge (left corner `lastZ`, same depth): with R10 = 1, or when tan R5 * R11 (tan R6 * R11)
// exceeds R9 (1 - R10). The rib between would stand up to the floor above, and the next rapid
// along Z at the sweep's low retract height would run through it. One plunge at the same depth
// next to the flank plunge closes the gap first, retracting to `retractX` (the height the sweep is
// at). The gap is at most R9 R10 - R9 + R11 tan(flank) <= R9 R10 (input check V1), so one is
// enough; where the plunges overlap (Kod 1) nothing is added.
void Sweeps::closeGap(double lastZ, double flankZ, double depth, double retractX)
{
    const double dir = flankZ > lastZ ? 1 : -1;  // towards the flank
    if (!((flankZ - lastZ) * dir > w))
        return;
    rapidZ(flankZ - dir * w);
    feedX(depth);
    rapidX(retractX);
}

// Fixes G3, G5 (docs/groove-strategy.md), before a rapid along Z to left corner `toZ`: the rapid to
// a flank plunge goes further than one step (up to R9 R10 + R11 tan(flank)), so it may pass over a
// staircase cell one infeed higher than the sweep's retract height clears; so may the rapids of
// the right-flank clean-ups in the first pass, whose heights the thesis takes at the regular
// plunges' positions. The top of the material there: going right in the first pass the surface
// at the insert's right corner, going left (ZP) the floor the ZL sweep left at the left corner,
// R12 - R11 floor((z - R13) / (R9 R10)). Where the sweep is below it the insert first rises to it
// plus R30. Returns the height the sweep is at.
double Sweeps::riseForRapidZ(double toZ)
{
    double top = -std::numeric_limits<double>::infinity();  // of the material the move passes over
    if (toZ > m_z && firstPass)                             // ZL, DNO_ZL
        top = g.surfaceX(toZ + w);
    else if (toZ < m_z)  // ZP: toZ >= R13 (the flank plunge lies right of Rp)
        top = rpx - i * std::floor((toZ - rpz) / s);
    // Only where the rapid would cut (1e-6: touching is what the thesis' own rapids do with R30 =
    // R11), so that Kod 1 keeps its blocks.
    if (m_x < top - 1e-6)
        rapidX(top + c);
    return m_x;
}

// PODPROG_ZL: plunges left to right, each R11 deeper, until the bottom or the right flank; then
// the plunge on the flank and the right-flank clean-up up to the flank's top.
void Sweeps::zl()
{
    m_out.calls.push_back("ZL");
    r18 = 0;
    while (rpx - r18 * i > xb && rpz + s * r18 + w < g.zRight(rpx - r18 * i) && turn()) {  // N160
        rapidZ(rpz + s * r18);
        feedX(rpx - r18 * i);
        rapidX(retractZl(r18));
        ++r18;
    }
    if (rpx - r18 * i <= xb) {  // N170
        dnoZl();
        return;
    }
    const double d = rpx - (r18 - 1) * i;  // the last depth; the right corner on the flank there
    const double zd = g.zRight(d);
    if (r18 >= 1)  // fixes.md G1: no rib between the last plunge and the one on the flank
        closeGap(rpz + s * (r18 - 1), zd - w, d, riseForRapidZ(zd - w));
    rapidZ(zd - w);
    feedX(d);
    rapidX(retractZl(r18));
    const double top = rpx + (firstPass ? g.h1 : 0) + r28 * i;  // R12+R56+R28*R11
    const double zTop = g.zRight(top);
    for (long r19 = 1; zd + s * r19 < zTop && turn(); ++r19) {  // only with tan R5 > 0
        riseForRapidZ(zd - w + s * r19);                        // G5
        rapidZ(zd - w + s * r19);
        feedX(g.xRight(zd + s * r19));
        feed(d, zd - w);
        rapidX(firstPass ? g.r.y + g.tan2 * (w + s + s * r18 + s * r19) + c : rpx + i * (2 + r18 + r19) + c);
    }
    riseForRapidZ(zTop - w);  // G5
    rapidZ(zTop - w);
    feedX(top);
    feed(d, zd - w);
    rapidX(d + i + c);
}

// PODPROG_ZP: plunges right to left from one step left of B, each R11 deeper, until the bottom or
// the left flank; then the plunge on the left flank, its clean-up, and the slide to the new Rp.
void Sweeps::zp()
{
    m_out.calls.push_back("ZP");
    r18 = 1;
    while (bx - r18 * i > xb && bz - w - s * r18 > g.zLeft(bx - r18 * i) && turn()) {  // N160
        rapidZ(bz - w - s * r18);
        feedX(bx - r18 * i);
        rapidX(bx + i + r18 * i + c);
        ++r18;
    }
    if (bx - r18 * i <= xb) {  // N165
        dnoZp();
        return;
    }
    const double d = bx - (r18 - 1) * i;
    const double zd = g.zLeft(d);
    closeGap(bz - w - s * (r18 - 1), zd, d, riseForRapidZ(zd));  // fixes.md G1, mirrored
    rapidZ(zd);
    feedX(d);
    rapidX(bx + 2 * i + r18 * i + c);
    for (long r19 = 1; zd - s * r19 > rpz && turn(); ++r19) {  // only with tan R6 > 0
        rapidZ(zd - s * r19);
        feedX(g.xLeft(zd - s * r19));
        feed(d, zd);
        rapidX(bx + r18 * i + 2 * i + c + i * r19);
    }
    rapidZ(rpz);
    feedX(rpx);
    feed(d, zd);
}

// PODPROG_DNO_ZL: the bottom reached going left to right. Plunges to the bottom up to T, the
// right-flank clean-up from T, then back leftwards over the staircase from half a step right of
// the last plunge (F3: never right of Tz - R9), S, the left-flank clean-up up to Rp.
void Sweeps::dnoZl()
{
    m_out.calls.push_back("DNO_ZL");
    auto retract = [&](long n) { return retractZl(static_cast<double>(n)); };
    long r60 = 0;
    for (; rpz + s * r18 + s * r60 + w < g.t.x && turn(); ++r60) {  // N30
        rapidZ(rpz + s * (r18 + r60));
        feedX(xb);
        rapidX(retract(r18 + r60));
    }
    rapidZ(g.t.x - w);  // N40, N50: right corner at T
    feedX(xb);
    rapidX(retract(r18 + r60));
    const double top = rpx + (firstPass ? g.h1 : 0) + r28 * i;
    const double zTop = g.zRight(top);
    for (long r19 = 1; g.t.x + s * r19 < zTop && turn(); ++r19) {  // N90
        riseForRapidZ(g.t.x - w + s * r19);                        // G5
        rapidZ(g.t.x - w + s * r19);
        feedX(g.xRight(g.t.x + s * r19));
        feed(xb, g.t.x - w);
        rapidX(firstPass ? g.r.y + g.tan2 * (w + s + s * r18 + s * r60 + s * r19) + c
                         : rpx + i * (2 + r18 + r60 + r19) + c);
    }
    riseForRapidZ(zTop - w);  // G5
    rapidZ(zTop - w);         // N100..N120
    feedX(top);
    feed(xb, g.t.x - w);
    rapidX(rpx - (r18 - 1) * i + c);  // N130
    const double m = rpz + (r18 - 1) * s + s / 2;
    const double start = std::min(m, g.t.x - w);                    // F3
    const long k0 = static_cast<long>(std::ceil((m - start) / s));  // fixes.md G4
    long r19 = 0;
    for (; start - s * r19 > g.s.x && turn(); ++r19) {  // N150
        rapidZ(start - s * r19);
        feedX(xb);
        rapidX(xb + 2 * i + (r19 + k0) * i + c);
    }
    rapidZ(g.s.x);  // N160..N180
    feedX(xb);
    rapidX(xb + 2 * i + (r19 + k0) * i + c);
    for (long r61 = 1; g.s.x - s * r61 > rpz && turn(); ++r61) {  // N200, only with tan R6 > 0
        rapidZ(g.s.x - s * r61);
        feedX(g.xLeft(g.s.x - s * r61));
        feed(xb, g.s.x);
        rapidX(xb + 2 * i + (r19 + k0) * i + c + r61 * i);
    }
    rapidZ(rpz);  // N210..N230
    feedX(rpx);
    feed(xb, g.s.x);
    finished = true;
}

// PODPROG_DNO_ZP, the mirror: plunges to the bottom down to S, the left-flank clean-up, then back
// rightwards from half a step left of the last plunge, T, the right-flank clean-up up to B. F2:
// steps 5-6 program the left corner (the printed code gave the right corner's Z, seed §3.5); F3:
// the half-step start never left of Sz.
void Sweeps::dnoZp()
{
    m_out.calls.push_back("DNO_ZP");
    long r60 = 0;
    for (; bz - w - s * r18 - s * r60 > g.s.x && turn(); ++r60) {  // N30
        rapidZ(bz - w - s * r18 - s * r60);
        feedX(xb);
        rapidX(bx + i * (2 + r18 + r60) + c);
    }
    rapidZ(g.s.x);  // N40
    feedX(xb);
    rapidX(bx + i * (2 + r18 + r60) + c);
    for (long r19 = 1; g.s.x - s * r19 > rpz && turn(); ++r19) {  // N60
        rapidZ(g.s.x - s * r19);
        feedX(g.xLeft(g.s.x - s * r19));
        feed(xb, g.s.x);
        rapidX(bx + i * (2 + r18 + r60 + r19) + c);
    }
    rapidZ(rpz);  // N70..N90
    feedX(rpx);
    feed(xb, g.s.x);
    rapidX(bx - (r18 - 1) * i + c);  // N100
    const double m = bz - (r18 - 1) * s - s / 2 - w;
    const double start = std::max(m, g.s.x);                        // F2, F3
    const long k0 = static_cast<long>(std::ceil((start - m) / s));  // fixes.md G4
    long r19 = 0;
    for (; start + s * r19 < g.t.x - w && turn(); ++r19) {  // N120
        rapidZ(start + s * r19);
        feedX(xb);
        rapidX(xb + 2 * i + (r19 + k0) * i + c);
    }
    rapidZ(g.t.x - w);  // N130..N150
    feedX(xb);
    rapidX(xb + 2 * i + (r19 + k0) * i + c);
    for (long r61 = 1; g.t.x + s * r61 < bz && turn(); ++r61) {  // N170, only with tan R5 > 0
        rapidZ(g.t.x + s * r61 - w);
        feedX(g.xRight(g.t.x + s * r61));
        feed(xb, g.t.x - w);
        rapidX(xb + 2 * i + (r19 + k0) * i + c + r61 * i);
    }
    rapidZ(bz - w);  // N180..N200
    feedX(bx);
    feed(xb, g.t.x - w);
    finished = true;
}

// Spec F5: the groove is too narrow at this depth for the staircase. Straight plunges to the
// offset bottom from right (Tz - R9) to left (Sz), no further apart than R9*R10, then both flanks
// cleaned from the bottom up as the bottom phases do it. Every rapid runs at Ux + R30: the
// surface is highest at U over all the insert reaches (the cone rises to the right and the insert
// never passes Uz), so nothing is in the way whatever the passes before left.
void Sweeps::fallback()
{
    m_out.calls.push_back("FALLBACK");
    m_out.fallback = true;
    const double safe = g.u.y + c;
    rapidX(safe);
    const double span = g.t.x - w - g.s.x;
    const long steps = std::max(1L, static_cast<long>(std::ceil(span / s - 1e-9)));
    for (long k = 0; k <= steps && turn(); ++k) {
        rapidZ(g.t.x - w - span * k / steps);
        feedX(xb);
        rapidX(safe);
    }
    for (long r19 = 1; g.t.x + s * r19 < g.u.x && turn(); ++r19) {  // only with tan R5 > 0
        rapidZ(g.t.x - w + s * r19);
        feedX(g.xRight(g.t.x + s * r19));
        feed(xb, g.t.x - w);
        rapidX(safe);
    }
    rapidZ(g.u.x - w);
    feedX(g.u.y);
    feed(xb, g.t.x - w);
    rapidX(safe);
    for (long r61 = 1; g.s.x - s * r61 > g.r.x && turn(); ++r61) {  // only with tan R6 > 0
        rapidZ(g.s.x - s * r61);
        feedX(g.xLeft(g.s.x - s * r61));
        feed(xb, g.s.x);
        rapidX(safe);
    }
    rapidZ(g.r.x);
    feedX(g.r.y);
    feed(xb, g.s.x);
    finished = true;
}

}  // namespace

base::Result<GrooveMoves> grooveMoves(const GrooveSetup& setup, const std::string& what,
                                      const std::function<bool(double)>& keepGoing)
{
    Sweeps sweeps(setup, what);
    if (base::Status status = sweeps.run(keepGoing); !status)
        return status.error();
    return sweeps.take();
}

}  // namespace camwb::ops::turning
