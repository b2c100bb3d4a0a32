// The 2.5D outside profile (contour) operation: one closed boundary, one depth, the tool centre
// offset outside by the tool radius, arcs kept as arcs. Pure: parameters in, CL records out.
#pragma once

#include "base/Result.h"
#include "geom/Profile.h"
#include "ops/OpCommon.h"
#include "toolpath/Toolpath.h"

#include <string>

namespace camwb::ops {


struct ProfileParams {
    std::string name = "Profile";
    int faceIndex = 0;       // model face whose outer boundary is profiled (resolved by the caller)
    double finalDepthZ = 0;  // the one cutting depth
    double safeZ = 0;        // rapid down to here, then plunge at plunge feed
    double clearanceZ = 0;   // rapid height between operations
    bool climb = true;       // climb milling (tool travels clockwise around an outside boundary)
};

// Records (each with SourceRef{operationIndex, i}): SectionBegin{name, "profile", tool, feeds},
// Rapid to (start, clearanceZ), Rapid to safeZ, Linear down to finalDepthZ at plunge feed, the
// loop as Linear/Arc at cutting feed back to the start, Rapid up to clearanceZ, SectionEnd.
// The loop starts at the midpoint of the longest line of the offset profile (the plunge happens
// on a straight side), else at the first segment's start. Full-circle arcs are emitted as two
// half circles so no Arc record has its end on its start. ToolChange/Spindle are the caller's.
// Errors (nothing produced): bad tool diameter, feeds or spindle speed, clearanceZ < safeZ,
// safeZ <= finalDepthZ, empty boundary, and every offset error (tool too large, ...).
base::Result<toolpath::Toolpath> computeOuterProfile(const geom::Profile& boundary, const ProfileParams& params,
                                                     const ToolController& tc, int operationIndex);

}  // namespace camwb::ops
