#include "document/detail/ToolFile.h"

#include "base/JsonRead.h"
#include "base/NumberFormat.h"

namespace camwb::document::detail {

using namespace base::jsonread;
using nlohmann::json;
using ojson = nlohmann::ordered_json;

namespace {

double positiveOrZero(const json& object, const char* key, const std::string& where)
{
    const double value = number(object, key, where);
    if (value < 0)
        throw JsonFieldError{where + "." + key + ": must not be negative, got " + base::formatGeneral(value, 6)};
    return value;
}

double optionalNumber(const json& object, const char* key, const std::string& where)
{
    return optionalMember(object, key, where) ? positiveOrZero(object, key, where) : 0.0;
}

ops::CuttingData readCuttingData(const json& c, const std::string& where)
{
    ops::CuttingData data;
    data.material = text(c, "material", where);
    if (data.material.empty())
        throw JsonFieldError{where + ".material: must not be empty"};
    data.vcMPerMin = positiveOrZero(c, "vc", where);
    data.fzMm = positiveOrZero(c, "fz", where);
    data.plungeFraction = optionalNumber(c, "plungeFraction", where);
    data.rampFraction = optionalNumber(c, "rampFraction", where);
    return data;
}

}  // namespace

ops::ToolController readTool(const json& t, const std::string& where, bool speedsRequired)
{
    ops::ToolController tc;
    tc.tool.number = integer(t, "number", where);
    tc.tool.name = text(t, "name", where);
    tc.tool.kind = text(t, "kind", where);
    tc.tool.diameterMm = number(t, "diameter", where);
    tc.tool.cornerRadiusMm = number(t, "cornerRadius", where);
    tc.tool.fluteLengthMm = number(t, "fluteLength", where);
    tc.tool.lengthMm = number(t, "length", where);
    tc.tool.flutes = integer(t, "flutes", where);
    if (speedsRequired || optionalMember(t, "spindleRpm", where))
        tc.spindleRpm = number(t, "spindleRpm", where);
    if (speedsRequired || optionalMember(t, "cuttingFeed", where))
        tc.cuttingFeedMmPerMin = number(t, "cuttingFeed", where);
    if (speedsRequired || optionalMember(t, "plungeFeed", where))
        tc.plungeFeedMmPerMin = number(t, "plungeFeed", where);
    if (optionalMember(t, "rampFeed", where))
        tc.rampFeedMmPerMin = number(t, "rampFeed", where);
    if (optionalMember(t, "pointAngle", where))
        tc.tool.pointAngleDeg = number(t, "pointAngle", where);
    if (optionalMember(t, "centreCutting", where))
        tc.tool.centreCutting = boolean(t, "centreCutting", where);
    if (optionalMember(t, "holder", where))
        tc.tool.holder = text(t, "holder", where);
    if (const json* data = optionalMember(t, "cuttingData", where)) {
        if (!data->is_array())
            throw JsonFieldError{where + ".cuttingData: expected an array"};
        for (std::size_t i = 0; i < data->size(); ++i)
            tc.cuttingData.push_back(readCuttingData((*data)[i], where + ".cuttingData[" + std::to_string(i) + "]"));
    }
    return tc;
}

ojson writeTool(const ops::ToolController& tc)
{
    ojson tool = {{"number", tc.tool.number},
                  {"name", tc.tool.name},
                  {"kind", tc.tool.kind},
                  {"diameter", tc.tool.diameterMm},
                  {"cornerRadius", tc.tool.cornerRadiusMm},
                  {"fluteLength", tc.tool.fluteLengthMm},
                  {"length", tc.tool.lengthMm},
                  {"flutes", tc.tool.flutes},
                  {"spindleRpm", tc.spindleRpm},
                  {"cuttingFeed", tc.cuttingFeedMmPerMin},
                  {"plungeFeed", tc.plungeFeedMmPerMin}};
    if (tc.rampFeedMmPerMin > 0)
        tool["rampFeed"] = tc.rampFeedMmPerMin;
    if (tc.tool.pointAngleDeg > 0)
        tool["pointAngle"] = tc.tool.pointAngleDeg;
    if (!tc.tool.centreCutting)
        tool["centreCutting"] = false;
    if (!tc.tool.holder.empty())
        tool["holder"] = tc.tool.holder;
    if (!tc.cuttingData.empty()) {
        ojson data = ojson::array();
        for (const ops::CuttingData& c : tc.cuttingData) {
            ojson entry = {{"material", c.material}, {"vc", c.vcMPerMin}, {"fz", c.fzMm}};
            if (c.plungeFraction > 0)
                entry["plungeFraction"] = c.plungeFraction;
            if (c.rampFraction > 0)
                entry["rampFraction"] = c.rampFraction;
            data.push_back(entry);
        }
        tool["cuttingData"] = data;
    }
    return tool;
}

}  // namespace camwb::document::detail
