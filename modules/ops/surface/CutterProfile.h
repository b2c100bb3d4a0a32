// The lower surface of a revolved cutter grown by the stock to leave, as the drop-cutter needs it:
// a few convex pieces (flat, arcs, cone lines) of height against radial distance, measured from
// the ungrown tool's tip, with the exact point where its slope matches a plane's.
#pragma once

#include "sim/ToolShape.h"

#include <array>

namespace camwb::ops::surface {

class CutterProfile {
public:
    // The tool's cutter (sim::ToolShape's reading of flat, ball, bull, drill, chamfer) grown by
    // `stockMm` all round: the Minkowski sum with a ball, exact for every kind.
    CutterProfile(const sim::ToolShape& shape, double stockMm);

    double radius() const { return m_radius; }  // of the grown cutter
    double lowest() const { return m_lowest; }  // height at the axis (minus the stock)
    // Height above the ungrown tip at radial distance d; +infinity beyond radius().
    double height(double d) const;
    // The d in [0, radius()] where slope * d - height(d) is largest (the contact with a plane of
    // that slope, measured from the axis along the plane's rise).
    double planeContact(double slope) const;
    // A flat bottom without stock (height 0 all over) or a single sphere centred on the axis: the
    // drop-cutter has closed forms for the edges of these.
    bool isFlat() const { return m_count == 1 && m_pieces[0].kind == Piece::Line && m_pieces[0].slope == 0; }
    bool isSphere() const { return m_count == 1 && m_pieces[0].kind == Piece::Arc && m_pieces[0].cd == 0; }
    double sphereRadius() const { return m_pieces[0].r; }
    double sphereCentre() const { return m_pieces[0].cz; }  // height of the centre above the tip

private:
    // A line z = z0 + slope * (d - d0) or the lower half of a circle around (cd, cz), on [d0, d1].
    struct Piece {
        enum Kind { Line, Arc } kind = Line;
        double d0 = 0, d1 = 0;
        double z0 = 0, slope = 0;
        double cd = 0, cz = 0, r = 0;
        double at(double d) const;
    };
    void add(const Piece& piece) { m_pieces[m_count++] = piece; }

    std::array<Piece, 3> m_pieces{};
    int m_count = 0;
    double m_radius = 0, m_lowest = 0;
};

}  // namespace camwb::ops::surface
