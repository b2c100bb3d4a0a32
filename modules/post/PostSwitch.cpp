// Post choice per machine and the job's property values across a change of post.
#include "post/PostSwitch.h"

#include <algorithm>

namespace camwb::post {

bool servesControl(const PostInfo& info, const std::string& control)
{
    if (info.controls.empty() || control.empty() || control == "any")
        return true;
    return std::find(info.controls.begin(), info.controls.end(), control) != info.controls.end();
}

bool servesMachine(const PostInfo& info, const kinematics::Machine& machine)
{
    if (!info.machines.empty())
        return std::find(info.machines.begin(), info.machines.end(), machine.id) != info.machines.end();
    return servesControl(info, machine.control);
}

namespace {

// Why `to` cannot take `name` = `value` that the job had under `from`; empty when it can.
std::string refusal(const std::string& name, const std::string& value, const PostInfo& from, const PostInfo& to,
                    bool perOperationOnly)
{
    const PropertyDef* def = to.property(name);
    if (!def)
        return to.id + " has no property '" + name + "'";
    if (perOperationOnly && !def->perOperation)
        return to.id + " does not take '" + name + "' per operation";
    if (const PropertyDef* old = from.property(name); old && old->type != def->type)
        return "'" + name + "' is " + propertyTypeName(def->type) + " in " + to.id + ", " +
               propertyTypeName(old->type) + " in " + from.id;
    if (auto parsed = parsePropertyValue(*def, value); !parsed)
        return to.id + ": " + parsed.error().message;
    return {};
}

}  // namespace

PostSwitch switchPost(const std::map<std::string, std::string>& values, const PostInfo& from, const PostInfo& to,
                      bool perOperationOnly)
{
    PostSwitch result;
    for (const auto& [name, value] : values) {
        std::string reason = refusal(name, value, from, to, perOperationOnly);
        if (reason.empty())
            result.kept[name] = value;
        else
            result.dropped.push_back({name, value, std::move(reason)});
    }
    return result;
}

}  // namespace camwb::post
