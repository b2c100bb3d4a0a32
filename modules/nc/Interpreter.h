// Reads an NC program in its dialect and drives a MachineSink with what the control would do:
// the one entry point the CLI, the NC inspector and the round-trip tests use. Before each record
// the interpreter calls sink.setSource() with the program line that made it (SourceRef::line,
// SourceRef::file indexing InterpretResult::files), so the GUI can link segments and lines.
// Before entering a called program it announces the calling block the same way (no record need
// follow), so records of the callee can be linked to the exact call.
//
// What reaches the sink, whatever the dialect: positions in mm in the work offset's frame (inch
// programs scaled, diameter programming halved), feeds in mm/min, mm/rev or 1/min with a
// FeedModeChange before a change of mode, rapids as Rapid, G1/L as Linear, circles and helices
// as Arc (turns for full extra revolutions), canned cycles as one Cycle record per hole call
// (clearance = where the tool returns between holes: the height before the call for G98, the
// RTP for SINUMERIK, the 2nd set-up clearance Q203+Q204 for Heidenhain; retract = R plane /
// set-up clearance; top = reference plane), ToolChange with the tool number (geometry default),
// Spindle, Coolant, WorkOffset, Dwell, CutterComp, ProgramStop, Comment for comments.
// A CL file (APT, FreeCAD dump, trace) goes through the same entry, read by its importer
// (InterpretOptions::clFormat), so everything that reads a program back reads CL as well.
#pragma once

#include "nc/BlockModal.h"
#include "nc/Diagnostic.h"
#include "nc/Dialect.h"
#include "toolpath/ClImport.h"
#include "toolpath/ClRecords.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::kinematics {
struct Machine;
}
namespace camwb::toolpath {
class MachineSink;
}

namespace camwb::nc {

class ToolTable;

// A program found by name for a call (Sinumerik subprogram/PROC, Heidenhain CALL PGM).
struct ProgramSource {
    std::string path;
    std::string text;
};
// Finds a called program by the name the caller wrote; nullopt when there is none.
using ProgramResolver = std::function<std::optional<ProgramSource>(std::string_view name)>;

// Looks for <folder>/<name> and <folder>/<name><ext> for each extension, trying the name as
// written, upper case and lower case (controls store SPF files in upper case).
ProgramResolver folderResolver(std::string folder, std::vector<std::string> extensions);

// The folder of `programPath`, with the extensions the dialect's called programs have (.h for
// Heidenhain; .spf, .mpf, .ngc, .nc otherwise): how the CLI and the inspector find subprograms.
ProgramResolver resolverBeside(const std::string& programPath, Dialect dialect);

struct InterpretOptions {
    Dialect dialect = Dialect::Iso;
    // Set: the text is a CL file of this format, read by its importer (toolpath/ClImport.h) and
    // sent on record by record, each at its statement's line; the NC-only options do not apply.
    std::optional<toolpath::ClFormat> clFormat;
    std::string fileName;                          // for diagnostics; empty = "<input>"
    ProgramResolver resolveProgram;                // empty: calls to other programs are errors
    const kinematics::Machine* machine = nullptr;  // kinematics::LimitCheck on what the program does, when set
    // False: the machine's chain reads the program but its limits are checked by the caller (the
    // simulator checks them on the same records as errors of its own).
    bool checkLimits = true;
    const ToolTable* toolTable = nullptr;  // tool radii for cutter compensation (the program's own data first)
    // Where the tool is when the program starts, when the caller knows it (rs274 starts at the
    // origin). None (the default): every axis is unknown until the program gives it in absolute
    // terms, as on the control; moves carry the known axes only until then (nc/KnownAxes.h).
    std::optional<toolpath::Vec3> start;
    BlockObserver onBlock;                // after each executed block: its modal state (BlockModal.h)
    std::int64_t maxBlocks = 10'000'000;  // executed blocks before a runaway-program error
    double arcRadiusToleranceMm = 0.01;   // start/end radius mismatch that is an error
    std::size_t maxDiagnostics = 1000;    // further ones are counted, not kept
    // Set from another thread to stop the run (a newer trace supersedes this one): checked every
    // kCancelCheckBlocks executed blocks; the result is then marked cancelled, without a diagnostic.
    const std::atomic<bool>* cancel = nullptr;
};

inline constexpr std::int64_t kCancelCheckBlocks = 1024;

// True when the run should stop: `blocksExecuted` is a multiple of kCancelCheckBlocks and the
// caller's cancel flag is set. Every dialect's block loop asks this.
inline bool cancelRequested(const InterpretOptions& options, std::int64_t blocksExecuted)
{
    return options.cancel && blocksExecuted % kCancelCheckBlocks == 0 &&
           options.cancel->load(std::memory_order_relaxed);
}

struct InterpretResult {
    std::vector<Diagnostic> diagnostics;
    std::vector<std::string> files;  // [0] the program itself, then subprograms as first called
    std::int64_t blocksExecuted = 0;
    std::size_t diagnosticsDropped = 0;
    bool completed = false;  // reached the program end (M30/M2/END PGM or the last line) without a fatal error
    bool cancelled = false;  // stopped by InterpretOptions::cancel

    bool hasErrors() const { return nc::hasErrors(diagnostics); }
};

InterpretResult interpret(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink);

// Reads the file (diagnostic when it cannot), guesses the dialect when `dialect` is empty (then
// a CL file's name, .apt .cls .dump .trace ..., has it read as that CL file) and resolves
// subprograms in the file's folder unless options.resolveProgram is set.
InterpretResult interpretFile(const std::string& path, std::optional<Dialect> dialect, InterpretOptions options,
                              toolpath::MachineSink& sink);

}  // namespace camwb::nc
