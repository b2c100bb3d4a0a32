// Motion: rapids and feeds, absolute and incremental, units, DIAMON, arcs in all planes.
#include "TestSupport.h"

namespace camwb::nc::sinumerik::test {
namespace {

TEST(SinumerikMotion, Smoke)
{
    const NcRun r = run(
        "N10 G17 G90 G54\nN20 T1 M6\nN30 M3 S1000\nN40 G0 X10 Y20 Z5\nN50 G1 Z-1 F100\nN60 G2 X20 Y10 I10 J0\nM30\n");
    std::printf("%s---\n%s", r.trace().c_str(), r.diagnostics().c_str());
    EXPECT_EQ(r.errors(), 0);
}

}  // namespace
}  // namespace camwb::nc::sinumerik::test
