// A CL tool as the simulator cuts with it: the cutter revolved from the tool's profile (flat, ball,
// bull-nose, drill, chamfer) up to the flute length, the shank above it up to the stick-out and
// the holder above that, so a stock can tell what the flutes cut from what the shank or holder hits.
// Heights are measured from the tip along the tool axis, radii from the axis.
#pragma once

#include "base/Vec.h"
#include "toolpath/ClRecords.h"

#include <string>
#include <vector>

namespace camwb::sim {

using base::Vec3;

// One cylinder of a holder, from its lower face upwards.
struct HolderStep {
    double diameterMm = 0;
    double lengthMm = 0;
};

// A holder's revolved shape (the collet nut first). CL tools name their holder but give no
// geometry, so a small table gives a typical shape per name; an unknown name or none gets the
// default (an ER32 nut on a 70 mm gauge length) and `fromTable` false so a report can say so.
struct HolderShape {
    std::string name;
    std::vector<HolderStep> steps;
    bool fromTable = false;
    double lengthMm() const;
};
HolderShape holderShape(const std::string& name);

enum class ToolPart { Cutter, Shank, Holder };

// The interval [s0, s1] of a line origin + s * dir that lies inside a part (empty: s0 > s1).
struct LineSpan {
    double s0 = 1, s1 = 0;
    bool empty() const { return s0 > s1; }
};

class ToolShape {
public:
    explicit ToolShape(const toolpath::Tool& tool);

    const toolpath::Tool& tool() const { return m_tool; }
    double radiusMm() const { return m_radius; }            // the cutter's
    double fluteLengthMm() const { return m_flute; }        // the cutter ends here
    double stickOutMm() const { return m_stickOut; }        // the shank ends (the holder starts) here
    double shankRadiusMm() const { return m_shankRadius; }  // the tool's radius: no shank data in the CL
    const HolderShape& holder() const { return m_holder; }
    double holderRadiusMm() const;    // the widest step
    double totalLengthMm() const;     // tip to the holder's top
    double boundingRadiusMm() const;  // the widest of cutter, shank and holder
    bool flatBottomed() const { return m_coneSlope == 0 && m_corner == 0; }
    double cornerRadiusMm() const { return m_corner; }  // ball: the radius; flat and pointed: 0
    double coneSlope() const { return m_coneSlope; }    // pointed: radius per height of the point; else 0

    // Height of the cutter's lower surface above the tip at radial distance d (the z-map's view of
    // the tool); +infinity beyond the cutter's radius. Non-decreasing and convex in d for every
    // kind here (flat 0, ball and corner arcs, cone lines), which the height field relies on.
    double lowerSurface(double d) const;
    // Radius of the whole tool (cutter, shank, holder) at height h above the tip; 0 outside.
    double profileRadius(double h) const;

    // The span of the line origin + s * dir (dir unit) inside `part` with the tip at `tip` and the
    // axis `axis` (unit, tip towards spindle). Each part is a union of convex revolved pieces and
    // the span is the hull of theirs: exact for the cutter and the shank (convex solids), on the
    // safe side for a stepped holder (it may bridge air between two steps).
    LineSpan intersect(ToolPart part, const Vec3& tip, const Vec3& axis, const Vec3& origin, const Vec3& dir) const;

private:
    // A convex revolved piece: a capped cylinder, the ball's sphere, the point's cone or the
    // bull-nose's corner (a torus filled to the axis).
    struct Piece {
        enum Kind { Cylinder, Sphere, Cone, Corner } kind;
        double radius = 0;      // cylinder, sphere, the corner's tube; cone: radius per height
        double h0 = 0, h1 = 0;  // heights it spans (sphere: h0 is its centre; it is cut off at h1)
        double inner = 0;       // corner: the tube's centre circle radius
    };
    LineSpan pieceSpan(const Piece& piece, double h0, double dh, const Vec3& perp0, const Vec3& perpD) const;
    LineSpan cornerSpan(const Piece& piece, double h0, double dh, const Vec3& perp0, const Vec3& perpD) const;

    toolpath::Tool m_tool;
    HolderShape m_holder;
    double m_radius = 0, m_corner = 0, m_coneSlope = 0;  // m_coneSlope: radius per height of the point; 0: none
    double m_flute = 0, m_stickOut = 0, m_shankRadius = 0;
    std::vector<Piece> m_cutter, m_shank, m_holderPieces;
};

}  // namespace camwb::sim
