// Private: C++ block templates, the native per-move path. A post that defines no onRapid/onLinear/
// onCircular handler declares `post.blocks` instead: word lists of literals and modal variables
// bound to move values (xOutput.bind("x")). The kernel writes those blocks in C++, sharing the
// variables' modal state with the script, so a million moves never enter the script engine.
#pragma once

#include "base/Result.h"
#include "post/OutputWriter.h"
#include "toolpath/ClRecords.h"

#include <QJSValue>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace camwb::post {

class VariableObject;
class PendingObject;

// Angle: the sweep signed by the direction (+ counter-clockwise about the plane's normal);
// Axial: the helix's rise along the normal, from the start as written to the end as written.
enum class MoveValue {
    X,
    Y,
    Z,
    I,
    J,
    K,
    CenterX,
    CenterY,
    CenterZ,
    Radius,
    Feed,
    Motion,
    Plane,
    Comp,
    Sweep,
    Angle,
    Axial,
    A,  // five-axis blocks (rapid5D, linear5D): the machine's rotary axes by name ...
    B,
    C,
    ToolX,  // ... and the tool axis in the workpiece frame (SINUMERIK's A3 B3 C3)
    ToolY,
    ToolZ
};

std::optional<MoveValue> moveValueFromName(const std::string& name);
std::string moveValueNames();  // "x, y, z, ..." for messages

// The values of one move that a template can write. Centre words (i, j, k) are measured from the
// start as written, since that is where the control believes the tool is.
struct MoveValues {
    toolpath::Vec3 start, end, center;
    toolpath::Vec3 writtenStart;  // set by BlockTemplate::write
    double radius = 0;            // signed: negative above 180 degrees when the post writes radius words
    double feed = 0;
    double sweepDeg = 0;
    double axialRise = 0;  // set by BlockTemplate::write
    int motion = 0;        // 0 rapid, 1 linear, 2 clockwise, 3 counter-clockwise (G0..G3)
    int plane = 17;        // 17 XY, 18 ZX, 19 YZ
    int comp = 40;         // 40 off, 41 left, 42 right
    int feedKind = 0;      // toolpath::FeedKind: which of the operation's feeds the move uses
    bool helical = false;
    std::array<double, 3> rotaryDeg{};  // A, B, C of a five-axis block
    toolpath::Vec3 toolAxis;            // of a five-axis block
    toolpath::AxisMask known;           // end axes the kernel knows: the others get no word (never invented)

    double value(MoveValue which) const;
};

class BlockTemplate {
public:
    struct Word {
        std::string literal;  // written as is when neither variable nor pending is set
        VariableObject* variable = nullptr;
        MoveValue value = MoveValue::X;
        bool force = false;  // bind(name, {force: true}): written in every such block
        // bind(name, {texts: {code: text}}): the text for the value's code; a code without one
        // writes no word (DR+/DR- for the motion, R0/RL/RR for the compensation).
        std::vector<std::pair<int, std::string>> texts;
        PendingObject* pending = nullptr;  // a one-shot word the script set (M3 with the first move)
    };

    std::vector<Word> words;
    std::vector<VariableObject*> forceOnHelical;  // reset before a helical block: always written
    std::array<VariableObject*, 3> axes{};        // the variables this block writes x, y and z with
    // The post's x, y and z variables from every template: the start as the control has it is
    // what they wrote (centre words and helix rises are measured from there).
    std::array<VariableObject*, 3> writtenAxes{};
    bool straight = false;            // rapid/linear: no block when no axis word changes
    std::vector<QJSValue> keepAlive;  // the script objects behind the raw pointers

    // What write() could not write as the move says.
    struct Issues {
        bool missingFeed = false;  // a feed word was left out because the feed is not positive
        std::string beyondMax;     // a value beyond its format's max ("X123456.789 beyond 99999.9999")
    };
    // Writes the block for `move`. False when nothing was written (a straight move that changes no
    // axis, or a value beyond its format's max: nothing of the block is written then).
    bool write(const MoveValues& move, OutputWriter& out, Issues& issues);
    // Bit 0 x, 1 y, 2 z: the axes this block writes with a variable.
    unsigned axisBits() const { return (axes[0] ? 1u : 0u) | (axes[1] ? 2u : 0u) | (axes[2] ? 4u : 0u); }

    // Whether the arc's end, as written, is its start in both axes of the plane (0 XY, 1 ZX,
    // 2 YZ): written so, a short arc would read back as a full circle.
    bool endsWhereItStarts(const MoveValues& move, int planeIndex) const;

private:
    // Scratch, sized once: one number buffer per word and the block being assembled, so that the
    // hot path neither allocates nor appends word by word to the output.
    std::vector<char> m_buffers;
    std::vector<std::string_view> m_texts;
    std::vector<char> m_skip;
    std::vector<char> m_block;
};

// The blocks one arc piece is written with: one (G2 X Y I J) or several (CC X Y, then C X Y DR+).
using ArcBlocks = std::vector<BlockTemplate>;

struct BlockTemplates {
    std::optional<BlockTemplate> rapid;
    std::optional<BlockTemplate> linear;
    std::optional<BlockTemplate> rapid5D;  // five-axis moves (FiveAxisWriter): x y z, a b c, toolx..
    std::optional<BlockTemplate> linear5D;
    std::array<ArcBlocks, 3> circular;   // XY, ZX, YZ; empty: none
    std::array<ArcBlocks, 3> helix;      // helical pieces, when they take other words (CP IPA IZ)
    std::vector<PendingObject*> before;  // one-shot blocks written before the next move's blocks
    std::vector<PendingObject*> after;   // one-shot blocks written after the next move's blocks
    std::vector<QJSValue> keepAlive;
    // Every variable any template writes x, y or z with: a move whose blocks leave an axis
    // unwritten though it moved resets them, so the next block writes that axis again.
    std::array<std::vector<VariableObject*>, 3> axisVariables;

    // The arc blocks for a piece in `planeIndex`: the helix ones for a helical piece if declared.
    ArcBlocks* arcBlocks(int planeIndex, bool helical);
    // Writes the pending `before` blocks (the TOOL CALL still waiting for its speed).
    void writeBeforeMove(OutputWriter& out)
    {
        if (!before.empty())  // most posts have none: no call on the per-move path
            writeBefore(out);
    }
    // After a move from `start` to `end` whose blocks bind the axes in `boundAxes` (axisBits):
    // resets the variables of the axes that moved but were not written; then writes the pending
    // `after` blocks.
    void finishMove(unsigned boundAxes, const toolpath::Vec3& start, const toolpath::Vec3& end, OutputWriter& out)
    {
        if (boundAxes != 7 || !after.empty())  // the usual block writes all axes and has nothing after it
            resetUnwrittenAndWriteAfter(boundAxes, start, end, out);
    }

    static int planeIndex(const std::string& plane);  // "XY" 0, "ZX" 1, "YZ" 2, else -1

    // Calls fn for every template block: rapid, linear, every arc and helix block.
    template <typename Fn> void forEach(Fn fn)
    {
        for (std::optional<BlockTemplate>* block : {&rapid, &linear, &rapid5D, &linear5D})
            if (*block)
                fn(**block);
        for (auto* planes : {&circular, &helix})
            for (ArcBlocks& blocks : *planes)
                for (BlockTemplate& block : blocks)
                    fn(block);
    }

private:
    void writeBefore(OutputWriter& out);
    void resetUnwrittenAndWriteAfter(unsigned boundAxes, const toolpath::Vec3& start, const toolpath::Vec3& end,
                                     OutputWriter& out);
};

// Reads `post.blocks` (undefined: no templates). Errors say which entry is wrong.
base::Result<BlockTemplates> parseBlockTemplates(const QJSValue& blocks, const std::string& postFile, int line);

}  // namespace camwb::post
