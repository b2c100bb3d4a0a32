#include "document/detail/OperationFile.h"

#include "document/detail/OperationFields.h"

#include <set>
#include <string>

namespace camwb::document::detail {

using namespace base::jsonread;
using ojson = nlohmann::ordered_json;

namespace {

const char* const kHeightKeys[] = {"clearance", "safe", "start", "final"};

std::optional<double>* heightSlot(HeightOverrides& h, int i)
{
    std::optional<double>* slots[] = {&h.clearanceZ, &h.safeZ, &h.startZ, &h.finalZ};
    return slots[i];
}

std::vector<int> indexList(const Json& object, const char* key, const std::string& where)
{
    std::vector<int> out;
    const Json* list = optionalMember(object, key, where);
    if (!list)
        return out;
    if (!list->is_array())
        throw JsonFieldError{where + "." + key + ": expected an array of indices"};
    for (const Json& v : *list) {
        if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000)
            throw JsonFieldError{where + "." + key + ": expected indices from 1, got " + v.dump()};
        out.push_back(v.get<int>());
    }
    return out;
}

// The object with each alias (fieldAliases) renamed to its field's key; both given is an error.
template <class Params> Json withoutAliases(const Params& params, const Json& object, const std::string& where)
{
    Json out = object;
    for (const FieldAlias& a : fieldAliases(params)) {
        const std::string alias(a.alias), key(a.key);
        if (!out.contains(alias))
            continue;
        if (out.contains(key))
            throw JsonFieldError{where + "." + alias + ": the same parameter as \"" + key + "\"; give one of them"};
        out[key] = out[alias];
        out.erase(alias);
    }
    return out;
}

template <class Params> void readParams(Params& params, const Json& given, const std::string& where)
{
    if (!given.is_object())
        throw JsonFieldError{where + ": expected an object"};
    const Json object = withoutAliases(params, given, where);
    std::set<std::string> known;
    visitFields(params, [&](const char* key, auto&& field) {
        known.insert(key);
        using Field = std::remove_cvref_t<decltype(field)>;
        if (!optionalMember(object, key, where))
            return;  // absent: the default
        if constexpr (kIsEnumField<Field>) {
            const std::string name = text(object, key, where);
            int i = 0;
            for (std::string_view candidate : field.names) {
                if (candidate == name) {
                    field.value = static_cast<std::remove_reference_t<decltype(field.value)>>(i);
                    return;
                }
                ++i;
            }
            std::string expected;
            for (std::string_view candidate : field.names)
                expected += (expected.empty() ? "\"" : ", \"") + std::string(candidate) + "\"";
            throw JsonFieldError{where + "." + key + ": expected one of " + expected + ", got \"" + name + "\""};
        } else if constexpr (std::is_same_v<Field, bool>) {
            field = boolean(object, key, where);
        } else if constexpr (std::is_same_v<Field, int>) {
            field = integer(object, key, where);
        } else {
            field = number(object, key, where);
        }
    });
    for (const auto& [key, value] : object.items())
        if (!known.contains(key))
            throw JsonFieldError{where + "." + key + ": unknown parameter"};
}

template <class Params> ojson writeParams(const Params& constParams)
{
    Params params = constParams;  // visitFields hands out references; a copy keeps writing const
    ojson out = ojson::object();
    visitFields(params, [&](const char* key, auto&& field) {
        using Field = std::remove_cvref_t<decltype(field)>;
        if constexpr (kIsEnumField<Field>)
            out[key] = std::string(*(field.names.begin() + static_cast<int>(field.value)));
        else
            out[key] = field;
    });
    return out;
}

OperationParams paramsOfType(const std::string& type, const std::string& where)
{
    if (type == "contour")
        return ops::ContourParams{};
    if (type == "pocket")
        return ops::PocketParams{};
    if (type == "helix")
        return ops::HelixParams{};
    if (type == "drill")
        return ops::DrillParams{};
    if (type == "swarf")
        return ops::SwarfParams{};
    if (type == "pocket3d")
        return ops::Pocket3dParams{};
    if (type == "waterline")
        return ops::WaterlineParams{};
    if (type == "parallel")
        return ops::ParallelParams{};
    if (type == "groove")
        return ops::GrooveParams{};
    throw JsonFieldError{where + ".type: unknown operation type \"" + type +
                         "\" (expected contour, pocket, helix, drill, swarf, pocket3d, waterline, parallel or groove)"};
}

// Versions 1-2: the outer profile of one face, all heights given.
Operation readLegacyProfile(const Json& o, const std::string& where)
{
    Operation op;
    ops::ContourParams p;
    p.name = text(o, "name", where);
    op.toolNumber = integer(o, "tool", where);
    op.geometry.faces = {integer(o, "face", where)};
    op.heights.finalZ = number(o, "finalDepth", where);
    op.heights.safeZ = number(o, "safeHeight", where);
    op.heights.clearanceZ = number(o, "clearanceHeight", where);
    const std::string direction = text(o, "direction", where);
    if (direction != "climb" && direction != "conventional")
        throw JsonFieldError{where + ".direction: expected \"climb\" or \"conventional\""};
    p.climb = direction == "climb";
    op.params = p;
    return op;
}

}  // namespace

// {"face": n} or {"a": A, "b": B, "c": C} (version 4).
static WorkingPlaneSpec readWorkingPlane(const Json& p, const std::string& where)
{
    WorkingPlaneSpec spec;
    if (optionalMember(p, "face", where)) {
        if (optionalMember(p, "a", where) || optionalMember(p, "b", where) || optionalMember(p, "c", where))
            throw JsonFieldError{where + ": a face or the angles a, b, c, not both"};
        spec.mode = WorkingPlaneSpec::Mode::Face;
        spec.face = integer(p, "face", where);
        if (spec.face < 1)
            throw JsonFieldError{where + ".face: expected a face number from 1"};
        return spec;
    }
    spec.mode = WorkingPlaneSpec::Mode::Angles;
    spec.aDeg = number(p, "a", where);
    spec.bDeg = number(p, "b", where);
    spec.cDeg = number(p, "c", where);
    return spec;
}

Operation readOperation(const Json& o, const std::string& where)
{
    const std::string type = text(o, "type", where);
    if (type == "profile")
        return readLegacyProfile(o, where);
    Operation op;
    op.params = paramsOfType(type, where);
    op.setName(text(o, "name", where));
    op.toolNumber = integer(o, "tool", where);
    if (const Json* geometry = optionalMember(o, "geometry", where)) {
        const std::string at = where + ".geometry";
        op.geometry.faces = indexList(*geometry, "faces", at);
        op.geometry.edges = indexList(*geometry, "edges", at);
        op.geometry.holes = indexList(*geometry, "holes", at);
    }
    if (const Json* heights = optionalMember(o, "heights", where)) {
        for (int i = 0; i < 4; ++i)
            if (optionalMember(*heights, kHeightKeys[i], where + ".heights"))
                *heightSlot(op.heights, i) = number(*heights, kHeightKeys[i], where + ".heights");
    }
    if (const Json* params = optionalMember(o, "params", where))
        std::visit([&](auto& p) { readParams(p, *params, where + ".params"); }, op.params);
    if (const Json* plane = optionalMember(o, "workingPlane", where))
        op.plane = readWorkingPlane(*plane, where + ".workingPlane");
    if (const Json* properties = optionalMember(o, "postProperties", where))
        op.postProperties = readPostProperties(*properties, where + ".postProperties");
    if (optionalMember(o, "enabled", where))
        op.enabled = boolean(o, "enabled", where);
    return op;
}

std::map<std::string, std::string> readPostProperties(const Json& object, const std::string& where)
{
    if (!object.is_object())
        throw JsonFieldError{where + ": expected an object"};
    std::map<std::string, std::string> values;
    for (const auto& [name, value] : object.items()) {
        if (value.is_string())
            values[name] = value.get<std::string>();
        else if (value.is_boolean() || value.is_number())
            values[name] = value.dump();
        else
            throw JsonFieldError{where + "." + name + ": expected a string, number or bool"};
    }
    return values;
}

ojson writeOperation(const Operation& op)
{
    ojson out;
    out["type"] = kindName(op.kind());
    out["name"] = op.name();
    out["tool"] = op.toolNumber;
    out["geometry"] = {{"faces", op.geometry.faces}, {"edges", op.geometry.edges}, {"holes", op.geometry.holes}};
    ojson heights = ojson::object();
    HeightOverrides h = op.heights;
    for (int i = 0; i < 4; ++i)
        if (const std::optional<double>& v = *heightSlot(h, i))
            heights[kHeightKeys[i]] = *v;
    out["heights"] = heights;
    out["params"] = std::visit([](const auto& p) { return writeParams(p); }, op.params);
    if (op.plane.mode == WorkingPlaneSpec::Mode::Face)
        out["workingPlane"] = {{"face", op.plane.face}};
    else if (op.plane.mode == WorkingPlaneSpec::Mode::Angles)
        out["workingPlane"] = {{"a", op.plane.aDeg}, {"b", op.plane.bDeg}, {"c", op.plane.cDeg}};
    if (!op.postProperties.empty())
        out["postProperties"] = op.postProperties;
    if (!op.enabled)
        out["enabled"] = false;
    return out;
}

void readOperationParams(Operation& op, const Json& params, const std::string& where)
{
    std::visit([&](auto& p) { readParams(p, params, where); }, op.params);
}

std::vector<std::string> operationParamNames(const Operation& op)
{
    std::vector<std::string> names;
    std::visit(
        [&](auto p) {
            visitFields(p, [&](const char* key, auto&&) { names.emplace_back(key); });
            for (const FieldAlias& a : fieldAliases(p))
                names.emplace_back(a.alias);
        },
        op.params);
    return names;
}

}  // namespace camwb::document::detail
