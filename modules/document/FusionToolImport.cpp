// Fusion 360 tool libraries: a JSON object whose "data" array holds the tools (and holders), each
// with "type", "unit", "geometry" (DC diameter, NOF flutes, LCF flute length, OAL overall length,
// RE corner radius, SIG point angle), "post-process" (number) and "start-values"."presets": the
// cutting data per material (v_c, f_z, n, v_f, v_f_plunge, v_f_ramp), which we keep.
#include "base/JsonRead.h"
#include "base/NumberFormat.h"
#include "document/detail/FusionTools.h"

#include <filesystem>
#include <numbers>

namespace camwb::document::detail {

using nlohmann::json;
using namespace base::jsonread;

namespace {

std::string kindOfType(const std::string& type)
{
    if (type == "flat end mill" || type == "face mill" || type == "slot mill")
        return "flat";
    if (type == "ball end mill")
        return "ball";
    if (type == "bull nose end mill" || type == "radius mill")
        return "bull";
    if (type == "drill" || type == "spot drill" || type == "center drill")
        return "drill";
    if (type == "chamfer mill" || type == "counter sink")
        return "chamfer";
    return {};
}

double optionalNumber(const json& object, const char* key, const std::string& where)
{
    return optionalMember(object, key, where) ? number(object, key, where) : 0.0;
}

// Units of the tool: lengths in inches and v_c in feet per minute when "unit" is "inches".
struct Units {
    double length = 1;  // to mm
    double speed = 1;   // to m/min
};

Units unitsOf(const json& t, const std::string& where)
{
    if (!optionalMember(t, "unit", where))
        return {};
    const std::string unit = text(t, "unit", where);
    if (unit == "millimeters")
        return {};
    if (unit == "inches")
        return {25.4, 0.3048};
    throw JsonFieldError{where + ".unit: expected \"millimeters\" or \"inches\", got \"" + unit + "\""};
}

// A preset's material: its "material"."category" when it names one, else the preset's name.
std::string presetMaterial(const json& p, const std::string& where)
{
    if (const json* m = optionalMember(p, "material", where))
        if (m->is_object() && m->contains("category") && (*m)["category"].is_string() &&
            !(*m)["category"].get<std::string>().empty())
            return (*m)["category"].get<std::string>();
    return optionalMember(p, "name", where) ? text(p, "name", where) : std::string();
}

void readPresets(const json& t, ops::ToolController& tc, const Units& u, const std::string& where)
{
    const json* start = optionalMember(t, "start-values", where);
    if (!start)
        return;
    const json* presets = optionalMember(*start, "presets", where + ".start-values");
    if (!presets)
        return;
    if (!presets->is_array())
        throw JsonFieldError{where + ".start-values.presets: expected an array"};
    for (std::size_t i = 0; i < presets->size(); ++i) {
        const std::string at = where + ".start-values.presets[" + std::to_string(i) + "]";
        const json& p = (*presets)[i];
        const double n = optionalNumber(p, "n", at);
        const double vf = optionalNumber(p, "v_f", at) * u.length;
        ops::CuttingData data;
        data.material = presetMaterial(p, at);
        if (data.material.empty())
            throw JsonFieldError{at + ": neither \"name\" nor \"material\".\"category\" names the material"};
        data.vcMPerMin = optionalNumber(p, "v_c", at) * u.speed;
        data.fzMm = optionalNumber(p, "f_z", at) * u.length;
        // Presets that give only n and v_f: their vc and fz follow from the tool.
        if (data.vcMPerMin <= 0 && n > 0)
            data.vcMPerMin = n * std::numbers::pi * tc.tool.diameterMm / 1000.0;
        if (data.fzMm <= 0 && n > 0 && vf > 0 && tc.tool.flutes > 0)
            data.fzMm = vf / (n * tc.tool.flutes);
        const double plunge = optionalNumber(p, "v_f_plunge", at) * u.length;
        const double ramp = optionalNumber(p, "v_f_ramp", at) * u.length;
        if (vf > 0) {
            data.plungeFraction = plunge / vf;
            data.rampFraction = ramp / vf;
        }
        // The first preset's speeds become the tool's own, as Fusion starts a new operation with them.
        if (i == 0) {
            tc.spindleRpm = n;
            tc.cuttingFeedMmPerMin = vf;
            tc.plungeFeedMmPerMin = plunge;
            tc.rampFeedMmPerMin = ramp;
        }
        tc.cuttingData.push_back(std::move(data));
    }
}

ops::ToolController readFusionTool(const json& t, int index, const Units& u, const std::string& where)
{
    ops::ToolController tc;
    tc.tool.kind = kindOfType(text(t, "type", where));
    const json& g = member(t, "geometry", where);
    const std::string gw = where + ".geometry";
    tc.tool.diameterMm = number(g, "DC", gw) * u.length;
    if (!(tc.tool.diameterMm > 0))
        throw JsonFieldError{gw + ".DC: must be positive"};
    tc.tool.flutes = optionalMember(g, "NOF", gw) ? count(number(g, "NOF", gw), gw + ".NOF") : 2;
    tc.tool.fluteLengthMm = optionalNumber(g, "LCF", gw) * u.length;
    tc.tool.lengthMm = optionalNumber(g, "OAL", gw) * u.length;
    tc.tool.cornerRadiusMm = optionalNumber(g, "RE", gw) * u.length;
    if (tc.tool.kind == "drill")
        tc.tool.pointAngleDeg = optionalNumber(g, "SIG", gw);
    tc.tool.number = index + 1;
    if (const json* post = optionalMember(t, "post-process", where))
        if (optionalMember(*post, "number", where + ".post-process"))
            tc.tool.number = integer(*post, "number", where + ".post-process");
    tc.tool.name = optionalMember(t, "description", where) ? text(t, "description", where) : std::string();
    if (tc.tool.name.empty())
        tc.tool.name = text(t, "type", where) + " D" + base::formatGeneral(tc.tool.diameterMm, 6);
    if (const json* holder = optionalMember(t, "holder", where))
        if (holder->is_object() && holder->contains("description") && (*holder)["description"].is_string())
            tc.tool.holder = (*holder)["description"].get<std::string>();
    readPresets(t, tc, u, where);
    return tc;
}

}  // namespace

ImportedTools readFusionLibrary(const json& root, const std::string& path)
{
    ImportedTools out;
    out.library.name = std::filesystem::path(path).stem().string();
    const json& data = member(root, "data", "library");
    if (!data.is_array())
        throw JsonFieldError{"library.data: expected an array"};
    for (std::size_t i = 0; i < data.size(); ++i) {
        const std::string where = "library.data[" + std::to_string(i) + "]";
        const std::string type = text(data[i], "type", where);
        if (kindOfType(type).empty()) {
            out.notes.push_back(where + " left out: type \"" + type + "\" is not a kind CAM Workbench models");
            continue;
        }
        out.library.tools.push_back(readFusionTool(data[i], static_cast<int>(i), unitsOf(data[i], where), where));
    }
    return out;
}

}  // namespace camwb::document::detail
