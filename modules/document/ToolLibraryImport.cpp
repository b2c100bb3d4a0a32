#include "document/ToolLibraryImport.h"

#include "base/AtomicFile.h"
#include "base/JsonRead.h"
#include "document/detail/FusionTools.h"
#include "document/detail/ZipJson.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <utility>

namespace camwb::document {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace base::jsonread;

namespace {

// FreeCAD writes quantities as text with a unit: "6.0000 mm", "0.25 in", "118.0000 °". Plain
// numbers are taken as they are (FreeCAD's Flutes).
double quantity(const json& value, const std::string& where, bool angle)
{
    if (value.is_number())
        return value.get<double>();
    if (!value.is_string())
        throw JsonFieldError{where + ": expected a quantity such as \"6.00 mm\""};
    const std::string text = value.get<std::string>();
    // from_chars, not strtod: the point is a point whatever the C locale (the GUI's follows the
    // user's, where strtod reads "6.35 mm" as 6 and ".35 mm").
    const char* begin = text.data() + std::min(text.find_first_not_of(' '), text.size());
    if (*begin == '+')
        ++begin;
    double number = 0;
    const auto [end, ec] = std::from_chars(begin, text.data() + text.size(), number);
    if (ec != std::errc() || !std::isfinite(number))  // from_chars also reads "inf" and "nan"
        throw JsonFieldError{where + ": expected a quantity such as \"6.00 mm\", got \"" + text + "\""};
    std::string unit(end);
    unit.erase(0, unit.find_first_not_of(' '));
    unit.erase(unit.find_last_not_of(' ') + 1);
    if (angle && (unit.empty() || unit == "°" || unit == "deg"))
        return number;
    if (!angle && (unit.empty() || unit == "mm"))
        return number;
    if (!angle && unit == "cm")
        return number * 10;
    if (!angle && (unit == "in" || unit == "\""))
        return number * 25.4;
    throw JsonFieldError{where + ": unknown unit \"" + unit + "\" in \"" + text + "\""};
}

// A parameter from "parameter" or "attribute" (FreeCAD puts Flutes in either); nullptr if absent.
const json* bitValue(const json& bit, const char* key, const std::string& where)
{
    for (const char* section : {"parameter", "attribute"})
        if (const json* s = optionalMember(bit, section, where))
            if (const json* v = optionalMember(*s, key, where + "." + section))
                return v;
    return nullptr;
}

// FreeCAD's shape file names what the bit is; our kinds are what the operations and simulator know.
std::string kindOfShape(std::string shape)
{
    shape = fs::path(shape).stem().string();
    if (shape == "endmill")
        return "flat";
    if (shape == "ballend")
        return "ball";
    if (shape == "bullnose")
        return "bull";
    if (shape == "drill")
        return "drill";
    if (shape == "chamfer" || shape == "v-bit")
        return "chamfer";
    return {};
}

ops::ToolController readBit(const json& bit, int number, const std::string& where)
{
    ops::ToolController tc;
    tc.tool.number = number;
    tc.tool.name = text(bit, "name", where);
    tc.tool.kind = kindOfShape(text(bit, "shape", where));
    const auto length = [&](const char* key) {
        const json* v = bitValue(bit, key, where);
        return v ? quantity(*v, where + "." + key, false) : 0.0;
    };
    const json* diameter = bitValue(bit, "Diameter", where);
    if (!diameter)
        throw JsonFieldError{where + ": missing \"Diameter\" in \"parameter\""};
    tc.tool.diameterMm = quantity(*diameter, where + ".Diameter", false);
    if (!(tc.tool.diameterMm > 0))
        throw JsonFieldError{where + ".Diameter: must be positive"};
    tc.tool.fluteLengthMm = length("CuttingEdgeHeight");
    tc.tool.lengthMm = length("Length");
    if (const json* flutes = bitValue(bit, "Flutes", where))
        tc.tool.flutes = count(quantity(*flutes, where + ".Flutes", false), where + ".Flutes");
    if (const json* tip = bitValue(bit, "TipAngle", where))
        tc.tool.pointAngleDeg = quantity(*tip, where + ".TipAngle", true);
    else if (const json* edge = bitValue(bit, "CuttingEdgeAngle", where))
        tc.tool.pointAngleDeg = quantity(*edge, where + ".CuttingEdgeAngle", true);
    if (tc.tool.kind == "ball")
        tc.tool.cornerRadiusMm = tc.tool.diameterMm / 2;
    else if (bitValue(bit, "CornerRadius", where))
        tc.tool.cornerRadiusMm = length("CornerRadius");
    else if (bitValue(bit, "FlatRadius", where))  // bull nose: the flat bottom's radius
        tc.tool.cornerRadiusMm = tc.tool.diameterMm / 2 - length("FlatRadius");
    return tc;
}

// FreeCAD keeps bits in a "Bit" folder beside the "Library" one; a library names them relative
// to itself ("../Bit/x.fctb") or by file name only.
fs::path findBit(const fs::path& libraryDir, const std::string& path)
{
    const fs::path given(path);
    for (const fs::path& candidate :
         {given.is_absolute() ? given : libraryDir / given, libraryDir / ".." / "Bit" / given})
        if (fs::is_regular_file(candidate))
            return candidate.lexically_normal();
    return {};
}

ImportedTools readFreeCadLibrary(const json& root, const std::string& path)
{
    ImportedTools out;
    out.library.name = fs::path(path).stem().string();
    const fs::path dir = fs::absolute(path).parent_path();
    const json& tools = member(root, "tools", "library");
    if (!tools.is_array())
        throw JsonFieldError{"library.tools: expected an array"};
    for (std::size_t i = 0; i < tools.size(); ++i) {
        const std::string where = "library.tools[" + std::to_string(i) + "]";
        const int number = integer(tools[i], "nr", where);
        const std::string bitPath = text(tools[i], "path", where);
        const fs::path bitFile = findBit(dir, bitPath);
        if (bitFile.empty())
            throw JsonFieldError{where + ".path: bit file \"" + bitPath +
                                 "\" not found beside the library or in ../Bit"};
        auto content = base::readTextFile(bitFile.string());
        if (!content)
            throw JsonFieldError{where + ".path: " + content.error().toString()};
        auto bit = parse(content.value(), bitFile.string());
        if (!bit)
            throw JsonFieldError{where + ".path: " + bit.error().toString()};
        ops::ToolController tc;
        try {
            tc = readBit(bit.value(), number, "bit");
        } catch (const JsonFieldError& e) {
            throw JsonFieldError{where + ".path: " + bitFile.string() + ": " + e.message};
        }
        if (tc.tool.kind.empty()) {
            out.notes.push_back("T" + std::to_string(number) + " \"" + tc.tool.name + "\" left out: shape \"" +
                                bit.value().value("shape", "") + "\" is not a kind CAM Workbench models");
            continue;
        }
        out.library.tools.push_back(std::move(tc));
    }
    return out;
}

// The file's text and its JSON; errors name the file (and line and column of malformed JSON).
base::Result<std::pair<std::string, json>> readJsonFile(const std::string& path)
{
    auto content = base::readTextFile(path);
    if (!content)
        return content.error();
    // Fusion's .tools is a zip holding the JSON (tools.json): the JSON inside is read.
    if (content.value().rfind("PK", 0) == 0) {
        content = detail::readJsonFromZip(path);
        if (!content)
            return content.error();
    }
    auto root = parse(content.value(), path);
    if (!root)
        return root.error();
    return std::pair{std::move(content.value()), std::move(root.value())};
}

// Runs a reader that throws JsonFieldError, turning that into an error naming the file.
template <class Reader> base::Result<ImportedTools> importWith(const std::string& path, Reader read)
{
    auto file = readJsonFile(path);
    if (!file)
        return file.error();
    try {
        return read(file->second, path);
    } catch (const JsonFieldError& e) {
        return base::makeError(e.message, path);
    }
}

}  // namespace

base::Result<ImportedTools> importFreeCadLibrary(const std::string& path)
{
    return importWith(path, readFreeCadLibrary);
}

base::Result<ImportedTools> importFusionLibrary(const std::string& path)
{
    return importWith(path, detail::readFusionLibrary);
}

base::Result<ImportedTools> importToolLibrary(const std::string& path)
{
    const std::string ext = fs::path(path).extension().string();
    if (ext == ".fctl")
        return importFreeCadLibrary(path);
    if (ext == ".tools")
        return importFusionLibrary(path);
    auto file = readJsonFile(path);
    if (!file)
        return file.error();
    if (file->second.is_object() && file->second.contains("data"))
        return importFusionLibrary(path);
    auto ours = parseToolLibrary(file->first, path);
    if (!ours)
        return ours.error();
    return ImportedTools{std::move(ours.value()), {}};
}

}  // namespace camwb::document
