// Line differences of two NC programs for a side-by-side view (the editor's Compare dialog):
// Myers' O(ND) diff in linear space on hashed lines, rows that pair removed and added lines as
// "changed", and hunks to step through. Optionally blind to block numbers and blanks, so a
// renumbered program compares equal to its original.
#pragma once

#include "nc/Dialect.h"

#include <string_view>
#include <vector>

namespace camwb::nc {

enum class DiffKind { Equal, Removed, Added, Changed };

// One row of the side-by-side view. Lines are 1-based; 0 = nothing on that side (a gap).
struct DiffRow {
    DiffKind kind = DiffKind::Equal;
    int leftLine = 0;
    int rightLine = 0;
};

// A run of rows that are not Equal.
struct DiffHunk {
    int firstRow = 0;  // index into LineDiff::rows
    int rowCount = 0;
    int leftStart = 0;  // first left line of the hunk (1-based), or the left line it follows when none
    int leftCount = 0;
    int rightStart = 0;
    int rightCount = 0;
};

struct LineDiff {
    std::vector<DiffRow> rows;
    std::vector<DiffHunk> hunks;
    bool identical() const { return hunks.empty(); }
};

struct DiffOptions {
    Dialect dialect = Dialect::Iso;  // how block numbers look
    bool ignoreBlockNumbers = false;
    bool ignoreWhitespace = false;  // all blanks, and the case of letters outside comments stays significant
};

LineDiff diffLines(std::string_view left, std::string_view right, const DiffOptions& options = {});

}  // namespace camwb::nc
