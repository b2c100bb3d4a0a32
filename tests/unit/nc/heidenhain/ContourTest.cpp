// Contour elements of the Klartext interpreter: L, C, CR, CT, CP (helix), LP, RND, CHF.
#include "TestSupport.h"

#include <cmath>

namespace camwb::nc::heidenhain::test {
namespace {

using namespace camwb::toolpath;

TEST(HeidenhainContour, Smoke)
{
    const Traced r = run("0 BEGIN PGM T MM\n"
                         "1 TOOL CALL 1 Z S3000\n"
                         "2 L X+10 Y+0 Z+5 R0 FMAX M3\n"
                         "3 L Z-1 F200\n"
                         "4 CC X+0 Y+0\n"
                         "5 C X+0 Y+10 DR+\n"
                         "6 L M30\n"
                         "7 END PGM T MM\n");
    std::printf("%s", r.trace().c_str());
    for (auto& d : r.diagnostics())
        std::printf("%s\n", d.c_str());
    EXPECT_TRUE(r.result.completed);
}

}  // namespace
}  // namespace camwb::nc::heidenhain::test
