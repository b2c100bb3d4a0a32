#include "base/JsonRead.h"

#include <climits>
#include <cmath>
#include <cstdint>

namespace camwb::base::jsonread {

namespace {

// nlohmann reports a byte offset; people want a line and column.
void lineAndColumn(const std::string& text, std::size_t offset, int& line, int& column)
{
    line = 1;
    column = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
}

}  // namespace

const Json* optionalMember(const Json& object, const char* key, const std::string& where)
{
    if (!object.is_object())
        throw JsonFieldError{where + ": expected an object"};
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const Json& member(const Json& object, const char* key, const std::string& where)
{
    const Json* value = optionalMember(object, key, where);
    if (!value)
        throw JsonFieldError{where + ": missing \"" + key + "\""};
    return *value;
}

double number(const Json& object, const char* key, const std::string& where)
{
    const Json& value = member(object, key, where);
    if (!value.is_number())
        throw JsonFieldError{where + "." + key + ": expected a number"};
    return value.get<double>();
}

int integer(const Json& object, const char* key, const std::string& where)
{
    const Json& value = member(object, key, where);
    if (!value.is_number_integer())
        throw JsonFieldError{where + "." + key + ": expected an integer"};
    const bool fits = value.is_number_unsigned()
                          ? value.get<std::uint64_t>() <= std::uint64_t(INT_MAX)
                          : value.get<std::int64_t>() >= INT_MIN && value.get<std::int64_t>() <= INT_MAX;
    if (!fits)
        throw JsonFieldError{where + "." + key + ": " + value.dump() + " is out of range"};
    return value.get<int>();
}

int count(double value, const std::string& where)
{
    // The range test first: converting a double beyond int's range to int is undefined.
    if (!(value >= 0 && value <= INT_MAX) || value != std::floor(value))
        throw JsonFieldError{where + ": expected a whole number from 0 to " + std::to_string(INT_MAX)};
    return static_cast<int>(value);
}

bool boolean(const Json& object, const char* key, const std::string& where)
{
    const Json& value = member(object, key, where);
    if (!value.is_boolean())
        throw JsonFieldError{where + "." + key + ": expected true or false"};
    return value.get<bool>();
}

std::string text(const Json& object, const char* key, const std::string& where)
{
    const Json& value = member(object, key, where);
    if (!value.is_string())
        throw JsonFieldError{where + "." + key + ": expected a string"};
    return value.get<std::string>();
}

Vec3 vec3(const Json& object, const char* key, const std::string& where)
{
    const Json& value = member(object, key, where);
    if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() ||
        !value[2].is_number())
        throw JsonFieldError{where + "." + key + ": expected [x, y, z]"};
    return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

Result<Json> parse(const std::string& content, const std::string& path)
{
    try {
        return Json::parse(content);
    } catch (const Json::parse_error& e) {
        int line = 0, column = 0;
        lineAndColumn(content, e.byte > 0 ? e.byte - 1 : 0, line, column);
        std::string reason = e.what();
        if (auto pos = reason.find("syntax error"); pos != std::string::npos)
            reason = reason.substr(pos);
        return makeError("malformed JSON: " + reason, path, line, column);
    }
}

}  // namespace camwb::base::jsonread
