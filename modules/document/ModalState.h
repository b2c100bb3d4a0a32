// The modal state of an interpreted NC program at any record, derived by replaying its CL records
// (what the NC inspector's modal panel shows for the block under the cursor). Plain C++, no Qt.
// What the records do not carry (plane, units, abs/inc as written) is not invented here: the
// plane is the one of the last arc (its normal), positions are in mm in the work offset's frame.
#pragma once

#include "base/Vec.h"
#include "toolpath/ClRecords.h"

#include <cstddef>
#include <string>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::document {

struct ModalState {
    int tool = 0;  // 0 = no tool change yet
    double feed = 0;
    toolpath::FeedMode feedMode = toolpath::FeedMode::PerMinute;
    double spindleRpm = 0;
    bool spindleClockwise = true;
    double surfaceSpeedMPerMin = 0;
    toolpath::CoolantMode coolant = toolpath::CoolantMode::Off;
    int workOffset = 0;  // 0 = none set by the program
    toolpath::CutterCompSide compensation = toolpath::CutterCompSide::Off;
    bool hasPosition = false;
    base::Vec3 position;
    bool hasArcNormal = false;
    base::Vec3 arcNormal{0, 0, 1};  // of the last arc: the plane the program was in then
    // The tool axis in the workpiece frame (+Z for 3-axis moves) and the machine's rotary axes
    // as the last five-axis move knew them (nc read back through a machine's kinematics).
    base::Vec3 toolAxis{0, 0, 1};
    bool fiveAxis = false;  // the last move was a five-axis move
    toolpath::RotaryAxes rotaryAxes;
};

// Applies one record to a state (position after the move, tool, feed, ...).
void applyRecord(ModalState& state, const toolpath::Record& record);

// "rapid", "linear", "arc CW", "cycle drill (3 holes)", "tool change T2", ...
std::string describeRecord(const toolpath::Record& record);
// As describeRecord, and "helix CW/CCW" for an arc that leaves its plane from `before`.
std::string describeMove(const ModalState& before, const toolpath::Record& record);
// "G17 (XY)" for a +/-Z normal, "G18 (ZX)", "G19 (YZ)", or the vector for another plane.
std::string planeOfNormal(const base::Vec3& normal);

// States before every record, computed from checkpoints: O(n) to build, O(stride) per query, so
// a cursor move in a million-record program costs microseconds.
class ModalStateTable {
public:
    ModalStateTable() = default;
    explicit ModalStateTable(const toolpath::Toolpath& program, std::size_t stride = 1024);

    // The state before record `index` runs (index == size: after the last record).
    ModalState before(const toolpath::Toolpath& program, std::size_t index) const;

private:
    std::size_t m_stride = 1024;
    std::vector<ModalState> m_checkpoints;  // state before record k * stride
};

}  // namespace camwb::document
