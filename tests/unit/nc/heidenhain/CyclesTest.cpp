// Cycles of the Klartext interpreter: 200/203/205 as Cycle records (iTNC 530 indented and
// TNC 640 `~` parameter lines), CYCL CALL, CYCL CALL POS, M99, M89, 208 expanded into a helix,
// 9 dwell, 247 datum setting, and the five-axis functions that are recognised with a warning.
#include "TestSupport.h"

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

TEST(HeidenhainCycles, Cycle200OfTheThesisWithCyclCallAndM99)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 TOOL CALL 2 Z S2000\n"
                         "7 CYCL DEF 200 VRT\xc3\x81N\xc3\x8d\n"
                         "  Q200=2 ;BEZPE\xc4\x8cN\xc3\x81 VZD\xc3\x81LENOST\n"
                         "  Q201=3 ;HLOUBKA\n"
                         "  Q206=150 ;POSUV\n"
                         "  Q202=5 ;HLOUBKA P\xc5\x98\xc3\x8dSUUVU\n"
                         "  Q210=0 ;PRODLEVA NAHOŘE\n"
                         "  Q203=+0 ;SOUŘADNICE POVRCHU\n"
                         "  Q204=50 ;2. BEZPEČNÁ VZDÁLENOST\n"
                         "  Q211=0,25 ;ČASOVÁ PRODLEVA DOLE\n"
                         "8 L X+20 Y+30 FMAX M3\n"
                         "9 CYCL CALL\n"
                         "10 L X+50 FMAX M99\n"
                         "11 END PGM T MM\n");
    EXPECT_EQ(r.count(Severity::Error), 0u) << r.diagnostics()[0];
    EXPECT_TRUE(r.has(Severity::Warning, 11, "decimal comma"));
    EXPECT_TRUE(r.has(Severity::Warning, 13, "depth is positive"));
    EXPECT_EQ(r.count(Severity::Warning), 2u);
    const auto cycles = r.all<Cycle>();
    ASSERT_EQ(cycles.size(), 2u);
    for (const Cycle& c : cycles) {
        EXPECT_EQ(c.kind, CycleKind::DrillDwell);  // plunging depth 5 >= depth 3: one plunge
        EXPECT_EQ(c.topZ, 0);
        EXPECT_EQ(c.bottomZ, -3);
        EXPECT_EQ(c.retractZ, 2);
        EXPECT_EQ(c.clearanceZ, 50);
        EXPECT_EQ(c.feedMmPerMin, 150);
        EXPECT_EQ(c.dwellSeconds, 0.25);
        EXPECT_TRUE(c.returnToClearance);
        ASSERT_EQ(c.holes.size(), 1u);
    }
    expectNear(cycles[0].holes[0], {20, 30, 0});
    expectNear(cycles[1].holes[0], {50, 30, 0});
    EXPECT_EQ(r.lines<Cycle>(), (std::vector<int>{13, 14}));
    // After the first hole the tool is at the 2nd set-up clearance: the rapid to X+50 stays there.
    expectNear(r.all<Rapid>()[1].to, {50, 30, 50});
}

TEST(HeidenhainCycles, Cycle203WithTildeContinuationsChipBreaks)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 TOOL CALL 1 Z S1000\n"
                         "2 CYCL DEF 203 UNIVERSAL DRILLING ~\n"
                         "    Q200=+2 ;SET-UP CLEARANCE ~\n"
                         "    Q201=-20 ;DEPTH ~\n"
                         "    Q206=+150 ;FEED RATE FOR PLNGNG ~\n"
                         "    Q202=+5 ;PLUNGING DEPTH ~\n"
                         "    Q210=+0 ;DWELL TIME AT TOP ~\n"
                         "    Q203=-1 ;SURFACE COORDINATE ~\n"
                         "    Q204=+50 ;2ND SET-UP CLEARANCE ~\n"
                         "    Q212=+0 ;DECREMENT ~\n"
                         "    Q213=+3 ;BREAKS ~\n"
                         "    Q205=+0 ;MIN. PLUNGING DEPTH ~\n"
                         "    Q211=+0.5 ;DWELL TIME AT DEPTH ~\n"
                         "    Q208=+500 ;RETRACTION FEED RATE ~\n"
                         "    Q256=+0.2 ;DIST FOR CHIP BRKNG\n"
                         "3 L X+10 Y+10 R0 FMAX M3\n"
                         "4 CYCL CALL\n"
                         "5 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto cycles = r.all<Cycle>();
    ASSERT_EQ(cycles.size(), 1u);
    EXPECT_EQ(cycles[0].kind, CycleKind::ChipBreak);
    EXPECT_EQ(cycles[0].peckMm, 5);
    EXPECT_EQ(cycles[0].topZ, -1);
    EXPECT_EQ(cycles[0].bottomZ, -21);
    EXPECT_EQ(cycles[0].retractZ, 1);
    EXPECT_EQ(cycles[0].clearanceZ, 49);
    EXPECT_EQ(cycles[0].dwellSeconds, 0.5);
    // The cycle parameters are global Q parameters too.
    const Traced q = run("0 BEGIN PGM T MM\n1 CYCL DEF 200 DRILLING Q200=2 Q201=-7 Q206=100 Q202=2 Q203=0 "
                         "Q204=10 Q211=0\n2 L X+Q201 FMAX\n3 END PGM T MM\n");
    EXPECT_EQ(q.all<Rapid>()[0].to.x, -7);
}

TEST(HeidenhainCycles, Cycle205ModalCallWithM89AndCallPos)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 CYCL DEF 205 UNIVERSAL PECKING Q200=2 Q201=-30 Q206=100 Q202=10 Q203=0 Q204=20\n"
                         "2 L X+0 Y+0 Z+50 FMAX M89\n"
                         "3 L X+10 FMAX\n"
                         "4 L X+20 FMAX M99\n"
                         "5 L X+30 FMAX\n"
                         "6 CYCL CALL POS X+40 Y+5 Z+20\n"
                         "7 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto cycles = r.all<Cycle>();
    ASSERT_EQ(cycles.size(), 4u);
    EXPECT_EQ(cycles[0].kind, CycleKind::Peck);
    EXPECT_EQ(cycles[0].peckMm, 10);
    EXPECT_EQ(r.lines<Cycle>(), (std::vector<int>{3, 4, 5, 7}));
    expectNear(cycles[3].holes[0], {40, 5, 0});
}

TEST(HeidenhainCycles, Cycle208BoreMillingIsAHelix)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 TOOL DEF 5 L+0 R+4\n"
                         "2 TOOL CALL 5 Z S2000\n"
                         "3 CYCL DEF 208 BORE MILLING Q200=2 Q201=-10 Q206=150 Q334=4 Q203=+0 Q204=20 Q335=20 "
                         "Q342=0 Q351=+1\n"
                         "4 L X+0 Y+0 Z+30 FMAX M3\n"
                         "5 CYCL CALL\n"
                         "6 END PGM T MM\n");
    EXPECT_TRUE(r.result.diagnostics.empty()) << r.diagnostics()[0];
    const auto arcs = r.all<Arc>();
    ASSERT_EQ(arcs.size(), 2u);
    // 12 mm from Z+2 to Z-10 at 4 mm per lap: three laps on radius 10 - 4.
    expectNear(arcs[0].to, {6, 0, -10});
    expectNear(arcs[0].center, {0, 0, 2});
    EXPECT_EQ(arcs[0].turns, 2);
    EXPECT_FALSE(arcs[0].clockwise);  // climb milling with M3
    expectNear(arcs[1].to, {6, 0, -10});
    EXPECT_EQ(arcs[1].turns, 0);
    const auto rapids = r.all<Rapid>();
    expectNear(rapids.back().to, {0, 0, 20});
    EXPECT_EQ(r.all<ToolChange>()[0].tool.diameterMm, 8);
}

TEST(HeidenhainCycles, CallWithoutDefinitionIsAnError)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 L X+1 FMAX M99\n2 CYCL CALL\n3 END PGM T MM\n");
    EXPECT_TRUE(r.has(Severity::Error, 2, "without a cycle definition"));
    EXPECT_TRUE(r.has(Severity::Error, 3, "without a cycle definition"));
}

TEST(HeidenhainCycles, DwellAndUntracedCycles)
{
    const Traced r = run("0 BEGIN PGM T MM\n1 CYCL DEF 9.0 DWELL TIME\n2 CYCL DEF 9.1 DWELL 1.5\n"
                         "3 CYCL DEF 251 RECTANGULAR POCKET Q215=0 Q218=80\n4 CYCL CALL\n5 END PGM T MM\n");
    ASSERT_EQ(r.all<Dwell>().size(), 1u);
    EXPECT_EQ(r.all<Dwell>()[0].seconds, 1.5);
    EXPECT_TRUE(r.has(Severity::Warning, 4, "cycle 251 is not traced"));
    EXPECT_EQ(r.count(Severity::Error), 0u);
}

TEST(HeidenhainCycles, FiveAxisFunctionsWithoutAMachine)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 PLANE SPATIAL SPA+0 SPB+45 SPC+0 TURN FMAX SEQ- TABLE ROT\n"
                         "2 CYCL DEF 19.0 WORKING PLANE\n"
                         "3 CYCL DEF 19.1 A+0 B+30 C+0\n"
                         "4 L X+1 Y+2 Z+3 B+30 C+90 FMAX M128\n"
                         "5 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\n"
                         "6 L X+2 FMAX M129\n"
                         "7 FUNCTION RESET TCPM\n"
                         "8 PLANE RESET STAY\n"
                         "9 CYCL DEF 19.1 A+0 B+0 C+0\n"
                         "10 END PGM T MM\n");
    // Without a machine PLANE SPATIAL is a plane all the same (its angles are the plane's); CYCL DEF
    // 19's are the machine's axes, so its plane is unknown (an error), its reset is not.
    EXPECT_TRUE(r.has(Severity::Error, 4, "needs a five-axis machine"));
    EXPECT_EQ(r.count(Severity::Error), 1u);
    EXPECT_TRUE(r.has(Severity::Warning, 5, "M128"));
    EXPECT_TRUE(r.has(Severity::Warning, 5, "rotary"));
    EXPECT_TRUE(r.has(Severity::Warning, 6, "FUNCTION TCPM"));
    EXPECT_EQ(r.count(Severity::Warning), 3u);
    const auto planes = r.all<WorkingPlane>();
    ASSERT_EQ(planes.size(), 3u);  // PLANE SPATIAL, PLANE RESET, CYCL DEF 19 with 0
    expectNear(planes[0].zAxis, {std::sqrt(0.5), 0, std::sqrt(0.5)});
    EXPECT_FALSE(planes[1].tilted());
    EXPECT_FALSE(planes[2].tilted());
    ASSERT_EQ(r.all<Rapid>().size(), 2u);
    expectNear(r.all<Rapid>()[0].to, {1, 2, 3});  // in the plane's frame
}

TEST(HeidenhainCycles, DatumSettingSelectsAPresetAndKeepsTheCycle)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 TOOL CALL 2 Z S2000\n"
                         "2 CYCL DEF 200 DRILLING ~\n"
                         "  Q200=2 ;SET-UP CLEARANCE ~\n"
                         "  Q201=-3 ;DEPTH ~\n"
                         "  Q206=150 ;FEED RATE FOR PLNGNG ~\n"
                         "  Q202=5 ;PLUNGING DEPTH ~\n"
                         "  Q203=+0 ;SURFACE COORDINATE ~\n"
                         "  Q204=50 ;2ND SET-UP CLEARANCE\n"
                         "3 CYCL DEF 247 DATUM SETTING\n"
                         "  Q339=+2 ;DATUM NUMBER\n"
                         "4 L X+20 Y+30 Z+50 FMAX M3 M99\n"
                         "5 CYCL DEF 247 DATUM SETTING\n"
                         "  Q339=-1 ;DATUM NUMBER\n"
                         "6 END PGM T MM\n");
    const auto offsets = r.all<WorkOffset>();
    ASSERT_EQ(offsets.size(), 1u);
    EXPECT_EQ(offsets[0].index, 2);
    EXPECT_EQ(r.lines<WorkOffset>(), (std::vector<int>{10}));
    ASSERT_EQ(r.all<Cycle>().size(), 1u);  // 200 is still the cycle M99 calls
    EXPECT_EQ(r.all<Cycle>()[0].bottomZ, -3);
    EXPECT_TRUE(r.has(Severity::Error, 13, "datum number Q339 -1.0000 is not a preset table line"))
        << r.diagnostics()[0];
    EXPECT_EQ(r.result.diagnostics.size(), 1u);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
