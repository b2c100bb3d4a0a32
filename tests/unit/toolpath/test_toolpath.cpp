#include "toolpath/KnownPosition.h"
#include "toolpath/MachineSink.h"
#include "toolpath/RecordNames.h"
#include "toolpath/Toolpath.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace camwb::toolpath;

namespace {

// Records which sink method was called, in order, with the source of each record.
class RecordingSink : public MachineSink {
public:
    std::vector<std::string> calls;
    std::vector<SourceRef> sources;

    void begin() override { calls.push_back("begin"); }
    void end() override { calls.push_back("end"); }
    void setSource(const SourceRef& s) override { sources.push_back(s); }
    void rapid(const Rapid&) override { calls.push_back("rapid"); }
    void linear(const Linear&) override { calls.push_back("linear"); }
    void arc(const Arc&) override { calls.push_back("arc"); }
    void toolChange(const ToolChange&) override { calls.push_back("toolChange"); }
    void spindle(const Spindle&) override { calls.push_back("spindle"); }
    void coolant(const Coolant&) override { calls.push_back("coolant"); }
    void feedMode(const FeedModeChange&) override { calls.push_back("feedMode"); }
    void workOffset(const WorkOffset&) override { calls.push_back("workOffset"); }
    void dwell(const Dwell&) override { calls.push_back("dwell"); }
    void cycle(const Cycle&) override { calls.push_back("cycle"); }
    void toolAxisMove(const ToolAxisMove&) override { calls.push_back("toolAxisMove"); }
    void cutterComp(const CutterComp&) override { calls.push_back("cutterComp"); }
    void comment(const Comment&) override { calls.push_back("comment"); }
    void sectionBegin(const SectionBegin&) override { calls.push_back("sectionBegin"); }
    void sectionEnd(const SectionEnd&) override { calls.push_back("sectionEnd"); }
    void programStop(const ProgramStop&) override { calls.push_back("programStop"); }
    void passThrough(const PassThrough&) override { calls.push_back("passThrough"); }
    void workingPlane(const WorkingPlane&) override { calls.push_back("workingPlane"); }
    void unknownAxes(const UnknownAxes&) override { calls.push_back("unknownAxes"); }
};

}  // namespace

TEST(Toolpath, AddKeepsRecordsAndSources)
{
    Toolpath tp;
    EXPECT_TRUE(tp.empty());
    tp.add(Rapid{{1, 2, 3}}, {4, 0});
    tp.add(Linear{{1, 2, 0}, 100});
    ASSERT_EQ(tp.size(), 2u);
    EXPECT_FALSE(tp.empty());
    ASSERT_TRUE(std::holds_alternative<Rapid>(tp.record(0)));
    EXPECT_EQ(std::get<Rapid>(tp.record(0)).to, (Vec3{1, 2, 3}));
    EXPECT_EQ(std::get<Linear>(tp.record(1)).feedMmPerMin, 100);
    EXPECT_EQ(tp.source(0).operationIndex, 4);
    EXPECT_EQ(tp.source(0).recordIndex, 0);
    EXPECT_EQ(tp.source(1).operationIndex, -1);  // default: unknown
    EXPECT_EQ(tp.source(1).recordIndex, -1);
    EXPECT_EQ(tp.records().size(), 2u);
}

TEST(Toolpath, AppendConcatenatesRecordsAndSources)
{
    Toolpath a, b;
    a.add(Comment{"a"}, {0, 0});
    b.add(Comment{"b0"}, {1, 0});
    b.add(Comment{"b1"}, {1, 1});
    a.append(b);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(std::get<Comment>(a.record(2)).text, "b1");
    EXPECT_EQ(a.source(1).operationIndex, 1);
    EXPECT_EQ(a.source(2).recordIndex, 1);
    EXPECT_EQ(b.size(), 2u);  // the appended toolpath is untouched
}

TEST(Toolpath, StatisticsSeparateArcsFromHelices)
{
    Toolpath tp;
    tp.add(Rapid{{0, 0, 10}});
    tp.add(Rapid{{10, 0, 10}});
    tp.add(Linear{{10, 0, 0}, 100});
    Arc planar;
    planar.to = {0, 10, 0};
    planar.center = {0, 0, 0};
    tp.add(planar);
    Arc helix = planar;
    helix.to = {0, 10, -2};  // leaves the plane through the centre
    tp.add(helix);
    Arc xzArc;  // an arc in the XZ plane is planar in its own plane
    xzArc.to = {0, 0, 10};
    xzArc.center = {0, 0, 0};
    xzArc.normal = {0, 1, 0};
    tp.add(xzArc);
    tp.add(ToolChange{});
    tp.add(Cycle{});
    tp.add(Cycle{});
    tp.add(Comment{"not counted"});

    const ToolpathStats s = statistics(tp);
    EXPECT_EQ(s.rapids, 2u);
    EXPECT_EQ(s.lines, 1u);
    EXPECT_EQ(s.arcs, 2u);
    EXPECT_EQ(s.helices, 1u);
    EXPECT_EQ(s.cycles, 2u);
    EXPECT_EQ(s.toolChanges, 1u);
}

TEST(Toolpath, PlayDispatchesEveryKindInOrder)
{
    Toolpath tp;
    int i = 0;
    auto add = [&](Record r) { tp.add(std::move(r), {7, i++}); };
    add(SectionBegin{});
    add(ToolChange{});
    add(Spindle{});
    add(Coolant{});
    add(FeedModeChange{});
    add(WorkOffset{});
    add(CutterComp{});
    add(Rapid{});
    add(Linear{});
    add(Arc{});
    add(Dwell{});
    add(Cycle{});
    add(ToolAxisMove{});
    add(Comment{});
    add(ProgramStop{});
    add(PassThrough{});
    add(WorkingPlane{});
    add(UnknownAxes{});
    add(SectionEnd{});

    RecordingSink sink;
    play(tp, sink);
    const std::vector<std::string> expected{
        "begin",      "sectionBegin", "toolChange",  "spindle",      "coolant",     "feedMode",   "workOffset",
        "cutterComp", "rapid",        "linear",      "arc",          "dwell",       "cycle",      "toolAxisMove",
        "comment",    "programStop",  "passThrough", "workingPlane", "unknownAxes", "sectionEnd", "end"};
    EXPECT_EQ(sink.calls, expected);
    ASSERT_EQ(sink.sources.size(), tp.size());
    for (std::size_t k = 0; k < sink.sources.size(); ++k) {
        EXPECT_EQ(sink.sources[k].operationIndex, 7);
        EXPECT_EQ(sink.sources[k].recordIndex, static_cast<int>(k));
    }
}

TEST(Toolpath, PlayOfEmptyToolpathOnlyBeginsAndEnds)
{
    RecordingSink sink;
    play(Toolpath{}, sink);
    EXPECT_EQ(sink.calls, (std::vector<std::string>{"begin", "end"}));
}

TEST(KnownPosition, AMoveSetsOnlyTheAxesItGives)
{
    KnownPosition at;
    EXPECT_FALSE(at.any());
    EXPECT_FALSE(at.point());
    at.moveTo(Rapid{{0, 0, 20}, AxisMask{AxisMask::kZ}});
    EXPECT_TRUE(at.known(2));
    EXPECT_FALSE(at.known(0));
    EXPECT_FALSE(at.point());  // X and Y are still unknown: no point to hand out
    EXPECT_EQ(endOf(at, {6, -20, 0}, AxisMask{AxisMask::kX | AxisMask::kY}), (Vec3{6, -20, 20}));
    EXPECT_FALSE(endOf(at, {6, 0, 0}, AxisMask{AxisMask::kX}));
    at.moveTo(Linear{{6, -20, 99}, 100, AxisMask{AxisMask::kX | AxisMask::kY}});
    ASSERT_TRUE(at.point());
    EXPECT_EQ(*at.point(), (Vec3{6, -20, 20}));
    at.forget();
    EXPECT_TRUE(at.known().none());
    // Records made without a mask give every axis.
    EXPECT_TRUE(Rapid{}.axes.all());
    EXPECT_TRUE((Linear{{1, 2, 3}, 100}.axes.all()));
}

TEST(FeedKind, EveryKindHasANameThatReadsBackAndUnspecifiedHasNone)
{
    EXPECT_STREQ(name(FeedKind::Unspecified), "");
    EXPECT_FALSE(feedKindNamed(""));
    EXPECT_FALSE(feedKindNamed("rapid"));
    EXPECT_FALSE(feedKindNamed("Plunge"));  // names are exact
    const std::vector<std::pair<FeedKind, std::string>> names{{FeedKind::Cutting, "cutting"},
                                                              {FeedKind::Plunge, "plunge"},
                                                              {FeedKind::Entry, "entry"},
                                                              {FeedKind::Exit, "exit"},
                                                              {FeedKind::Finishing, "finishing"}};
    for (const auto& [kind, text] : names) {
        EXPECT_EQ(name(kind), text);
        EXPECT_EQ(feedKindNamed(text), kind) << text;
    }
}

TEST(FeedKind, SectionFeedsAnswerEachKind)
{
    const SectionFeeds feeds{600, 150, 250, 500, 400};
    EXPECT_EQ(feeds.of(FeedKind::Cutting), 600);
    EXPECT_EQ(feeds.of(FeedKind::Plunge), 150);
    EXPECT_EQ(feeds.of(FeedKind::Entry), 250);
    EXPECT_EQ(feeds.of(FeedKind::Exit), 500);
    EXPECT_EQ(feeds.of(FeedKind::Finishing), 400);
    EXPECT_EQ(feeds.of(FeedKind::Unspecified), 0);
}

// The kind sits in padding: a million-move toolpath is no larger for it.
TEST(FeedKind, MovesAreNoLargerForTheirKind)
{
    struct LinearWithoutKind {
        Vec3 to;
        double feed;
        AxisMask axes;
    };
    struct ArcWithoutKind {
        Vec3 to, center, normal;
        bool clockwise;
        int turns;
        double feed;
    };
    EXPECT_EQ(sizeof(Linear), sizeof(LinearWithoutKind));
    EXPECT_EQ(sizeof(Arc), sizeof(ArcWithoutKind));
    const Linear line{{1, 2, 3}, 100, AxisMask{AxisMask::kZ}, FeedKind::Exit};
    EXPECT_EQ(line.feedKind, FeedKind::Exit);
    EXPECT_EQ(line.axes, AxisMask{AxisMask::kZ});
    const Arc arc{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}, true, 2, 300, FeedKind::Entry};
    EXPECT_TRUE(arc.clockwise);
    EXPECT_EQ(arc.turns, 2);
    EXPECT_EQ(arc.feedMmPerMin, 300);
    EXPECT_EQ(arc.feedKind, FeedKind::Entry);
    EXPECT_EQ(Arc{}.feedKind, FeedKind::Unspecified);
}
