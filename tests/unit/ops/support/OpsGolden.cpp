#include "OpsGolden.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace camwb::ops::test {

void expectGolden(const std::string& family, const std::string& name, const std::string& trace)
{
    const std::string path = std::string(CAMWB_TEST_DATA_DIR) + "/tests/unit/ops/" + family + "/golden/" + name;
    if (const char* update = std::getenv("CAMWB_UPDATE_GOLDEN"); update && std::string(update) == "1") {
        std::ofstream(path, std::ios::binary) << trace;
        return;
    }
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(in) << "no golden " << path << " (CAMWB_UPDATE_GOLDEN=1 writes it)";
    std::stringstream expected;
    expected << in.rdbuf();
    EXPECT_EQ(trace, expected.str()) << "golden " << path << " differs (CAMWB_UPDATE_GOLDEN=1 rewrites it)";
}

}  // namespace camwb::ops::test
