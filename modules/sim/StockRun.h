// Plays a move list through a stock, move by move (a level arc's pieces as one run), and turns
// what each cut did into checks:
// rapids into stock, gouges into the design model, shank or holder in the stock, plunges of
// tools that do not cut at their centre, cutting with the spindle stopped, feed moves in air.
// The command line runs it to the end at once; the simulator dock runs it as it plays, so the
// stock it shows is always the stock at the playback's move.
#pragma once

#include "sim/Checks.h"
#include "sim/Moves.h"
#include "sim/Stock.h"
#include "sim/ToolShape.h"

#include <atomic>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <set>

namespace camwb::sim {

class StockRun {
public:
    // `moves` and `stock` must outlive the run.
    StockRun(const MoveList& moves, Stock& stock);

    // Cuts the moves up to (not including) `endMove`, or until `cancel` is set; the moves cut
    // so far stay cut. Returns the next move to cut.
    std::size_t cutTo(std::size_t endMove, const std::atomic<bool>* cancel = nullptr);
    std::size_t nextMove() const { return m_next; }
    bool finished() const { return m_next >= m_moves.moves.size(); }

    // The findings so far, with their messages.
    std::vector<Check> checks() const;
    const CheckList& checkList() const { return m_checks; }
    double removedMm3() const { return m_removedMm3; }
    double airCuttingMm() const { return m_airMm; }
    double cuttingMm() const { return m_cuttingMm; }  // feed moves that removed material

    // Removal below this is numerical noise, not a cut (a rapid that grazes the stock's top).
    double noiseMm3() const;

private:
    const ToolShape* shapeOf(int tool);
    // What moves [first, end) did, together (one move, or the pieces of one level arc).
    void judge(std::size_t first, std::size_t end, const CutResult& cut, const ToolShape& shape);

    const MoveList& m_moves;
    Stock& m_stock;
    std::map<int, std::unique_ptr<ToolShape>> m_shapes;
    std::set<int> m_shapeless;  // tools already reported without a shape
    std::size_t m_next = 0;
    std::size_t m_runStart = 0, m_runEnd = 0;  // the run of moves being cut (see cutTo)
    CutResult m_runCut;                        // what its moves cut so far did
    CheckList m_checks;
    double m_removedMm3 = 0;
    double m_airMm = 0;
    double m_cuttingMm = 0;
};

// The finished stock's deepest gouge (compare()) as an error check when no cut reported one: a
// gouge is an error wherever it is found. It names the move that last cut there, or none when no
// move did (then the stock itself lies inside the part: a blank smaller than the part).
std::optional<Check> finishedStockGouge(const Deviation& deviation, const MoveList& moves,
                                        const std::vector<Check>& checks);

// A check's message from its kind and values ("gouge 0.512 mm into the model", ...); a check
// that brought its own (machine limits) keeps it.
std::string describe(const Check& check);

}  // namespace camwb::sim
