#include "geom/detail/RawOffset.h"

#include "geom/CarrierIntersection.h"
#include "geom/detail/LoopQueries.h"
#include "geom/detail/OffsetCore.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace camwb::geom::detail {

namespace {

constexpr double kTangentTol = 1e-9;  // rad: smaller turns are tangent joints
// Offset ends closer than this (mm, Clipper's unit) are joined directly, as ClipperOffset does.
constexpr double kJoinGap = 1e-6;
constexpr double kMinPiece = 1e-9;        // mm: shorter pieces are left out (the loop stays continuous)
constexpr double kBypassTangency = 1e-6;  // rad: joints this close to tangent count as fillets

// A loop's elements, each arc that collapses replaced by its chords. Such an arc turns towards
// the offset side with a radius up to the distance: it has no offset of its own (every point of
// it lies within the distance of the arc). Clipper offsets the polygon of such an arc into a fan
// of detours whose winding removes that area; the chords are that polygon (they lie on the offset
// side of the arc, so nothing comes closer to it). `arcOf[i]`: the collapsed arc (in `arcs`)
// element i is a chord of, or -1.
struct SourceLoop {
    std::vector<Segment> segs;
    std::vector<int> arcOf;
    std::vector<Segment> arcs;
};

SourceLoop sourceLoop(const std::vector<Segment>& segments, bool toLeft, double d, double chordTolerance)
{
    std::vector<Segment> segs = withoutDegenerate(segments);
    auto collapses = [&](const Segment& s) { return s.isArc() && s.ccw == toLeft && radiusOf(s) <= d + kMinPiece; };
    // Start at an element that stays, so that no run of chords wraps round the loop's start.
    const auto keeps = std::find_if_not(segs.begin(), segs.end(), collapses);
    if (keeps != segs.end())
        std::rotate(segs.begin(), keeps, segs.end());
    SourceLoop out;
    out.segs.reserve(segs.size());
    for (const Segment& s : segs) {
        if (!collapses(s)) {
            out.segs.push_back(s);
            out.arcOf.push_back(-1);
            continue;
        }
        const double r = radiusOf(s);
        const double sweep = s.sweep();
        const int chords = std::max(2, chordCount(r, std::abs(sweep), chordTolerance));
        const Vec2 a = s.start - s.center;
        const double a0 = std::atan2(a.y, a.x);
        Vec2 from = s.start;
        for (int i = 1; i <= chords; ++i) {
            const double angle = a0 + sweep * i / chords;
            const Vec2 to = i == chords ? s.end : s.center + Vec2{std::cos(angle), std::sin(angle)} * r;
            if (fastDistance(from, to) <= kMinPiece)
                continue;  // a chord of a vanishing arc: the next one starts where this began
            out.segs.push_back(Segment::line(from, to));
            out.arcOf.push_back(static_cast<int>(out.arcs.size()));
            from = to;
        }
        out.arcs.push_back(s);
    }
    return out;
}

// One element moved sideways (arcs keep their centre: radius +- d, never through zero here).
RawPiece moveElement(const Segment& s, bool toLeft, double d)
{
    RawPiece out;
    if (!s.isArc()) {
        const Vec2 t = (s.end - s.start) * (1 / fastDistance(s.start, s.end));
        const Vec2 n = toLeft ? t.leftNormal() : t.rightNormal();
        out.segment = Segment::line(s.start + n * d, s.end + n * d);
        return out;
    }
    const double r = radiusOf(s);
    const double moved = s.ccw != toLeft ? r + d : r - d;  // the centre on the other side: grows
    const double k = moved / r;
    out.segment = Segment::arc(s.center + (s.start - s.center) * k, s.center + (s.end - s.center) * k, s.center, s.ccw);
    out.sweep = s.sweep();
    out.radius = moved;
    return out;
}

double pieceLength(const RawPiece& p)
{
    return p.segment.isArc() ? p.radius * std::abs(p.sweep) : fastDistance(p.segment.start, p.segment.end);
}

// Appends one loop's pieces, each starting where the previous one ended.
class LoopWriter {
public:
    LoopWriter(RawLoops& out, Vec2 start) : m_out(out), m_first(out.pieces.size()), m_at(start), m_start(start) {}

    Vec2 at() const { return m_at; }

    void moved(const RawPiece& piece)
    {
        RawPiece p = piece;
        p.segment.start = m_at;
        add(p);
    }
    void line(Vec2 to)
    {
        RawPiece p;
        p.segment = Segment::line(m_at, to);
        add(p);
    }
    void arc(Vec2 to, Vec2 centre, double radius, double sweep)
    {
        RawPiece p;
        p.segment = Segment::arc(m_at, to, centre, sweep > 0);
        p.sweep = sweep;
        p.radius = radius;
        add(p);
    }
    // Ends the loop exactly where it began; false when it holds no piece.
    bool close()
    {
        if (m_out.pieces.size() == m_first)
            return false;
        m_out.pieces.back().segment.end = m_start;
        return true;
    }

private:
    void add(const RawPiece& p)
    {
        if (pieceLength(p) < kMinPiece)
            return;
        m_out.pieces.push_back(p);
        m_at = p.segment.end;
    }

    RawLoops& m_out;
    std::size_t m_first;
    Vec2 m_at, m_start;
};

// A moved element and the part of it in use after trimming at concave joints: parameters `from`
// and `to` (lines: fraction of the length, arcs: radians along the sweep), ends `start` and `end`.
struct Element {
    RawPiece moved;
    double from = 0, to = 0;
    Vec2 start, end;
};

Element elementOf(const RawPiece& moved)
{
    const bool arc = moved.segment.isArc();
    return {moved, 0, arc ? std::abs(moved.sweep) : 1.0, moved.segment.start, moved.segment.end};
}

double parameterOf(const Element& e, Vec2 q)
{
    const Segment& s = e.moved.segment;
    if (!s.isArc()) {
        const Vec2 d = s.end - s.start;
        return (q - s.start).dot(d) / d.dot(d);
    }
    const double total = std::abs(e.moved.sweep);
    const double angle = angleAlongArc(s, q);  // [0, 2 pi): just before the start reads as negative
    return angle > total && angle > 0.5 * (total + 2 * std::numbers::pi) ? angle - 2 * std::numbers::pi : angle;
}

// mm per unit of parameter.
double scaleOf(const Element& e)
{
    return e.moved.segment.isArc() ? e.moved.radius : fastDistance(e.moved.segment.start, e.moved.segment.end);
}

RawPiece pieceOf(const Element& e)
{
    RawPiece p = e.moved;
    const Segment& s = e.moved.segment;
    if (s.isArc()) {
        p.segment = Segment::arc(e.start, e.end, s.center, s.ccw);
        p.sweep = (s.ccw ? 1.0 : -1.0) * (e.to - e.from);
    } else {
        p.segment = Segment::line(e.start, e.end);
    }
    return p;
}

enum class Joint { Direct, Round, Detour, Trimmed };

// Cuts a's end and b's start at x when x lies inside both and leaves each a length.
bool cutAt(Element& a, Element& b, const std::optional<Vec2>& x)
{
    if (!x)
        return false;
    const double ta = parameterOf(a, *x), tb = parameterOf(b, *x);
    const double sa = scaleOf(a), sb = scaleOf(b);
    if ((ta - a.from) * sa < kMinPiece || (ta - a.to) * sa > kMinPiece || (b.from - tb) * sb > kMinPiece ||
        (b.to - tb) * sb < kMinPiece)
        return false;
    a.to = ta;
    a.end = *x;
    b.from = tb;
    b.start = *x;
    return true;
}

std::optional<Vec2> meeting(const Element& a, const Element& b)
{
    return intersectCarriers(a.moved.segment, b.moved.segment, (a.end + b.start) * 0.5);
}

// At a concave joint the two offsets overlap: where their carriers meet inside both (leaving each
// a length), both are cut there, as the union would; otherwise the joint stays a detour.
bool trim(Element& a, Element& b) { return cutAt(a, b, meeting(a, b)); }

bool tangent(Vec2 t1, Vec2 t2) { return t1.dot(t2) > 0 && std::abs(t1.cross(t2)) < kBypassTangency; }

// The offsets of the elements on either side of a collapsed arc, cut where they meet and the arc's
// chords left out. Only where the arc runs on tangentially from both (a fillet): then every point
// of either offset up to the meeting point keeps the distance from the arc once that point does.
bool bypass(Element& a, Element& b, const Segment& before, const Segment& arc, const Segment& after, double d)
{
    if (!tangent(before.endTangent(), arc.startTangent()) || !tangent(arc.endTangent(), after.startTangent()))
        return false;
    const std::optional<Vec2> x = meeting(a, b);
    return x && distanceToSegment(*x, arc) >= d - kMinPiece && cutAt(a, b, x);
}

// How the offset of one element continues into the next round the source vertex between them: on
// directly (tangent), by an arc where the offsets part (convex on the offset side), cut where they
// overlap, else a detour through the vertex (the union removes the loop this makes).
Joint joint(Element& a, Element& b, const Segment& before, const Segment& after, bool toLeft)
{
    if (fastDistance(a.end, b.start) < kJoinGap)
        return Joint::Direct;
    const Vec2 t1 = before.endTangent(), t2 = after.startTangent();
    const double turn = std::atan2(t1.cross(t2), t1.dot(t2));
    if (std::abs(turn) >= kTangentTol && (toLeft ? -turn : turn) > 0)
        return Joint::Round;
    return trim(a, b) ? Joint::Trimmed : Joint::Detour;
}

void addLoop(const Profile& loop, bool toLeft, double d, double chordTolerance, RawLoops& out)
{
    const SourceLoop source = sourceLoop(loop.segments, toLeft, d, chordTolerance);
    const std::vector<Segment>& segs = source.segs;
    if (segs.empty())
        return;
    const std::size_t n = segs.size();
    std::vector<Element> elements;
    elements.reserve(n);
    for (const Segment& s : segs)
        elements.push_back(elementOf(moveElement(s, toLeft, d)));
    std::vector<Joint> joints(n, Joint::Direct);
    std::vector<bool> skipped(n, false);
    for (std::size_t i = 0; i < n;) {
        const std::size_t j = (i + 1) % n;
        if (source.arcOf[i] < 0 && source.arcOf[j] >= 0) {
            std::size_t last = j;  // the collapsed arc's chords are j..last (never past the loop's end)
            while (last + 1 < n && source.arcOf[last + 1] == source.arcOf[j])
                ++last;
            const std::size_t k = (last + 1) % n;
            if (source.arcOf[k] < 0 && k != i &&
                bypass(elements[i], elements[k], segs[i], source.arcs[static_cast<std::size_t>(source.arcOf[j])],
                       segs[k], d)) {
                joints[i] = Joint::Trimmed;
                for (std::size_t c = j; c <= last; ++c)
                    skipped[c] = true;
                i = last + 1;
                continue;
            }
        }
        joints[i] = joint(elements[i], elements[j], segs[i], segs[j], toLeft);
        ++i;
    }

    const Vec2 start = elements.front().start;
    out.loopBegin.push_back(out.pieces.size());
    LoopWriter writer(out, start);
    for (std::size_t i = 0; i < n; ++i) {
        if (skipped[i])
            continue;
        writer.moved(pieceOf(elements[i]));
        const std::size_t j = (i + 1) % n;
        const Vec2 to = j == 0 ? start : elements[j].start;
        if (joints[i] == Joint::Round) {
            const Vec2 t1 = segs[i].endTangent(), t2 = segs[j].startTangent();
            writer.arc(to, segs[i].end, d, std::atan2(t1.cross(t2), t1.dot(t2)));
        } else if (joints[i] == Joint::Detour) {
            writer.line(segs[i].end);
            writer.line(to);
        }
    }
    if (!writer.close())
        out.loopBegin.pop_back();
}

}  // namespace

std::size_t RawLoops::loopOf(std::size_t piece) const
{
    std::size_t lo = 0, hi = loopBegin.size() - 1;  // loopBegin[lo] <= piece < loopBegin[hi]
    while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (loopBegin[mid] <= piece ? lo : hi) = mid;
    }
    return lo;
}

std::size_t RawLoops::next(std::size_t piece) const
{
    const std::size_t loop = loopOf(piece);
    return piece + 1 < loopBegin[loop + 1] ? piece + 1 : loopBegin[loop];
}

std::size_t RawLoops::prev(std::size_t piece) const
{
    const std::size_t loop = loopOf(piece);
    return piece > loopBegin[loop] ? piece - 1 : loopBegin[loop + 1] - 1;
}

RawLoops rawOffset(const std::vector<Region>& regions, double distance, bool inward, double chordTolerance)
{
    // Normalised loops have the region on their left: outer loops ccw, holes cw.
    RawLoops out;
    for (const Region& region : regions) {
        addLoop(region.outer, inward, distance, chordTolerance, out);
        for (const Profile& hole : region.holes)
            addLoop(hole, inward, distance, chordTolerance, out);
    }
    out.loopBegin.push_back(out.pieces.size());
    return out;
}

Vec2 piecePoint(const RawPiece& piece, double t)
{
    const Segment& s = piece.segment;
    if (!s.isArc())
        return s.start + (s.end - s.start) * t;
    const Vec2 a = s.start - s.center;
    const double angle = std::atan2(a.y, a.x) + piece.sweep * t;
    return s.center + Vec2{std::cos(angle), std::sin(angle)} * piece.radius;
}

}  // namespace camwb::geom::detail
