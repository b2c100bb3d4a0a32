// The words of a Klartext PLANE block (iTNC 530 User's Manual, "The PLANE function: tilting the
// working plane"): the values of its form (SPA SPB SPC, BX..NZ of VECTOR, A B C of AXIAL), how the
// rotary axes are positioned (MOVE, TURN, STAY with MB, F/FMAX, DIST) and SEQ+/SEQ-; the choice of
// transformation (COORD ROT, TABLE ROT) is accepted.
#include "nc/heidenhain/Parser.h"

#include <array>
#include <string>

namespace camwb::nc::heidenhain {

namespace {

constexpr std::array<std::string_view, kPlaneWordCount> kValueNames{"SPA", "SPB", "SPC", "BX", "BY", "BZ",
                                                                    "NX",  "NY",  "NZ",  "A",  "B",  "C"};

int valueIndex(std::string_view name)
{
    for (std::size_t i = 0; i < kValueNames.size(); ++i) {
        if (equalsIgnoreCase(name, kValueNames[i]))
            return static_cast<int>(i);
    }
    return -1;
}

}  // namespace

void parsePlaneWords(Cursor& c, ParseEnv& env, Block& b)
{
    Program& p = env.program;
    b.firstWord = static_cast<int>(p.words.size());
    if (!b.flag && !equalsIgnoreCase(b.name, "SPATIAL") && !equalsIgnoreCase(b.name, "VECTOR") &&
        !equalsIgnoreCase(b.name, "AXIAL"))
        return;  // the other forms are warned about when run
    auto error = [&](int line, int column, std::string message) {
        env.reporter.report(Severity::Error, env.file, line, column, std::move(message));
        b.kind = BlockKind::Invalid;
    };
    while (!c.atEnd()) {
        const int line = c.line(), column = c.column();
        const std::string_view name = c.letters();
        if (name.empty()) {
            return error(line, column, "unknown word '" + std::string(c.token()) + "' in PLANE");
        } else if (equalsIgnoreCase(name, "MOVE") || equalsIgnoreCase(name, "TURN") || equalsIgnoreCase(name, "STAY")) {
            b.a = equalsIgnoreCase(name, "MOVE")   ? kPlaneMove
                  : equalsIgnoreCase(name, "TURN") ? kPlaneTurn
                                                   : kPlaneStay;
        } else if (equalsIgnoreCase(name, "SEQ")) {
            const char sign = c.peek();
            if (sign != '+' && sign != '-')
                return error(c.line(), c.column(), "SEQ must be followed by + or -");
            c.advance();
            b.b = sign == '+' ? 1 : -1;
        } else if (equalsIgnoreCase(name, "MB")) {
            c.skipSpace();
            if (c.keyword("MAX")) {
                p.words.push_back({Key::Mb, -1, 1, line, column});
            } else {
                const int e = parseValue(c, env);
                if (e < 0)
                    return error(c.line(), c.column(), "MB needs a retract distance or MAX");
                p.words.push_back({Key::Mb, e, 0, line, column});
            }
        } else if (equalsIgnoreCase(name, "FMAX") || equalsIgnoreCase(name, "FAUTO")) {
            // The positioning feed of the rotary axes: not traced (the turn is not a move of the tip).
        } else if (equalsIgnoreCase(name, "F") || equalsIgnoreCase(name, "DIST")) {
            c.skipSpace();
            if (parseValue(c, env) < 0)
                return error(c.line(), c.column(), std::string(name) + " needs a value");
        } else if (equalsIgnoreCase(name, "COORD") || equalsIgnoreCase(name, "TABLE")) {
            c.skipSpace();
            if (!c.keyword("ROT"))
                return error(c.line(), c.column(), std::string(name) + " must be followed by ROT");
        } else if (const int index = valueIndex(name); index >= 0) {
            c.skipSpace();
            const int e = parseValue(c, env);
            if (e < 0)
                return error(c.line(), c.column(), std::string(name) + " needs a value");
            p.words.push_back({Key::PlaneValue, e, index, line, column});
        } else {
            return error(line, column, "unknown word '" + std::string(name) + "' in PLANE");
        }
    }
    b.wordCount = static_cast<int>(p.words.size()) - b.firstWord;
}

}  // namespace camwb::nc::heidenhain
