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

enum class MoveValue { X, Y, Z, I, J, K, CenterX, CenterY, CenterZ, Radius, Feed, Motion, Plane, Comp, Sweep };

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
    int motion = 0;  // 0 rapid, 1 linear, 2 clockwise, 3 counter-clockwise (G0..G3)
    int plane = 17;  // 17 XY, 18 ZX, 19 YZ
    int comp = 40;   // 40 off, 41 left, 42 right
    bool helical = false;
    toolpath::AxisMask known;  // end axes the kernel knows: the others get no word (never invented)

    double value(MoveValue which) const;
};

class BlockTemplate {
public:
    struct Word {
        std::string literal;  // written as is when variable is null
        VariableObject* variable = nullptr;
        MoveValue value = MoveValue::X;
    };

    std::vector<Word> words;
    std::vector<VariableObject*> forceOnHelical;  // reset before a helical block: always written
    std::array<VariableObject*, 3> axes{};        // the variables that write x, y and z
    bool straight = false;                        // rapid/linear: no block when no axis word changes
    std::vector<QJSValue> keepAlive;              // the script objects behind the raw pointers

    // Writes the block for `move`. False when nothing was written (a straight move that changes no
    // axis). missingFeed is set when a feed word was left out because the feed is not positive.
    bool write(const MoveValues& move, OutputWriter& out, bool& missingFeed);

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

struct BlockTemplates {
    std::optional<BlockTemplate> rapid;
    std::optional<BlockTemplate> linear;
    std::array<std::optional<BlockTemplate>, 3> circular;  // XY, ZX, YZ

    static int planeIndex(const std::string& plane);  // "XY" 0, "ZX" 1, "YZ" 2, else -1
};

// Reads `post.blocks` (undefined: no templates). Errors say which entry is wrong.
base::Result<BlockTemplates> parseBlockTemplates(const QJSValue& blocks, const std::string& postFile, int line);

}  // namespace camwb::post
