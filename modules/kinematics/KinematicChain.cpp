#include "kinematics/KinematicChain.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>

namespace camwb::kinematics {

namespace {

using Eigen::Vector3d;
using Rotation = Eigen::Matrix3d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;
// Below this length a vector's projection on a rotary axis' plane has no direction: the tool
// axis lies on that rotary axis (the pole), so the axis' angle is free.
constexpr double kPoleEpsilon = 1e-9;

Vector3d eigen(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 vec(const Vector3d& v) { return {v.x(), v.y(), v.z()}; }

Rotation rotation(const RotaryJoint& joint, double deg)
{
    return Eigen::AngleAxisd(deg * kDeg, eigen(joint.direction).normalized()).toRotationMatrix();
}

// A rigid motion x -> r x + t.
struct Motion {
    Rotation r = Rotation::Identity();
    Vector3d t = Vector3d::Zero();

    Vector3d apply(const Vector3d& x) const { return r * x + t; }
    Vector3d applyInverse(const Vector3d& x) const { return r.transpose() * (x - t); }
};

// The turn of `joint` by `deg` about its pivot: x -> R (x - p) + p.
Motion turn(const RotaryJoint& joint, double deg, const Vec3& pivot)
{
    Motion m;
    m.r = rotation(joint, deg);
    m.t = eigen(pivot) - m.r * eigen(pivot);
    return m;
}

Motion compose(const Motion& outer, const Motion& inner) { return {outer.r * inner.r, outer.r * inner.t + outer.t}; }

// What the table joints do to the workpiece (workpiece coordinates about workpieceZero -> machine).
Motion tableMotion(const KinematicChain& chain, const std::array<double, 2>& deg)
{
    Motion m;
    for (std::size_t i = 0; i < chain.joints.size(); ++i) {
        const RotaryJoint& joint = chain.joints[i];
        if (joint.onTable)
            m = compose(m, turn(joint, deg[i], joint.pivot));
    }
    Motion shift;
    shift.t = eigen(chain.workpieceZero);
    return compose(m, shift);
}

// What the head joints do to the tool, with the linear axes at zero: its tip starts at the origin
// and its gauge point at (0, 0, toolLength).
Motion headMotion(const KinematicChain& chain, const std::array<double, 2>& deg, double toolLengthMm)
{
    Motion m;
    for (std::size_t i = 0; i < chain.joints.size(); ++i) {
        const RotaryJoint& joint = chain.joints[i];
        if (!joint.onTable)
            m = compose(m, turn(joint, deg[i], joint.pivot + Vec3{0, 0, toolLengthMm}));
    }
    return m;
}

// The signed angle (degrees) that turns `from` onto `to` about unit `axis`, both projected on the
// plane normal to it; nullopt when either projection has no direction.
std::optional<double> angleAbout(const Vector3d& axis, const Vector3d& from, const Vector3d& to)
{
    const Vector3d f = from - axis * axis.dot(from);
    const Vector3d t = to - axis * axis.dot(to);
    if (f.norm() < kPoleEpsilon || t.norm() < kPoleEpsilon)
        return std::nullopt;
    return std::atan2(axis.dot(f.cross(t)), f.dot(t)) / kDeg;
}

// The angle in degrees between `v` and the line along unit `u` (0 .. 90).
double angleToLine(const Vector3d& v, const Vector3d& u)
{
    return std::atan2(v.cross(u).norm(), std::abs(v.dot(u))) / kDeg;
}

double wrap180(double deg)
{
    double w = std::remainder(deg, 360.0);
    if (w <= -180)
        w += 360;
    return w;
}

// The orientation equation of every chain written as R(u1, θ1) · R(u2, θ2) · p = q (Paden and
// Kahan's second subproblem); `flip1` says θ1 is the negated angle of its joint.
struct OrientationProblem {
    Vector3d u1, u2, p, q;
    bool flip1 = false;
};

OrientationProblem orientationProblem(const KinematicChain& chain, const Vector3d& toolAxis)
{
    const Vector3d d1 = eigen(chain.joints[0].direction).normalized();
    const Vector3d d2 = eigen(chain.joints[1].direction).normalized();
    const Vector3d z = Vector3d::UnitZ();
    switch (chain.type) {
    case ChainType::TableTable:  // z = R1 R2 a: the table turns the workpiece's tool axis onto Z
        return {d1, d2, toolAxis, z, false};
    case ChainType::HeadTable:  // Rh z = Rt a, so R(dt, -θt) R(dh, θh) z = a
        return {d1, d2, z, toolAxis, true};
    case ChainType::HeadHead:  // R1 R2 z = a
    case ChainType::ThreeAxis:
        break;
    }
    return {d1, d2, z, toolAxis, false};
}

}  // namespace

const char* name(ChainType type)
{
    switch (type) {
    case ChainType::ThreeAxis:
        return "three-axis";
    case ChainType::TableTable:
        return "table-table";
    case ChainType::HeadTable:
        return "head-table";
    case ChainType::HeadHead:
        return "head-head";
    }
    return "?";
}

ToolPose forwardKinematics(const KinematicChain& chain, const MachinePose& pose, double toolLengthMm)
{
    const Motion table = tableMotion(chain, pose.rotaryDeg);
    const Motion head = headMotion(chain, pose.rotaryDeg, toolLengthMm);
    const Vector3d tipMachine = eigen(pose.linear) + head.t;
    const Vector3d axisMachine = head.r * Vector3d::UnitZ();
    return {vec(table.applyInverse(tipMachine)), vec(table.r.transpose() * axisMachine)};
}

std::array<double, 2> tipRadii(const KinematicChain& chain, const MachinePose& pose, double toolLengthMm)
{
    std::array<double, 2> radii{0, 0};
    const Vector3d tip = eigen(pose.linear) + headMotion(chain, pose.rotaryDeg, toolLengthMm).t;
    // Each axis where the joints outside it (nearer the machine frame on its side) have carried
    // it: a table axis in machine coordinates, a head axis beside the linear axes' position.
    Motion table, head;
    for (std::size_t i = 0; i < chain.joints.size() && i < 2; ++i) {
        const RotaryJoint& joint = chain.joints[i];
        const Vector3d direction = eigen(joint.direction).normalized();
        Vector3d point, axis;
        if (joint.onTable) {
            point = table.apply(eigen(joint.pivot));
            axis = table.r * direction;
            table = compose(table, turn(joint, pose.rotaryDeg[i], joint.pivot));
        } else {
            const Vec3 pivot = joint.pivot + Vec3{0, 0, toolLengthMm};
            point = eigen(pose.linear) + head.apply(eigen(pivot));
            axis = head.r * direction;
            head = compose(head, turn(joint, pose.rotaryDeg[i], pivot));
        }
        radii[i] = (tip - point).cross(axis).norm();
    }
    return radii;
}

TiltedAxes tiltedAxes(const KinematicChain& chain, const std::array<double, 2>& rotaryDeg)
{
    // A direction turned by the head, then seen from the turned workpiece (the tool's length moves
    // points, not directions).
    const Rotation r = tableMotion(chain, rotaryDeg).r.transpose() * headMotion(chain, rotaryDeg, 0).r;
    return {vec(r * Vector3d::UnitX()), vec(r * Vector3d::UnitZ())};
}

RigidMotion machineFrameMotion(const KinematicChain& chain, const std::array<double, 2>& rotaryDeg)
{
    const Motion table = tableMotion(chain, rotaryDeg);
    RigidMotion m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            m.rotation[static_cast<std::size_t>(3 * r + c)] = table.r(r, c);
    m.translation = vec(table.t) - chain.workpieceZero;
    return m;
}

Vec3 linearAxesFor(const KinematicChain& chain, const Vec3& tip, const std::array<double, 2>& rotaryDeg,
                   double toolLengthMm)
{
    // A chain without rotary joints only shifts the workpiece to its zero: the same sum the
    // motions below make (their identity products are exact), without composing them per call.
    if (chain.joints.empty())
        return tip + chain.workpieceZero;
    const Motion table = tableMotion(chain, rotaryDeg);
    const Motion head = headMotion(chain, rotaryDeg, toolLengthMm);
    return vec(table.apply(eigen(tip)) - head.t);
}

std::vector<IkSolution> inverseKinematics(const KinematicChain& chain, const ToolPose& tool,
                                          const std::array<double, 2>& freeAngleDeg, double toolLengthMm)
{
    std::vector<IkSolution> out = inverseOrientation(chain, tool.axis, freeAngleDeg);
    for (IkSolution& solution : out)
        solution.pose.linear = linearAxesFor(chain, tool.tip, solution.pose.rotaryDeg, toolLengthMm);
    return out;
}

std::vector<IkSolution> inverseOrientation(const KinematicChain& chain, const Vec3& toolAxis,
                                           const std::array<double, 2>& freeAngleDeg)
{
    std::vector<IkSolution> out;
    if (!chain.fiveAxis())
        return out;
    const Vector3d axis = eigen(toolAxis).normalized();
    const OrientationProblem op = orientationProblem(chain, axis);
    // θ1 and θ2 such that R(u1, θ1) R(u2, θ2) p = q: the vector c = R(u2, θ2) p = R(u1, -θ1) q lies on
    // both cones, u1·c = u1·q and u2·c = u2·p; c = α u1 + β u2 + γ u1×u2.
    const double s = op.u1.dot(op.u2);
    const double det = 1 - s * s;
    if (det < 1e-12)
        return out;  // parallel rotary axes cannot point a tool
    const double a = (op.u1.dot(op.q) - s * op.u2.dot(op.p)) / det;
    const double b = (op.u2.dot(op.p) - s * op.u1.dot(op.q)) / det;
    const Vector3d inPlane = a * op.u1 + b * op.u2;
    const Vector3d normal = op.u1.cross(op.u2);
    const double g2 = (1 - inPlane.squaredNorm()) / normal.squaredNorm();
    if (g2 < -1e-9)
        return out;  // a direction these axes cannot reach
    const double g = std::sqrt(std::max(0.0, g2));
    const double fromPole1 = angleToLine(op.p, op.u2);  // on it, joint 2's angle is free
    const double fromPole0 = angleToLine(op.q, op.u1);  // on it, joint 1's angle is free
    const int poleJoint = fromPole1 <= fromPole0 ? 1 : 0;
    const double signs[2] = {1, -1};
    for (int k = 0; k < (g > 1e-12 ? 2 : 1); ++k) {
        const Vector3d c = (inPlane + signs[k] * g * normal).normalized();
        IkSolution solution;
        std::array<double, 2>& deg = solution.pose.rotaryDeg;
        auto theta1 = angleAbout(op.u1, c, op.q);  // R(u1, θ1) c = q
        auto theta2 = angleAbout(op.u2, op.p, c);  // R(u2, θ2) p = c
        if (!theta2) {  // p on u2: joint 2 is free; keep its angle, then joint 1 turns p onto q
            solution.pole = 1;
            deg[1] = freeAngleDeg[1];
            theta1 = angleAbout(op.u1, op.p, op.q);
            deg[0] = theta1 ? (op.flip1 ? -*theta1 : *theta1) : freeAngleDeg[0];
        } else if (!theta1) {  // q on u1: joint 1 is free
            solution.pole = 0;
            deg[0] = freeAngleDeg[0];
            const Vector3d onCone = rotation(chain.joints[0], op.flip1 ? deg[0] : -deg[0]) * op.q;
            theta2 = angleAbout(op.u2, op.p, onCone);
            deg[1] = theta2 ? *theta2 : freeAngleDeg[1];
        } else {
            deg[0] = op.flip1 ? -*theta1 : *theta1;
            deg[1] = *theta2;
        }
        for (int i = 0; i < 2; ++i) {
            if (i != solution.pole)
                deg[i] = wrap180(deg[i]);
        }
        solution.poleJoint = poleJoint;
        solution.poleDistanceDeg = std::min(fromPole0, fromPole1);
        // At the pole both signs give the same pose.
        if (k == 1 && !out.empty() && out.front().pole >= 0)
            break;
        out.push_back(solution);
    }
    return out;
}

}  // namespace camwb::kinematics
