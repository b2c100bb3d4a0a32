#include "nc/Dialect.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace camwb::nc {

namespace {

std::string lower(std::string_view s)
{
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::string upperPrefix(std::string_view text, std::size_t length)
{
    std::string out(text.substr(0, std::min(text.size(), length)));
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return out;
}

bool endsWith(const std::string& s, std::string_view suffix)
{
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

const char* dialectName(Dialect dialect)
{
    switch (dialect) {
    case Dialect::Sinumerik:
        return "sinumerik";
    case Dialect::Heidenhain:
        return "heidenhain";
    case Dialect::Iso:
        return "iso";
    }
    return "iso";
}

std::optional<Dialect> dialectFromName(std::string_view name)
{
    const std::string n = lower(name);
    if (n == "sinumerik" || n == "siemens")
        return Dialect::Sinumerik;
    if (n == "heidenhain" || n == "klartext")
        return Dialect::Heidenhain;
    if (n == "iso" || n == "linuxcnc" || n == "fanuc")
        return Dialect::Iso;
    return std::nullopt;
}

Dialect guessDialect(std::string_view text, std::string_view path)
{
    const std::string name = lower(path);
    if (endsWith(name, ".h"))
        return Dialect::Heidenhain;
    if (endsWith(name, ".mpf") || endsWith(name, ".spf"))
        return Dialect::Sinumerik;
    // The content decides for .nc, .txt and the rest: the first 64 KiB are enough.
    const std::string head = upperPrefix(text, 64 * 1024);
    if (head.find("BEGIN PGM") != std::string::npos || head.find("TOOL CALL") != std::string::npos)
        return Dialect::Heidenhain;
    static const char* const sinumerikWords[] = {"CYCLE8", "MCALL", "PROC ", "G710",     "G700",    "DIAMON", "DIAMOF",
                                                 "M17",    "CR=",   "AR=",   "DEF REAL", "DEF INT", "TRAORI", "LIMS=",
                                                 "GOTOF",  "GOTOB", "ENDIF", "ENDWHILE", "G500"};
    for (const char* word : sinumerikWords)
        if (head.find(word) != std::string::npos)
            return Dialect::Sinumerik;
    // An R parameter assigned at the start of a block word ("R1=", " R12 =") is Sinumerik.
    for (std::size_t i = head.find('R'); i != std::string::npos; i = head.find('R', i + 1)) {
        if (i > 0 && std::isalnum(static_cast<unsigned char>(head[i - 1])))
            continue;
        std::size_t j = i + 1;
        while (j < head.size() && std::isdigit(static_cast<unsigned char>(head[j])))
            ++j;
        if (j == i + 1)
            continue;
        while (j < head.size() && head[j] == ' ')
            ++j;
        if (j < head.size() && head[j] == '=')
            return Dialect::Sinumerik;
    }
    if (endsWith(name, ".ngc") || endsWith(name, ".tap"))
        return Dialect::Iso;
    // ';' comments without parentheses comments: Siemens style.
    if (head.find(';') != std::string::npos && head.find('(') == std::string::npos)
        return Dialect::Sinumerik;
    return Dialect::Iso;
}

}  // namespace camwb::nc
