// Post properties and capabilities: typed values from text (command line, job file), defaults,
// and messages that say what a property accepts.
#include "base/NumberFormat.h"
#include "post/PostInfo.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace camwb::post {

namespace {

std::optional<double> parseNumber(const std::string& text)
{
    double value = 0;
    const char* begin = text.data();
    const char* end = text.data() + text.size();
    if (begin != end && *begin == '+')
        ++begin;
    const auto result = std::from_chars(begin, end, value);
    if (result.ec != std::errc() || result.ptr != end || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::string join(const std::vector<std::string>& items)
{
    std::string text;
    for (const std::string& item : items)
        text += (text.empty() ? "" : ", ") + item;
    return text;
}

std::string numberText(double value)
{
    base::NumberFormat format{12, true};
    return format.format(value);
}

}  // namespace

bool PostCapabilities::writesCycle(const std::string& kind) const
{
    return std::find(cycles.begin(), cycles.end(), kind) != cycles.end();
}

bool PostCapabilities::writesHelix(const std::string& plane) const
{
    return std::find(helicalPlanes.begin(), helicalPlanes.end(), plane) != helicalPlanes.end();
}

const PropertyDef* PostInfo::property(const std::string& name) const
{
    for (const PropertyDef& def : properties)
        if (def.name == name)
            return &def;
    return nullptr;
}

const char* propertyTypeName(PropertyType type)
{
    switch (type) {
    case PropertyType::Bool:
        return "bool";
    case PropertyType::Integer:
        return "int";
    case PropertyType::Number:
        return "number";
    case PropertyType::Enum:
        return "enum";
    case PropertyType::String:
        break;
    }
    return "string";
}

std::optional<PropertyType> propertyTypeFromName(const std::string& name)
{
    for (PropertyType type :
         {PropertyType::Bool, PropertyType::Integer, PropertyType::Number, PropertyType::Enum, PropertyType::String})
        if (name == propertyTypeName(type))
            return type;
    return std::nullopt;
}

base::Result<PropertyValue> parsePropertyValue(const PropertyDef& def, const std::string& text)
{
    PropertyValue value;
    value.type = def.type;
    const std::string what = "property '" + def.name + "'";
    switch (def.type) {
    case PropertyType::Bool:
        if (text == "true" || text == "1" || text == "yes" || text == "on")
            value.boolean = true;
        else if (text == "false" || text == "0" || text == "no" || text == "off")
            value.boolean = false;
        else
            return base::makeError(what + " is a bool: use true or false, not '" + text + "'");
        value.text = value.boolean ? "true" : "false";
        return value;
    case PropertyType::Integer:
    case PropertyType::Number: {
        const std::optional<double> number = parseNumber(text);
        const bool integer = def.type == PropertyType::Integer;
        if (!number || (integer && *number != std::floor(*number)))
            return base::makeError(what + " is " + (integer ? "an integer" : "a number") + ", not '" + text + "'");
        if ((def.min && *number < *def.min) || (def.max && *number > *def.max))
            return base::makeError(what + " must be in " + (def.min ? numberText(*def.min) : "-inf") + ".." +
                                   (def.max ? numberText(*def.max) : "inf") + ", not " + text);
        value.number = *number;
        value.text = numberText(*number);
        return value;
    }
    case PropertyType::Enum:
        if (std::find(def.values.begin(), def.values.end(), text) == def.values.end())
            return base::makeError(what + " is one of " + join(def.values) + ", not '" + text + "'");
        value.text = text;
        return value;
    case PropertyType::String:
        value.text = text;
        return value;
    }
    return value;
}

base::Result<std::map<std::string, PropertyValue>>
resolveProperties(const PostInfo& info, const std::map<std::string, std::string>& userValues)
{
    std::map<std::string, PropertyValue> values;
    for (const auto& [name, text] : userValues) {
        const PropertyDef* def = info.property(name);
        if (!def) {
            std::vector<std::string> known;
            for (const PropertyDef& d : info.properties)
                known.push_back(d.name);
            return base::makeError("post " + info.id + " has no property '" + name + "'" +
                                   (known.empty() ? std::string(" (it has none)") : "; it has: " + join(known)));
        }
        auto value = parsePropertyValue(*def, text);
        if (!value)
            return value.error();
        value->fromUser = true;
        values[name] = value.value();
    }
    for (const PropertyDef& def : info.properties) {
        if (values.count(def.name))
            continue;
        auto value = parsePropertyValue(def, def.defaultValue);
        if (!value)  // checked when the post was loaded; kept as a guard
            return base::makeError("default of " + value.error().message, info.filePath, def.line);
        values[def.name] = value.value();
    }
    return values;
}

base::Result<std::pair<std::string, std::string>> splitPropertyAssignment(const std::string& text)
{
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0)
        return base::makeError("expected --property name=value, got '" + text + "'");
    return std::pair{text.substr(0, equals), text.substr(equals + 1)};
}

}  // namespace camwb::post
