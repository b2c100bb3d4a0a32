// The ISO program runner: walks the text line by line (the whole file is one string_view, no
// copy), reads each line into the one reused Block, applies its parameter assignments and hands
// it to the Machine; O-word subroutines, loops and conditions move the read position; o<name> call
// of a subroutine defined nowhere in the program loads <name>.ngc through resolveProgram. A runaway
// limit (InterpretOptions::maxBlocks) counts executed and skipped lines, so no input runs forever.
#pragma once

#include "nc/CutterCompensation.h"
#include "nc/Interpreter.h"
#include "nc/iso/IsoBlock.h"
#include "nc/iso/IsoMachine.h"
#include "nc/iso/IsoParameters.h"
#include "nc/iso/IsoReporter.h"
#include "nc/iso/IsoScanner.h"

#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::nc::iso {

class Program {
public:
    Program(std::string_view text, const InterpretOptions& options, toolpath::MachineSink& sink,
            InterpretResult& result);

    void run();

private:
    enum class Flow { Next, Stop };

    struct Position {
        std::size_t offset = 0;  // start of a line in its file's text
        int line = 1;            // its 1-based number
        int file = 0;            // index into m_texts and InterpretResult::files
    };
    struct CallFrame {
        Position returnTo;
        int controlDepth = 0;  // m_control.size() at the call
    };
    struct ControlFrame {
        OKeyword kind = OKeyword::None;  // If, While, Do, Repeat
        std::string label;
        Position start;  // While: its own line; Do and Repeat: the first line of the body
        long long remaining = 0;
        bool taken = false;
    };

    bool readLine(std::string_view& line);
    bool countBlock();
    void applyAssignments();

    // IsoControlFlow.cpp
    Flow oWord();  // dispatches to one of these by keyword
    Flow oReturn();
    Flow oCall();
    Flow oWhile();
    Flow oEndWhile();
    Flow oRepeat();
    Flow oEndRepeat();
    Flow oIf();
    Flow oElse();
    Flow oBreakOrContinue();
    int oCondition(const char* what);  // 1 true, 0 false, -1 missing (reported)
    static Flow skipped(bool found);   // after skipTo: Stop when no end was found
    bool skipTo(const std::string& label, std::initializer_list<OKeyword> keywords, bool pastIt,
                OKeyword* found = nullptr);
    bool findSubroutine(const std::string& label, Position& body);
    void scanSubroutines(int file);
    bool loadSubroutineFile(const std::string& label);
    void returnFromCall();
    ControlFrame* innermost(const std::string& label, std::initializer_list<OKeyword> kinds);
    void oError(std::string message);

    std::vector<std::string_view> m_texts;  // [0] the program, then subroutine files as first called
    std::deque<std::string> m_loaded;       // the texts of subroutine files (stable addresses)
    const InterpretOptions& m_options;
    toolpath::MachineSink& m_sink;  // m_compensation, in front of the caller's sink
    InterpretResult& m_result;
    Reporter m_reporter;
    CutterCompensation m_compensation;
    Parameters m_parameters;
    LineScanner m_scanner;
    Machine m_machine;
    Block m_block;

    Position m_current;    // the line being executed
    Position m_next;       // the line read next
    int m_lineNumber = 0;  // the line being executed
    bool m_fatal = false;
    bool m_programEnd = false;

    std::vector<CallFrame> m_calls;
    std::vector<ControlFrame> m_control;
    std::map<std::string, Position> m_subroutines;  // label -> first line of the body
    bool m_scannedSubroutines = false;
    std::map<std::string, bool> m_triedFiles;  // subroutine names looked up with resolveProgram
    std::string m_labelScratch;
};

}  // namespace camwb::nc::iso
