// The document's numbers under a locale that writes 1.5 as "1,5", as the GUI runs in the user's
// (Qt sets the C library's locale from LANG): tool libraries read their quantities, and the names
// and descriptions made from numbers keep their point, exactly as in the "C" locale.
#include "document/ModalState.h"
#include "document/ToolLibraryImport.h"

#include "../../support/DecimalCommaLocale.h"

#include <gtest/gtest.h>

#include <charconv>

using namespace camwb;

namespace {

const std::string kData = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/tools";

// A double to the last bit, without the C library (whose "%a" would follow the locale too).
std::string bits(double value)
{
    char text[64];
    return std::string(text, std::to_chars(text, text + sizeof text, value, std::chars_format::hex).ptr);
}

// Each tool as one line: number, name, kind, diameter and the lengths to the last bit.
std::string toolsOf(const std::string& library)
{
    auto imported = document::importToolLibrary(library);
    if (!imported.ok())
        return imported.error().toString();
    std::string out;
    for (const ops::ToolController& tc : imported->library.tools)
        out += "T" + std::to_string(tc.tool.number) + " \"" + tc.tool.name + "\" " + tc.tool.kind + " " +
               bits(tc.tool.diameterMm) + " " + bits(tc.tool.cornerRadiusMm) + " " + bits(tc.tool.fluteLengthMm) + " " +
               bits(tc.tool.lengthMm) + "\n";
    return out;
}

}  // namespace

TEST(DecimalComma, ToolLibrariesReadTheSameAsInTheCLocale)
{
    const std::string freecad = toolsOf(kData + "/freecad/Library/shop.fctl");
    const std::string fusion = toolsOf(kData + "/fusion/shop.json");
    EXPECT_NE(freecad.find("T4 "), std::string::npos) << freecad;  // the 0.3125 in ball end mill
    EXPECT_NE(fusion.find("\"ball end mill D6.35\""), std::string::npos) << "a tool without a description\n" << fusion;
    camwb::test::DecimalCommaLocale comma;
    if (!comma.active())
        GTEST_SKIP() << comma.missing();
    EXPECT_EQ(toolsOf(kData + "/freecad/Library/shop.fctl"), freecad) << comma.name();
    EXPECT_EQ(toolsOf(kData + "/fusion/shop.json"), fusion) << comma.name();
}

TEST(DecimalComma, RecordDescriptionsKeepThePoint)
{
    camwb::test::DecimalCommaLocale comma;
    if (!comma.active())
        GTEST_SKIP() << comma.missing();
    EXPECT_EQ(document::describeRecord(toolpath::Dwell{0.5}), "dwell 0.5 s");
    EXPECT_EQ(document::planeOfNormal({0, -0.6, 0.8}), "normal (0.000, -0.600, 0.800)");
}
