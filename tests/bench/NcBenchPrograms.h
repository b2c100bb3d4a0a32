// The NC programs the interpreter benchmarks read, generated deterministically: bench::
// benchProgram's lines and quarter arcs as our posts write them in each dialect (ISO as
// posts/linuxcnc.js, SINUMERIK as posts/sinumerik828d-emco.js, Heidenhain Klartext with L, CC
// and C), and two loop-heavy programs that compute every move from R or Q parameters.
#pragma once

#include "nc/Dialect.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace camwb::bench {

enum class NcProgram {
    Iso,               // straight: one block per move
    Sinumerik,         // straight: the same moves, N-numbered
    SinumerikLoops,    // WHILE, LOOP, GOTOF/GOTOB and R arithmetic
    Heidenhain,        // straight: the same moves, an arc is CC + C (two blocks)
    HeidenhainLabels,  // Q parameters, LBL section repeats, a called label, FN 12 jumps
};

// The name on the command line (iso, sinumerik, sinumerik-loops, heidenhain, heidenhain-labels).
std::optional<NcProgram> ncProgramFromName(std::string_view name);
const char* ncProgramName(NcProgram program);
nc::Dialect dialectOf(NcProgram program);

// The program's text, about `blocks` blocks executed: the ISO and SINUMERIK straight programs
// have that many moves (bench::benchProgram; the ISO one is the file scripts/bench-nc.sh gives
// rs274), the Heidenhain one two thirds as many, the loop programs run rows until that many
// blocks have executed (a few dozen lines).
std::string ncProgram(NcProgram program, std::size_t blocks);

}  // namespace camwb::bench
