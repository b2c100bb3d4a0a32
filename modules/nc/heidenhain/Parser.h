// The Klartext block parser: turns a program text into Program blocks (kind, words, expressions,
// labels) once, reporting syntax problems with line and column; the interpreter never re-reads text.
#pragma once

#include "nc/heidenhain/Expression.h"
#include "nc/heidenhain/Lexer.h"
#include "nc/heidenhain/Program.h"

#include <string_view>

namespace camwb::nc::heidenhain {

// Fills `program` (segments, blocks, labels) from `text`, whose storage must outlive it.
void parseProgram(Program& program, std::string_view text, Reporter& reporter);

// Word sets a block kind accepts (bit mask of WordGroup).
enum WordGroup : unsigned {
    kAxes = 1u << 0,      // X Y Z A B C U V W and IX..IW
    kPolar = 1u << 1,     // PR PA IPR IPA
    kRadius = 1u << 2,    // R
    kDir = 1u << 3,       // DR+ DR-
    kComp = 1u << 4,      // R0 RL RR
    kFeed = 1u << 5,      // F FMAX FAUTO FU FZ
    kMisc = 1u << 6,      // M
    kTool = 1u << 7,      // tool axis, S, DL, DR, DR2
    kToolDef = 1u << 8,   // L R
    kLenAngle = 1u << 9,  // LEN CCA
};

// The rest of a PLANE block after its form (SPATIAL, VECTOR, AXIAL, RESET ...): its values as
// Key::PlaneValue words, MB, the positioning (Block::a) and SEQ (Block::b); errors at their columns.
void parsePlaneWords(Cursor& cursor, ParseEnv& env, Block& block);

// Parses the words of a block until its end into program.words (block.firstWord/wordCount).
void parseWords(Cursor& cursor, ParseEnv& env, Block& block, unsigned groups);

}  // namespace camwb::nc::heidenhain
