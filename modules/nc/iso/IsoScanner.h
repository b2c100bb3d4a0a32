// Reads one line of an ISO (RS274NGC) program into a Block: words, values given as numbers,
// parameters, [expressions] or functions, comments, parameter assignments and O-words. Values are
// evaluated as the line is read, with the parameters as they were before the line (LinuxCNC sets
// the line's assignments after reading it). One diagnostic per line: the rest of a broken line is
// not read.
#pragma once

#include "nc/iso/IsoBlock.h"
#include "nc/iso/IsoNumber.h"
#include "nc/iso/IsoParameters.h"
#include "nc/iso/IsoReporter.h"

#include <string_view>

namespace camwb::nc::iso {

class LineScanner {
public:
    LineScanner(const Parameters& parameters, Reporter& reporter) : m_parameters(parameters), m_reporter(reporter) {}

    // Fills `block` from `line` (no line end). Errors are reported and set block.error.
    void scan(std::string_view line, int lineNumber, Block& block);

    // Only the O-word of a line, nothing evaluated: for skipping to the end of a loop or condition.
    static bool peekOWord(std::string_view line, std::string& label, OKeyword& keyword);

private:
    // Values (IsoExpression.cpp).
    bool readValue(double& out);
    bool readExpression(double& out, int minPrecedence);
    bool readBracketed(double& out);
    bool readParameter(double& out);
    bool readFunction(double& out);
    bool readParameterIndex(int& index, std::string& name);
    int readOperator(int& precedence);  // 0 none, else an operator id; consumes it

    // The line (IsoScanner.cpp).
    bool readWord(char letter, Block& block);
    bool readAssignment(Block& block);
    bool readOWord(Block& block);
    bool readComment(Block& block);

    void fail(const char* at, std::string message);
    int columnOf(const char* at) const { return static_cast<int>(at - m_begin) + 1; }
    void skipBlanks()
    {
        while (m_p < m_end && isBlank(*m_p))
            ++m_p;
    }

    const Parameters& m_parameters;
    Reporter& m_reporter;
    const char* m_begin = nullptr;
    const char* m_p = nullptr;
    const char* m_end = nullptr;
    int m_line = 0;
    int m_depth = 0;  // nesting of brackets and unary operators: bounded, so no input overflows the stack
    bool m_failed = false;
    std::string m_name;  // scratch for parameter names
};

}  // namespace camwb::nc::iso
