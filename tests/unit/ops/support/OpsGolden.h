// The op tests' golden comparison: a CL trace compared byte for byte with a committed file under
// tests/unit/ops/<family>/golden/. CAMWB_UPDATE_GOLDEN=1 rewrites the file instead (review the
// diff before committing it).
#pragma once

#include <string>

namespace camwb::ops::test {

// Compares `trace` with tests/unit/ops/<family>/golden/<name> (family: "contour", "pocket",
// "holes"); a missing or different file fails the calling test.
void expectGolden(const std::string& family, const std::string& name, const std::string& trace);

}  // namespace camwb::ops::test
