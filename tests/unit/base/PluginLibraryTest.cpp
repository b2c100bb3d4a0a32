// base/PluginLibrary.h: where a library loaded on use is looked for, and each way it is refused.
#include "base/PluginLibrary.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace camwb::base;

namespace {

struct TestPluginTable {
    int abi;
    int answer;
};

PluginPlace place(std::string fromBinDir, std::string built)
{
    return {"the test plugin", "it answers", "CAMWB_TEST_PLUGIN", std::move(fromBinDir), std::move(built)};
}

// The variable cleared before the test and after it.
struct NoVariable {
    NoVariable() { unsetenv("CAMWB_TEST_PLUGIN"); }
    ~NoVariable() { unsetenv("CAMWB_TEST_PLUGIN"); }
};

}  // namespace

TEST(PluginLibrary, LoadsTheTableWhereTheBuildPutIt)
{
    NoVariable clean;
    const auto table = loadPlugin<TestPluginTable>(place("no-such-folder/x.so", CAMWB_TEST_PLUGIN_BUILT),
                                                   "camwb_test_plugin_table", 7);
    ASSERT_TRUE(table) << table.error().message;
    EXPECT_EQ(table.value()->answer, 42);
}

TEST(PluginLibrary, NamesEveryPlaceItLookedAt)
{
    NoVariable clean;
    const auto table =
        loadPlugin<TestPluginTable>(place("no-such-folder/x.so", "/no/such/built.so"), "camwb_test_plugin_table", 7);
    ASSERT_FALSE(table);
    const std::string& message = table.error().message;
    EXPECT_EQ(message.rfind("the test plugin is not at /", 0), 0u) << message;
    EXPECT_NE(message.find("no-such-folder/x.so nor at /no/such/built.so (it answers; CAMWB_TEST_PLUGIN may name"),
              std::string::npos)
        << message;
}

TEST(PluginLibrary, TheVariableAloneIsLookedAtWhenSet)
{
    NoVariable clean;
    setenv("CAMWB_TEST_PLUGIN", "/no/such/chosen.so", 1);
    const auto missing =
        loadPlugin<TestPluginTable>(place("x.so", CAMWB_TEST_PLUGIN_BUILT), "camwb_test_plugin_table", 7);
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("is not at /no/such/chosen.so ("), std::string::npos)
        << missing.error().message;
    setenv("CAMWB_TEST_PLUGIN", CAMWB_TEST_PLUGIN_BUILT, 1);
    EXPECT_TRUE(loadPlugin<TestPluginTable>(place("x.so", "/no/such/built.so"), "camwb_test_plugin_table", 7));
}

TEST(PluginLibrary, RefusesAFileThatIsNoLibraryAnotherEntryPointAndAnotherAbi)
{
    NoVariable clean;
    const std::string built = CAMWB_TEST_PLUGIN_BUILT;
    const auto notALibrary =
        loadPlugin<TestPluginTable>(place("x.so", CAMWB_TEST_SOURCE), "camwb_test_plugin_table", 7);
    ASSERT_FALSE(notALibrary);
    EXPECT_EQ(notALibrary.error().message.rfind(
                  std::string("the test plugin ") + CAMWB_TEST_SOURCE + " could not be loaded: ", 0),
              0u)
        << notALibrary.error().message;
    const auto noEntry = loadPlugin<TestPluginTable>(place("x.so", built), "camwb_other_table", 7);
    ASSERT_FALSE(noEntry);
    EXPECT_EQ(noEntry.error().message,
              "the test plugin " + built + " could not be loaded: it has no entry point camwb_other_table");
    const auto otherAbi = loadPlugin<TestPluginTable>(place("x.so", built), "camwb_test_plugin_table", 8);
    ASSERT_FALSE(otherAbi);
    EXPECT_EQ(otherAbi.error().message, "the test plugin " + built +
                                            " could not be loaded: it was built for another version of the program "
                                            "(ABI 7, expected 8)");
}
