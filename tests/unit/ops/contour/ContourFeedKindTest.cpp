// Which feed each contour move says it uses: straight down at the plunge feed (Plunge), down along
// the helix or ramp at the ramp feed (Entry), leaving along the lead-out and departure (Exit), and
// everything else at depth, lead-in and approach included, at the cutting feed (Cutting).
#include "../support/FeedKinds.h"
#include "ContourTestUtil.h"

using namespace camwb;
using namespace camwb::ops::test;
using toolpath::FeedKind;

namespace {

toolpath::Toolpath compute(const std::vector<Profile>& loops, const ops::ContourParams& p)
{
    auto r = ops::computeContour(loops, p, tool(), 0);
    EXPECT_TRUE(r.ok()) << r.error().message;
    return r.ok() ? r.value().toolpath : toolpath::Toolpath{};
}

// Each feed move's kind against its geometry: straight down is Plunge, down while moving in XY is
// Entry, level or up is one of the kinds at depth.
void expectKindsFollowTheMoves(const toolpath::Toolpath& tp)
{
    for (const Move& m : walk(tp)) {
        if (m.rapid)
            continue;
        const FeedKind kind = feedKindOf(tp.record(m.record));
        const bool down = m.to.z < m.from.z - 1e-9;
        const bool inXY = distance(m.from.xy(), m.to.xy()) > 1e-9 || m.arc;
        if (down && !inXY)
            EXPECT_EQ(kind, FeedKind::Plunge) << "record " << m.record;
        else if (down)
            EXPECT_EQ(kind, FeedKind::Entry) << "record " << m.record;
        else
            EXPECT_TRUE(kind == FeedKind::Cutting || kind == FeedKind::Exit) << "record " << m.record;
    }
}

// The kind of the first feed move after each record of type T (a retract, a compensation change).
template <class Pred> std::vector<FeedKind> kindsAfter(const toolpath::Toolpath& tp, Pred isMark)
{
    std::vector<FeedKind> out;
    bool marked = false;
    for (const toolpath::Record& r : tp.records()) {
        if (isMark(r)) {
            marked = true;
        } else if (marked &&
                   (std::holds_alternative<toolpath::Linear>(r) || std::holds_alternative<toolpath::Arc>(r))) {
            out.push_back(feedKindOf(r));
            marked = false;
        }
    }
    return out;
}

}  // namespace

TEST(ContourFeedKinds, RampsArePlungesAndEntriesLeadOutsAreExits)
{
    auto p = params();
    p.stepDownMm = 2;
    p.leadIn = p.leadOut = ops::LeadKind::Arc;
    p.leadRadiusMm = 6;
    p.entry = ops::EntryKind::Ramp;
    p.rampAngleDeg = 5;
    p.tabCount = 2;
    p.tabWidthMm = 4;
    p.tabHeightMm = 1.5;
    const toolpath::Toolpath tp = compute({geom::test::roundedRectangle(0, 0, 90, 60, 8)}, p);
    expectFeedKindsAgreeWithSections(tp);
    expectKindsFollowTheMoves(tp);
    const std::vector<FeedKind> kinds = feedKinds(tp);
    ASSERT_FALSE(kinds.empty());
    EXPECT_EQ(kinds.front(), FeedKind::Plunge);  // down from the safe height to the top
    EXPECT_GT(std::count(kinds.begin(), kinds.end(), FeedKind::Entry), 0);
    // Two levels, one lead-out quarter arc each, and nothing else leaves.
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), FeedKind::Exit), 2);
    const Move* lastFeed = nullptr;
    const auto moves = walk(tp);  // kept: lastFeed points into it
    for (const Move& m : moves)
        if (!m.rapid)
            lastFeed = &m;
    ASSERT_NE(lastFeed, nullptr);
    EXPECT_TRUE(lastFeed->arc);
    EXPECT_EQ(feedKindOf(tp.record(lastFeed->record)), FeedKind::Exit);
}

TEST(ContourFeedKinds, WithoutALeadOutNothingIsAnExit)
{
    auto p = params();
    p.stepDownMm = 1.5;
    p.leadIn = ops::LeadKind::Line;
    p.leadRadiusMm = 3;
    const toolpath::Toolpath tp = compute({geom::test::rectangle(0, 0, 40, 20)}, p);
    expectFeedKindsAgreeWithSections(tp);
    expectKindsFollowTheMoves(tp);
    const std::vector<FeedKind> kinds = feedKinds(tp);
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), FeedKind::Exit), 0);
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), FeedKind::Entry), 0);   // plunged, not ramped
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), FeedKind::Plunge), 2);  // one per level
}

TEST(ContourFeedKinds, HelixIsTheEntryApproachCutsAndDepartureExits)
{
    auto p = params(ops::ContourSide::Inside);
    p.compensation = ops::CompensationOutput::Control;
    p.leadIn = p.leadOut = ops::LeadKind::Arc;
    p.leadRadiusMm = 8;
    p.entry = ops::EntryKind::Helix;
    p.helixDiameterMm = 6;
    p.helixPitchMm = 1.5;
    const toolpath::Toolpath tp = compute({geom::test::roundedRectangle(0, 0, 80, 50, 12)}, p);
    expectFeedKindsAgreeWithSections(tp);
    expectKindsFollowTheMoves(tp);
    // The helix: two turns down 3 mm at 1.5 mm pitch, in half turns, all Entry arcs.
    int helixArcs = 0;
    for (const Move& m : walk(tp))
        if (m.helix) {
            ++helixArcs;
            EXPECT_EQ(feedKindOf(tp.record(m.record)), FeedKind::Entry) << "record " << m.record;
        }
    EXPECT_EQ(helixArcs, 4);
    const auto isComp = [](toolpath::CutterCompSide side) {
        return [side](const toolpath::Record& r) {
            const auto* c = std::get_if<toolpath::CutterComp>(&r);
            return c && c->side == side;
        };
    };
    EXPECT_EQ(kindsAfter(tp, isComp(toolpath::CutterCompSide::Left)), std::vector<FeedKind>{FeedKind::Cutting});
    EXPECT_EQ(kindsAfter(tp, isComp(toolpath::CutterCompSide::Off)), std::vector<FeedKind>{FeedKind::Exit});
}
