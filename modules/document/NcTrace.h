// One interpretation of an NC program for the inspector: the recorded CL records with their
// source lines, the diagnostics, and the indexes the GUI needs to link lines and records both
// ways (line -> records, record -> line) and to show the modal state. A CL file (APT, FreeCAD
// dump, trace) is read by its importer into the same form, each record at its statement's line.
// Built on a worker thread; plain C++, no Qt, so it is testable on its own.
#pragma once

#include "document/ModalState.h"
#include "kinematics/Machine.h"
#include "nc/Dialect.h"
#include "nc/Interpreter.h"
#include "nc/ToolTable.h"
#include "toolpath/ClImport.h"
#include "toolpath/Toolpath.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace camwb::document {

// What one line of the main program does: the state before its first record and after its
// first run (a line inside a loop runs several times; `runs` counts them).
struct LineState {
    int line = 0;
    std::size_t records = 0;  // over all runs
    int runs = 0;
    std::string move;  // "linear", "arc CW", "cycle drill (3 holes)", "" = no motion
    ModalState before;
    ModalState after;
    // The modal state the line ran with in the dialect's own words (G90, G710, RL, ...); for a
    // line that did not run, the last one before it that did. Empty before the first block.
    std::optional<nc::BlockModal> words;
};

struct NcTrace {
    nc::Dialect dialect = nc::Dialect::Iso;
    bool dialectGuessed = true;
    // Set when the text was read as a CL file of this format, not as NC in `dialect`.
    std::optional<toolpath::ClFormat> clFormat;
    toolpath::Toolpath program;
    nc::InterpretResult result;  // diagnostics, files ([0] the program), completion
    bool cancelled = false;      // a newer trace superseded this one; its records are incomplete
    double interpretSeconds = 0;
    double indexSeconds = 0;
    // Per record, true for a block with an error (nc::recordsInError; empty when none): drawn
    // marked, not as what it claims.
    std::vector<bool> recordsInError;

    // Records of a line of the main program (file 0), in execution order (a line in a loop has
    // several runs). Subprogram records are not in here: see callerLine().
    std::vector<std::size_t> recordsOfLine(int line) const;
    // The main-program line a record belongs to: its own line, or for a record of a called
    // program (SourceRef::file > 0) the main-program line last active before the call.
    int lineOfRecord(std::size_t record) const;
    // True when the record comes from a called program; `file`/`line` say where.
    bool isInSubprogram(std::size_t record) const;
    // "O1234.spf:12" for a subprogram record, "12" for the main program.
    std::string whereOf(std::size_t record) const;

    ModalState stateBefore(std::size_t record) const { return modal.before(program, record); }
    // A line without records gets the state in force where the next recorded line starts.
    LineState lineState(int line) const;

    // The modal words a main-program line ran with first (or the nearest earlier line's).
    const nc::BlockModal* wordsOfLine(int line) const;

    // Distinct modal states in the order they appeared, and per main-program line the index of
    // the one its first run had (kNoWords where the line did not run): a few states for a
    // million lines.
    static constexpr std::uint32_t kNoWords = 0xFFFFFFFFu;
    std::vector<nc::BlockModal> modalWords;
    std::vector<std::uint32_t> wordsIndexOfLine;

    // (line, record) of main-program records, sorted by line then record.
    std::vector<std::pair<int, std::uint32_t>> lineRecords;
    // Starts of subprogram runs: (first record, calling main-program line), sorted by record.
    std::vector<std::pair<std::uint32_t, int>> subprogramRuns;
    ModalStateTable modal;
};

struct NcTraceRequest {
    std::string text;
    std::string path;  // for diagnostics, the dialect guess and subprogram lookup
    // nullopt: a CL file by its extension (toolpath::clFormatFromExtension), else nc::guessDialect.
    std::optional<nc::Dialect> dialect;
    // Checked against its limits (kinematics::LimitCheck) as posting checks CL, when set.
    std::shared_ptr<const kinematics::Machine> machine;
    bool checkLimits = true;  // false: the machine reads the program, the caller checks its limits
    // Tool sizes for cutter compensation where the program gives none (the job's tools).
    std::shared_ptr<const nc::ToolTable> tools;
    const std::atomic<bool>* cancel = nullptr;
};

// How a program is read when `dialectChoice` is what the user asked for: as a CL file of the format
// its extension names when no dialect is asked for (nullopt: as NC). The inspector, its editor's
// highlighting and block-number tools and Program Information all go by this one rule.
std::optional<toolpath::ClFormat> clFormatToRead(const std::string& path, std::optional<nc::Dialect> dialectChoice);

// Interprets the text (subprograms looked up in the folder of `path` when it has one), or imports
// it as a CL file when no dialect is asked for and `path` names one, and builds the indexes. Once
// `cancel` is set the interpreter stops within a thousand blocks (SINUMERIK and Heidenhain finish
// parsing first), nothing more is recorded and the trace is marked cancelled.
NcTrace traceNc(const NcTraceRequest& request);

}  // namespace camwb::document
