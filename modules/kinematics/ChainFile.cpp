#include "kinematics/detail/ChainFile.h"

#include <cmath>

namespace camwb::kinematics::detail {

using namespace base::jsonread;

namespace {

ChainType chainType(const std::string& text, const std::string& where)
{
    if (text == "table-table")
        return ChainType::TableTable;
    if (text == "head-table")
        return ChainType::HeadTable;
    if (text == "head-head")
        return ChainType::HeadHead;
    throw JsonFieldError{where + ".type: expected \"table-table\", \"head-table\" or \"head-head\""};
}

RotaryJoint readJoint(const Json& j, const std::string& where, const Machine& machine)
{
    RotaryJoint joint;
    joint.axis = text(j, "axis", where);
    const Axis* axis = machine.axis(joint.axis);
    if (axis == nullptr || !axis->rotary)
        throw JsonFieldError{where + ".axis: " + joint.axis + " is not a rotary axis of the machine's \"axes\""};
    const std::string on = text(j, "on", where);
    if (on != "table" && on != "head")
        throw JsonFieldError{where + ".on: expected \"table\" or \"head\""};
    joint.onTable = on == "table";
    joint.direction = vec3(j, "direction", where);
    const double length = joint.direction.length();
    if (length < 1e-9)
        throw JsonFieldError{where + ".direction: a zero vector has no direction"};
    joint.direction = joint.direction * (1 / length);
    joint.pivot = optionalMember(j, "pivot", where) ? vec3(j, "pivot", where) : Vec3{};
    return joint;
}

}  // namespace

KinematicChain readKinematicChain(const Json& k, const std::string& where, const Machine& machine)
{
    KinematicChain chain;
    chain.type = chainType(text(k, "type", where), where);
    const Json& joints = member(k, "rotaries", where);
    if (!joints.is_array() || joints.size() != 2)
        throw JsonFieldError{where + ".rotaries: expected the machine's two rotary axes"};
    for (std::size_t i = 0; i < joints.size(); ++i)
        chain.joints.push_back(readJoint(joints[i], where + ".rotaries[" + std::to_string(i) + "]", machine));
    if (chain.joints[0].axis == chain.joints[1].axis)
        throw JsonFieldError{where + ".rotaries: axis " + chain.joints[0].axis + " twice"};
    const int onTable = int(chain.joints[0].onTable) + int(chain.joints[1].onTable);
    const int expected = chain.type == ChainType::TableTable ? 2 : chain.type == ChainType::HeadTable ? 1 : 0;
    if (onTable != expected)
        throw JsonFieldError{where + ".rotaries: a " + name(chain.type) + " chain has " + std::to_string(expected) +
                             " table axes, this one " + std::to_string(onTable)};
    if (chain.type == ChainType::HeadTable && !chain.joints[0].onTable)
        throw JsonFieldError{where + ".rotaries: list the table axis first, then the head axis"};
    const Vec3 d0 = chain.joints[0].direction, d1 = chain.joints[1].direction;
    if (d0.cross(d1).length() < 1e-6)
        throw JsonFieldError{where + ".rotaries: the two axes are parallel and cannot point a tool"};
    chain.workpieceZero = optionalMember(k, "workpieceZero", where) ? vec3(k, "workpieceZero", where) : Vec3{};
    if (const Json* preferred = optionalMember(k, "preferred", where)) {
        const std::string at = where + ".preferred";
        const std::string axis = text(*preferred, "axis", at);
        for (std::size_t i = 0; i < 2; ++i) {
            if (chain.joints[i].axis == axis)
                chain.preferredJoint = static_cast<int>(i);
        }
        if (chain.preferredJoint < 0)
            throw JsonFieldError{at + ".axis: " + axis + " is not one of the chain's rotaries"};
        const std::string sign = text(*preferred, "sign", at);
        if (sign != "positive" && sign != "negative")
            throw JsonFieldError{at + ".sign: expected \"positive\" or \"negative\""};
        chain.preferredSign = sign == "positive" ? 1 : -1;
    }
    return chain;
}

}  // namespace camwb::kinematics::detail
