// The bundled teaching part, built with OCCT so that the example STEP file can be regenerated
// (resources/examples/generator) and the tests can make a fresh copy.
#pragma once

#include "base/Result.h"

#include <string>

namespace camwb::occ {

// A 90 x 60 x 15 mm block (corner at the origin, top at Z=15) with its four vertical edges rounded
// R8; a pocket 44 x 36 mm, 5 mm deep (floor at Z=10), corner radius 6, centred at (33, 30), with a
// round island of diameter 10 at its centre rising back to the top (Z=15); a through hole of
// diameter 10 at (72, 30); four blind holes of diameter 5, 8 mm deep (flat bottom at Z=7) at
// (8, 8), (82, 8), (82, 52) and (8, 52), concentric with the rounded corners. Written as AP214 STEP
// in mm, with a fixed header time stamp so that regenerating gives the same file.
base::Status writeExamplePart(const std::string& stepPath);

// The five-axis teaching part (after seed 000's test part): an 80 x 80 mm block, zero at the
// centre of its bottom, 20 mm of vertical sides and above them four faces inclined 30 degrees up
// to a 28 x 28 mm top at Z 35 with a spherical cap (R20 about (0, 0, 20), 5 mm high); a hole D6, 8
// deep, square to each inclined face at its middle (Z 27.5; on the -X face 12 mm towards -Y) and a
// boss 10 x 8 x 3 mm on the -X face 12 mm towards +Y.
base::Status writeFiveAxisExamplePart(const std::string& stepPath);
// The five-axis part's cast blank (resources/examples/example-five-axis-blank.step, the example
// job's stock): the inclined block and cap without the holes; a pad 18 x 16 mm, 3 mm high, in
// place of the boss; a round stub R6, 5 mm high, in place of the drafted boss.
base::Status writeFiveAxisExampleBlank(const std::string& stepPath);

// The three-axis mould teaching part (the 3D pocket and finishing example): a 100 x 80 x 30 mm
// block (corner at the origin, top at Z 30) with a cavity whose opening at the top is 80 x 60 mm
// from (10, 10) to (90, 70), corners R12; its walls drafted 10 degrees inwards (the corners cones)
// down to a flat floor at Z 10, the floor edge rounded R3. At the -X end a shelf with a flat top at
// Z 20: its wall faces +X, at X 28 on top, drafted 10 degrees; the edges where the shelf meets the
// walls and the floor rounded R3, its top edge at X 28 sharp. On the floor a spherical dome (sphere
// R20 about (60, 40, -4)) rises to Z 16, its foot rounded R2 into the floor. No undercut: no face
// but the bottom looks down. Written like the others (fixed header, same file every time).
base::Status writeMouldExamplePart(const std::string& stepPath);

}  // namespace camwb::occ
