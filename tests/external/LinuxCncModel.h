// What LinuxCNC 2.9 should do with the output of posts/linuxcnc.js for a CL toolpath, written as
// the CL records that tests/external/Rs274Trace.h reads back: canned cycles expanded into the moves
// LinuxCNC's interpreter makes at each hole (G-code reference, "G80-G89 Canned Cycles"), M6 stopping
// the spindle, M5 M9 and M2's reset at the end. Written from the documentation, not from the post.
#pragma once

#include "toolpath/Toolpath.h"

namespace camwb::external {

// The value as the post writes it (3 decimals): cycle depths are computed by LinuxCNC from these.
double written(double value);

// The expected motion: Rapid, Linear, Arc (whole CL arcs; normals along +X, +Y or +Z), Dwell,
// Spindle, Coolant, ToolChange, WorkOffset, FeedModeChange and ProgramStop records, state records
// only on change. Feeds are in the readback's unit: mm/min, mm/rev, or for inverse time the mm/min
// LinuxCNC derives from the move's length. Comments, sections and cutter compensation add nothing.
// `fromPost`: the records are a CL that posts/linuxcnc.js writes (its first rapid after a tool
// change goes over in X/Y, then Z); false: they are what an NC program commands, block by block.
toolpath::Toolpath expectedMotion(const toolpath::Toolpath& cl, bool fromPost = true);

// Sweep in degrees of an arc from `start` (extra turns included; start = end is a full turn).
double arcSweepDeg(const toolpath::Vec3& start, const toolpath::Arc& arc);

// Length of an arc from `start`, helix included, as LinuxCNC measures it for inverse time feeds.
double arcLengthMm(const toolpath::Vec3& start, const toolpath::Arc& arc);

// The arc seen about the positive principal axis (a normal along -Z becomes +Z, the direction flips).
toolpath::Arc canonicalArc(const toolpath::Arc& arc);

}  // namespace camwb::external
