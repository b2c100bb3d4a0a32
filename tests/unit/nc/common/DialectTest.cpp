// The dialect guess (extension first, then words only one dialect uses) and dialect names.
#include "nc/Dialect.h"

#include <gtest/gtest.h>

namespace camwb::nc {
namespace {

TEST(Dialect, NamesRoundTrip)
{
    for (Dialect d : {Dialect::Sinumerik, Dialect::Heidenhain, Dialect::Iso})
        EXPECT_EQ(dialectFromName(dialectName(d)), d);
    EXPECT_EQ(dialectFromName("SIEMENS"), Dialect::Sinumerik);
    EXPECT_EQ(dialectFromName("LinuxCNC"), Dialect::Iso);
    EXPECT_FALSE(dialectFromName("fanuc-macro-b"));
}

TEST(Dialect, ExtensionDecidesFirst)
{
    EXPECT_EQ(guessDialect("G0 X1 (move)\n", "part.MPF"), Dialect::Sinumerik);
    EXPECT_EQ(guessDialect("G0 X1\n", "sub.spf"), Dialect::Sinumerik);
    EXPECT_EQ(guessDialect("G0 X1\n", "/tmp/PART.H"), Dialect::Heidenhain);
}

TEST(Dialect, ContentDecidesForNeutralNames)
{
    EXPECT_EQ(guessDialect("0 BEGIN PGM P1 MM\n1 L X+0 FMAX\n", "p1.nc"), Dialect::Heidenhain);
    EXPECT_EQ(guessDialect("N10 G17 G40\nN20 MCALL CYCLE81(10,0,2,-5)\n", "p.nc"), Dialect::Sinumerik);
    EXPECT_EQ(guessDialect("R1=5\nG1 X=R1\n", "p.txt"), Dialect::Sinumerik);
    EXPECT_EQ(guessDialect("N10 G0 X1 ; first\n", "p.nc"), Dialect::Sinumerik);
    EXPECT_EQ(guessDialect("(part)\nG21 G90\nG0 X1 Y2 ; comment\n", "p.nc"), Dialect::Iso);
    EXPECT_EQ(guessDialect("%\nG81 R2 Z-5\n%\n", "p.ngc"), Dialect::Iso);
    EXPECT_EQ(guessDialect("", ""), Dialect::Iso);
    // An R word that is an arc radius, not an assignment, says nothing.
    EXPECT_EQ(guessDialect("G2 X10 Y0 R5\n", "p.nc"), Dialect::Iso);
}

}  // namespace
}  // namespace camwb::nc
