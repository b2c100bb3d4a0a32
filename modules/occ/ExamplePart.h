// The bundled teaching part, built with OCCT so that the example STEP file can be regenerated
// (resources/examples/generator) and the tests can make a fresh copy.
#pragma once

#include "base/Result.h"

#include <string>

namespace camwb::occ {

// A 90 x 60 x 15 mm block (corner at the origin, top at Z=15) with its four vertical edges rounded
// R8, a rectangular pocket 40 x 24 mm, 5 mm deep, corner radius 5, centred at (35, 30), and a
// through hole of diameter 10 at (72, 30). Written as AP214 STEP in mm, with a fixed header time
// stamp so that regenerating gives the same file.
base::Status writeExamplePart(const std::string& stepPath);

}  // namespace camwb::occ
