// The post kernel's five-axis services, Qt-free: the machine poses of a program's five-axis
// sections chosen section by section with kinematics::planBranches (fewest reconfigurations over
// the whole operation), the pole cone, retract-turn-re-enter where the plan reconfigures, the
// joint-space linearisation of post-side machine coordinates and the feed a control without TCPM
// reads. ScriptSink writes the steps through the post's rapid5D/linear5D templates or onLinear5D.
#pragma once

#include "base/Result.h"
#include "kinematics/Machine.h"
#include "kinematics/PoseSolver.h"
#include "toolpath/Toolpath.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace camwb::post {

struct FiveAxisOptions {
    // A tool axis within this angle of the pole (the C axis' direction for a B/C table) keeps C:
    // the written axis is the pole's, off the CL's by at most this angle (a warning says by how
    // much). 0: only an axis exactly on the pole keeps C.
    double poleConeDeg = 0;
    // Where no branch finishes an operation without a flip or rewind: retract along the tool axis
    // by retractMm, turn, re-enter (true), or stop with an error naming the CL record (false).
    bool retractToReconfigure = true;
    double retractMm = 50;
    double reconfigureStepDeg = 30;  // kinematics::BranchPlanOptions::reconfigureStepDeg
};

enum class StepKind {
    Move,      // the CL's move (or one point of an arc linearised in a five-axis section)
    Retract,   // reconfiguration: away from the last point along its tool axis, old rotaries
    Turn,      // reconfiguration: the rotaries to the next pose, the tip where it is
    Approach,  // reconfiguration: to retractMm along the new tool axis above the next point
    Position,  // the first rapid of a section: X and Y of its pose before Z
};

// One block-to-be of a five-axis section.
struct FiveAxisStep {
    std::size_t record = 0;  // the CL record it belongs to
    int section = 0;         // index of its five-axis section (FiveAxisPlan::sections)
    StepKind kind = StepKind::Move;
    kinematics::ToolPose tool;      // workpiece frame
    kinematics::MachinePose pose;   // machine axes: linear about the chain's origin, rotaries by joint
    toolpath::AxisMask linearAxes;  // the linear axes the block gives (Position: X and Y)
    double feedMmPerMin = 0;        // 0: rapid
    int feedKind = 0;               // toolpath::FeedKind
    bool pole = false;              // C kept: the tool axis on (or within the cone of) the pole
    bool reconfigure = false;       // Retract/Turn/Approach and the move after them
    double axisDeviationDeg = 0;    // within the pole cone: the written axis' angle from the CL's
};

struct FiveAxisSection {
    std::size_t firstRecord = 0, lastRecord = 0;  // the move records it spans
    std::size_t firstStep = 0, endStep = 0;
    int reconfigurations = 0;
    double toolLengthMm = 0;  // of the tool that cuts it (head joints turn about a pivot above the tip)
    // Where the post turns the rotaries after it (onFiveAxisEnd): each at the whole turn nearest
    // where it stands (0 where that is beyond its limits); the next section is planned from there.
    std::array<double, 2> home{0, 0};
};

struct FiveAxisPlan {
    std::vector<FiveAxisStep> steps;  // in record order
    std::vector<FiveAxisSection> sections;
    int poleAdjusted = 0;  // steps whose axis the cone moved onto the pole
    double maxAxisDeviationDeg = 0;
    std::size_t firstPoleAdjusted = 0;  // its CL record
    int arcsLinearised = 0;             // arcs in five-axis sections, written as lines
    std::size_t firstArcLinearised = 0;
};

// Whether a tool axis is +Z: a ToolAxisMove along it is a three-axis move.
inline bool alongZ(const toolpath::Vec3& axis)
{
    return std::abs(axis.x) < 1e-9 && std::abs(axis.y) < 1e-9 && axis.z > 0;
}

// A section (SectionBegin to its SectionEnd; what lies outside sections counts as one) with a ToolAxisMove
// off +Z is five-axis: every move in it is a tool pose (Rapid/Linear and arcs, linearised within
// `arcToleranceMm`, along +Z), all
// planned together from the home pose (rotaries 0, or the whole turns FiveAxisSection::home of
// the section before, where the post returns them).
// Errors name the CL record: a pose out of reach, a reconfiguration refused, a cycle or an
// unknown start in a five-axis section.
base::Result<FiveAxisPlan> planFiveAxis(const toolpath::Toolpath& toolpath, const kinematics::Machine& machine,
                                        const FiveAxisOptions& options, double arcToleranceMm);

// The poses a control without TCPM is sent, in joint space from `from` to `to` (`to` last, `from`
// not), such that the tool tip, as the control interpolates each axis linearly between blocks,
// stays within `toleranceMm` of the CL's straight line from `tipFrom` to `tipTo`. Intermediate
// poses have interpolated rotaries and the linear axes that put the tip on that line.
std::vector<kinematics::MachinePose> lineariseJointMove(const kinematics::KinematicChain& chain,
                                                        const kinematics::MachinePose& from,
                                                        const kinematics::MachinePose& to,
                                                        const toolpath::Vec3& tipFrom, const toolpath::Vec3& tipTo,
                                                        double toleranceMm, double toolLengthMm = 0);

// The largest distance of the tool tip from the segment tipFrom-tipTo while every axis moves
// linearly from `from` to `to` (sampled; what lineariseJointMove keeps within its tolerance).
double jointMoveTipDeviation(const kinematics::KinematicChain& chain, const kinematics::MachinePose& from,
                             const kinematics::MachinePose& to, const toolpath::Vec3& tipFrom,
                             const toolpath::Vec3& tipTo, double toolLengthMm = 0);

// How F of a five-axis block is written: the CL's tip feed (TCPM, M116), for all axes together in
// mm and degrees (combinedFeed), or inverse time (inverseTimeFeed: SINUMERIK G93).
enum class FiveAxisFeed { Tip, Combined, InverseTime };

// F for a block from `from` to `to` on a control that moves all axes together at F in mm and
// degrees (the iTNC without M116/M128): the block takes the time the tip needs for tipLengthMm at
// tipFeed. A rotary-only block (tip standing) keeps tipFeed as degrees/min. Capped at maxFeed
// (0: none); `capped` says so.
double combinedFeed(const kinematics::MachinePose& from, const kinematics::MachinePose& to, double tipLengthMm,
                    double tipFeed, double maxFeed, bool* capped = nullptr);

// Inverse time (1/min) for the same block: the tip's time at tipFeed (a rotary-only block: its
// rotary travel at tipFeed degrees/min), no shorter than all axes together need at maxFeed.
double inverseTimeFeed(const kinematics::MachinePose& from, const kinematics::MachinePose& to, double tipLengthMm,
                       double tipFeed, double maxFeed, bool* capped = nullptr);

}  // namespace camwb::post
