// Private: Clipper decides the topology of an offset, the exact pieces give its geometry. The raw
// offset pieces are discretised into Clipper paths whose vertices remember their piece; a contour
// of the union is then walked back onto the pieces (new vertices, where loops crossed, become the
// exact crossing of the two pieces), so the result is exact lines and arcs without arc fitting.
#pragma once

#include "geom/detail/ClipperRegions.h"
#include "geom/detail/RawOffset.h"

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace camwb::geom::detail {

class PieceSnap {
public:
    // `raw` must outlive this. Arcs are split into chords within `chordTolerance`.
    PieceSnap(const RawLoops& raw, double chordTolerance);

    bool inRange() const { return m_inRange; }
    const ClipperLib::Paths& paths() const { return m_paths; }

    // The contour (a loop of the union of paths()) as exact lines and arcs of the pieces, in the
    // contour's direction; nullopt where a vertex or an edge cannot be placed on the pieces within
    // a few chord tolerances (the caller then fits the contour instead).
    std::optional<Profile> snap(const ClipperLib::Path& contour) const;

private:
    struct Origin {
        std::size_t piece = 0;
        bool isStart = false;  // the piece's start point (so also the previous piece's end)
        Vec2 exact;
    };
    struct Key {
        ClipperLib::cInt x, y;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const
        {
            return static_cast<std::size_t>(static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ull ^
                                            static_cast<std::uint64_t>(k.y));
        }
    };
    friend class ContourWalk;

    const Origin* origin(const ClipperLib::IntPoint& p) const;
    // The piece passing within the snap tolerance of both points (an edge between two crossings),
    // looked up in horizontal bands of the pieces, built when first needed.
    std::optional<std::size_t> pieceThrough(Vec2 a, Vec2 b) const;
    void buildBands() const;
    std::size_t band(double y) const;
    bool onPiece(Vec2 p, std::size_t piece) const;

    const RawLoops& m_raw;
    double m_snapTolerance;
    double m_chordTolerance;
    bool m_inRange = true;
    ClipperLib::Paths m_paths;
    std::vector<Origin> m_origins;
    std::unordered_map<Key, int, KeyHash> m_index;          // origin index, -1 where two origins share a point
    mutable std::vector<std::vector<std::size_t>> m_bands;  // pieces per band of y
    mutable double m_minY = 0, m_bandHeight = 1;
};

}  // namespace camwb::geom::detail
