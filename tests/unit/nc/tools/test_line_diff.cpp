// Line differences for the side-by-side compare: rows, hunks, options that ignore block numbers
// and blanks, and a result that reproduces both programs.
#include "nc/tools/BlockNumbers.h"
#include "nc/tools/LineDiff.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

using namespace camwb::nc;

namespace {

std::string join(const std::vector<std::string>& lines)
{
    std::string out;
    for (const std::string& l : lines)
        out += l + "\n";
    return out;
}

// Rebuilds both sides from the rows: every line exactly once, in order.
void expectCovers(const LineDiff& d, std::size_t leftLines, std::size_t rightLines)
{
    int nextLeft = 1;
    int nextRight = 1;
    for (const DiffRow& row : d.rows) {
        if (row.leftLine != 0)
            EXPECT_EQ(row.leftLine, nextLeft++);
        if (row.rightLine != 0)
            EXPECT_EQ(row.rightLine, nextRight++);
    }
    EXPECT_EQ(nextLeft - 1, int(leftLines));
    EXPECT_EQ(nextRight - 1, int(rightLines));
}

}  // namespace

TEST(LineDiff, IdenticalProgramsHaveNoHunks)
{
    const std::string a = "G0 X0\nG1 X1\nM30\n";
    const LineDiff d = diffLines(a, a);
    EXPECT_TRUE(d.identical());
    EXPECT_EQ(d.rows.size(), 3u);
}

TEST(LineDiff, FindsChangesRemovalsAndAdditions)
{
    const std::string a = join({"G0 X0", "G1 X1", "G1 X2", "G1 X3", "M5", "M30"});
    const std::string b = join({"G0 X0", "G1 X1", "G1 X2.5", "G1 X3", "G1 X4", "M30"});
    const LineDiff d = diffLines(a, b);
    ASSERT_EQ(d.hunks.size(), 2u);
    EXPECT_EQ(d.rows[d.hunks[0].firstRow].kind, DiffKind::Changed);
    EXPECT_EQ(d.rows[d.hunks[0].firstRow].leftLine, 3);
    EXPECT_EQ(d.rows[d.hunks[0].firstRow].rightLine, 3);
    EXPECT_EQ(d.hunks[1].leftStart, 5);
    EXPECT_EQ(d.hunks[1].rightStart, 5);
    expectCovers(d, 6, 6);

    const LineDiff ins = diffLines(join({"A", "C"}), join({"A", "B", "C"}));
    ASSERT_EQ(ins.hunks.size(), 1u);
    EXPECT_EQ(ins.rows[1].kind, DiffKind::Added);
    EXPECT_EQ(ins.rows[1].leftLine, 0);
    EXPECT_EQ(ins.rows[1].rightLine, 2);
    EXPECT_EQ(ins.hunks[0].leftCount, 0);
    EXPECT_EQ(ins.hunks[0].leftStart, 1);  // follows left line 1

    const LineDiff del = diffLines(join({"A", "B", "C"}), join({"A", "C"}));
    ASSERT_EQ(del.hunks.size(), 1u);
    EXPECT_EQ(del.rows[1].kind, DiffKind::Removed);
    EXPECT_EQ(del.rows[1].leftLine, 2);
}

TEST(LineDiff, IgnoresBlockNumbersAndBlanksOnRequest)
{
    const std::string a = "N10 G0 X0\nN20 G1  X1\nN30 M30\n";
    RenumberOptions ro;
    ro.start = 5;
    ro.step = 5;
    const std::string b = renumberBlocks("G0 X0\nG1 X1\nM30\n", ro).text;
    EXPECT_EQ(diffLines(a, b).hunks.size(), 1u);
    DiffOptions o;
    o.dialect = Dialect::Sinumerik;
    o.ignoreBlockNumbers = true;
    EXPECT_EQ(diffLines(a, b, o).hunks.size(), 1u);  // the double blank in line 2
    o.ignoreWhitespace = true;
    EXPECT_TRUE(diffLines(a, b, o).identical());
}

TEST(LineDiff, EmptySides)
{
    EXPECT_TRUE(diffLines("", "").identical());
    const LineDiff d = diffLines("", "A\nB\n");
    ASSERT_EQ(d.hunks.size(), 1u);
    EXPECT_EQ(d.hunks[0].rightCount, 2);
    expectCovers(d, 0, 2);
}

TEST(LineDiff, RandomEditsAreMinimalEnoughAndConsistent)
{
    std::mt19937 rng(7);
    std::vector<std::string> base;
    for (int i = 0; i < 10'000; ++i)
        base.push_back("G1 X" + std::to_string(rng() % 500) + " Y" + std::to_string(i));
    std::vector<std::string> edited = base;
    int edits = 0;
    for (int k = 0; k < 200; ++k) {
        const std::size_t at = rng() % edited.size();
        switch (rng() % 3) {
        case 0:
            edited.erase(edited.begin() + long(at));
            break;
        case 1:
            edited.insert(edited.begin() + long(at), "M0 ; inserted " + std::to_string(k));
            break;
        default:
            edited[at] = "G0 Z" + std::to_string(k);
            break;
        }
        ++edits;
    }
    const LineDiff d = diffLines(join(base), join(edited));
    expectCovers(d, base.size(), edited.size());
    int changedLines = 0;
    for (const DiffRow& r : d.rows)
        changedLines += r.kind == DiffKind::Equal ? 0 : (r.kind == DiffKind::Changed ? 2 : 1);
    EXPECT_LE(changedLines, 2 * edits);
    // Equal rows really are equal.
    for (const DiffRow& r : d.rows)
        if (r.kind == DiffKind::Equal)
            EXPECT_EQ(base[std::size_t(r.leftLine - 1)], edited[std::size_t(r.rightLine - 1)]);
}
