// The modal state of an RS274NGC (LinuxCNC / Fanuc style) mill and the execution of one block
// in LinuxCNC's order of execution ("G-code overview", "Order of Execution"): feed mode, feed,
// speed, tool, M6, spindle, coolant, dwell, plane, units, compensation, work offset, distance
// modes, retract mode, then motion and stops. Records go to the MachineSink in mm, in the work
// offset's frame, each after setSource() with the block's line.
#pragma once

#include "nc/BlockModal.h"
#include "nc/CutterCompensation.h"
#include "nc/KnownAxes.h"
#include "nc/ToolTable.h"
#include "nc/iso/IsoBlock.h"
#include "nc/iso/IsoParameters.h"
#include "nc/iso/IsoReporter.h"
#include "toolpath/MachineSink.h"

#include <optional>

namespace camwb::nc::iso {

struct ModalState {
    int motion = 800;     // G code x10 of the motion mode; LinuxCNC starts in G80
    int lastMotion = -1;  // the last of G0..G3 programmed, -1 = none yet
    int plane = 170;      // 170, 180, 190
    bool absolute = true;
    bool arcAbsolute = false;  // G90.1; LinuxCNC starts in G91.1
    toolpath::FeedMode feedMode = toolpath::FeedMode::PerMinute;
    double unit = 1.0;  // mm per program unit: 25.4 under G20
    toolpath::CutterCompSide comp = toolpath::CutterCompSide::Off;
    int compCode = 400;  // as programmed: 400, 410, 411, 420, 421
    int workOffset = 1;
    bool retractToR = false;  // G99 (LinuxCNC starts in G98)
    double feed = 0;          // mm/min, mm/rev, or 1/min under G93
    double rpm = 0;           // programmed S
    double runningRpm = 0;    // the speed last sent to the sink
    int spindle = 0;          // 1 clockwise, -1 counter-clockwise, 0 stopped
    int selectedTool = 0;
    int tool = 0;
    bool mist = false;
    bool flood = false;
    toolpath::Vec3 position;  // mm, work frame; 0 on axes not yet known (rs274 starts at the origin)
    KnownAxes known;          // axes given in absolute terms so far (none at the start)
    // Canned-cycle words kept between cycle blocks (LinuxCNC 2.9 keeps R, Z, P and Q).
    double cycleR = 0, cycleZ = 0, cycleP = 0, cycleQ = 0;
    bool haveCycleR = false, haveCycleZ = false;
    bool cycleSequence = false;  // the last motion was a hole of a cycle still in force
    double cycleStartZ = 0;      // Z before the first hole of that cycle: the Cycle records' clearance
};

// The X, Y and Z words a block has.
toolpath::AxisMask axisWords(const Block& block);

enum class BlockOutcome { Continue, ProgramEnd };

class Machine {
public:
    // `sink` compensates the cutter radius (CutterCompensation.h); `toolTable` may be null.
    Machine(CutterCompensation& sink, const ToolTable* toolTable, Reporter& reporter, const Parameters& parameters,
            double arcToleranceMm) :
        m_sink(sink),
        m_compensation(sink),
        m_toolTable(toolTable),
        m_reporter(reporter),
        m_parameters(parameters),
        m_arcTolerance(arcToleranceMm)
    {
    }

    // The tool is at `position` (work frame, mm) with every axis known: InterpretOptions::start.
    // Where the program starts, when known, and which axes are (nc::knownAtStart).
    void startAt(const std::optional<toolpath::Vec3>& position, const KnownAxes& known)
    {
        if (position)
            m_state.position = *position;
        m_state.known = known;
    }
    // Runs a block read without errors. `fileIndex` is the SourceRef::file of its line.
    BlockOutcome execute(const Block& block, int line, int fileIndex);
    // M2/M30 resets (also at the end of a file without them, as LinuxCNC's end of program does not).
    void programEnd();
    const ModalState& state() const { return m_state; }
    // The state after the last executed block in the program's words (BlockModal.h).
    void reportModal(const BlockObserver& observer) const;
    // Tells the sink which block is running without a record: the call line before a subroutine's
    // records, so a viewer links them to the exact call (Interpreter.h).
    void announce(int line, int fileIndex) { m_sink.setSource(toolpath::SourceRef{-1, -1, line, fileIndex}); }

private:
    struct Groups {  // codes of one block by modal group, x10; -1 = none
        int g[16];
        int gColumn[16];
        int stop = -1, toolChange = -1, spindle = -1, coolantCount = 0, coolant[3] = {-1, -1, -1};
        int stopColumn = 0;
    };
    bool classify(const Block& block, Groups& groups);
    // One step per modal group, in LinuxCNC's order of execution (execute() calls them); false:
    // an error was reported and the rest of the block is left out.
    void applyFeedMode(const Groups& groups);
    void applyUnits(const Groups& groups);
    bool applyFeedRate(const Block& block);
    bool applySpindleSpeed(const Block& block, const Groups& groups);
    bool applyToolSelection(const Block& block);
    bool applyToolChange(const Block& block, const Groups& groups);
    void applySpindle(const Groups& groups);
    void applyCoolant(const Groups& groups);
    bool applyDwell(const Block& block, const Groups& groups);
    void applyPlane(const Groups& groups);
    void applyCompensation(const Block& block, const Groups& groups);
    void setCompensationRadius(const Block& block, int code);
    void applyWorkOffset(const Groups& groups);
    void applyDistanceModes(const Groups& groups);
    void applyRetractMode(const Groups& groups);
    bool applyMotion(const Block& block, const Groups& groups);
    BlockOutcome applyStop(const Groups& groups);
    void source() { m_sink.setSource(toolpath::SourceRef{-1, -1, m_line, m_file}); }
    void setSpindle(double rpm, int direction);
    void setCoolant(bool mist, bool flood);
    void motion(const Block& block, int mode);
    void moveInMachineCoordinates(const Block& block, int column);
    bool executeMotionOnly(const Block& block);
    toolpath::Vec3 target(const Block& block) const;
    void checkAxes(const Block& block);
    bool needKnown(const Block& block, toolpath::AxisMask before, toolpath::AxisMask after, toolpath::AxisMask given,
                   const char* need);
    bool checkKnown(const Block& block, int mode, toolpath::AxisMask& given);

    // IsoArcs.cpp
    void arc(const Block& block, bool clockwise, const toolpath::Vec3& to);
    // IsoCycles.cpp
    void cycle(const Block& block, int mode);
    void referenceReturn(const Block& block, int code);

    double feedFor(const Block& block, const char* what);
    void error(const Block& block, char letter, std::string message);

    toolpath::MachineSink& m_sink;
    CutterCompensation& m_compensation;
    const ToolTable* m_toolTable;
    Reporter& m_reporter;
    const Parameters& m_parameters;
    double m_arcTolerance;
    ModalState m_state;
    int m_line = 0;
    int m_file = 0;
    bool m_warnedRotary = false;
    bool m_warnedG53 = false;
    bool m_warnedG80 = false;
};

}  // namespace camwb::nc::iso
