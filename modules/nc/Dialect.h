// The NC dialects the interpreters read, their names on the command line, and a guess from a
// file's name and first lines for when the user does not say.
#pragma once

#include <optional>
#include <string_view>

namespace camwb::nc {

enum class Dialect {
    Sinumerik,   // SINUMERIK 828D/840D: R parameters, CYCLE8x, PROC, ';' comments
    Heidenhain,  // Heidenhain Klartext (iTNC 530 / TNC 640)
    Iso,         // plain ISO as LinuxCNC and Fanuc read it: '(' comments, G81-G89, G98/G99
};

const char* dialectName(Dialect dialect);  // "sinumerik", "heidenhain", "iso"
std::optional<Dialect> dialectFromName(std::string_view name);

// Heidenhain when the text has BEGIN PGM or the name ends in .h/.H; Sinumerik for .mpf/.spf or
// Sinumerik-only words (R parameters assigned, CYCLE8x(, MCALL, PROC, ';' comments, G710 ...);
// ISO otherwise (.ngc, .nc, .tap, parentheses comments).
Dialect guessDialect(std::string_view text, std::string_view path);

}  // namespace camwb::nc
