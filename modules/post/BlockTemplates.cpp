#include "post/detail/BlockTemplates.h"

#include "post/detail/ScriptBindings.h"

#include <cmath>
#include <cstring>

namespace camwb::post {

namespace {

constexpr const char* kValueNames[] = {"x",  "y",      "z",    "i",      "j",     "k",    "cx",   "cy",
                                       "cz", "radius", "feed", "motion", "plane", "comp", "sweep"};
static_assert(std::size(kValueNames) == static_cast<std::size_t>(MoveValue::Sweep) + 1);

bool isAxis(MoveValue v) { return v == MoveValue::X || v == MoveValue::Y || v == MoveValue::Z; }

// Which move values each kind of block may use: a rapid has no feed, straight moves no centre.
bool allowed(MoveValue v, const std::string& kind)
{
    if (kind == "circular")
        return v != MoveValue::Comp;
    if (isAxis(v) || v == MoveValue::Motion || v == MoveValue::Comp)
        return true;
    return kind == "linear" && v == MoveValue::Feed;
}

base::Result<BlockTemplate> parseWords(const QJSValue& list, const std::string& kind, const std::string& where,
                                       const std::string& postFile, int line)
{
    if (!list.isArray())
        return base::makeError(where + " must be an array of words", postFile, line);
    BlockTemplate block;
    block.straight = kind != "circular";
    bool hasAxis = false;
    const int length = list.property("length").toInt();
    for (int i = 0; i < length; ++i) {
        const QJSValue item = list.property(static_cast<quint32>(i));
        const std::string at = where + "[" + std::to_string(i) + "]";
        BlockTemplate::Word word;
        if (item.isString()) {
            // Cleaned once here as OutputWriter::addWord would clean it in every block: no line
            // break inside a block, none at its end.
            word.literal = item.toString().toStdString();
            while (!word.literal.empty() && (word.literal.back() == '\r' || word.literal.back() == '\n'))
                word.literal.pop_back();
            for (char& c : word.literal)
                if (c == '\r' || c == '\n')
                    c = ' ';
        } else {
            const QJSValue variable = item.property("__camwbVariable");
            auto* object = qobject_cast<VariableObject*>(variable.toQObject());
            if (!object)
                return base::makeError(at + ": expected a string or a variable's bind(\"name\")", postFile, line);
            const std::optional<MoveValue> value = moveValueFromName(item.property("value").toString().toStdString());
            if (!value || !allowed(*value, kind))
                return base::makeError(at + ": a " + kind + " block cannot write '" +
                                           item.property("value").toString().toStdString() + "'",
                                       postFile, line);
            word.variable = object;
            word.value = *value;
            hasAxis = hasAxis || isAxis(*value);
            if (isAxis(*value) && !block.axes[static_cast<int>(*value)])
                block.axes[static_cast<int>(*value)] = object;
            block.keepAlive.push_back(variable);
        }
        block.words.push_back(std::move(word));
    }
    if (!hasAxis)
        return base::makeError(where + " writes no axis (bind x, y or z)", postFile, line);
    return block;
}

}  // namespace

std::optional<MoveValue> moveValueFromName(const std::string& name)
{
    for (std::size_t i = 0; i < std::size(kValueNames); ++i)
        if (name == kValueNames[i])
            return static_cast<MoveValue>(i);
    return std::nullopt;
}

std::string moveValueNames()
{
    std::string names;
    for (const char* name : kValueNames)
        names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

double MoveValues::value(MoveValue which) const
{
    switch (which) {
    case MoveValue::X:
        return end.x;
    case MoveValue::Y:
        return end.y;
    case MoveValue::Z:
        return end.z;
    case MoveValue::I:
        return center.x - writtenStart.x;
    case MoveValue::J:
        return center.y - writtenStart.y;
    case MoveValue::K:
        return center.z - writtenStart.z;
    case MoveValue::CenterX:
        return center.x;
    case MoveValue::CenterY:
        return center.y;
    case MoveValue::CenterZ:
        return center.z;
    case MoveValue::Radius:
        return radius;
    case MoveValue::Feed:
        return feed;
    case MoveValue::Motion:
        return motion;
    case MoveValue::Plane:
        return plane;
    case MoveValue::Comp:
        return comp;
    case MoveValue::Sweep:
        return sweepDeg;
    }
    return 0;
}

bool BlockTemplate::endsWhereItStarts(const MoveValues& move, int planeIndex) const
{
    static constexpr int kPlaneAxes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    const double start[3] = {move.start.x, move.start.y, move.start.z};
    const double end[3] = {move.end.x, move.end.y, move.end.z};
    char a[base::NumberFormat::kBufferSize], b[base::NumberFormat::kBufferSize];
    for (int axis : kPlaneAxes[planeIndex]) {
        const VariableObject* variable = axes[axis];
        if (!variable)
            return false;
        if (std::abs(end[axis] - start[axis]) > 1.5 * variable->resolution())
            return false;  // further apart than the last decimal: written differently for sure
        const std::size_t length = variable->textOf(start[axis], a);
        if (variable->textOf(end[axis], b) != length || std::memcmp(a, b, length) != 0)
            return false;
    }
    return true;
}

bool BlockTemplate::write(const MoveValues& given, OutputWriter& out, bool& missingFeed)
{
    MoveValues move = given;
    move.writtenStart = move.start;
    if (!straight) {  // centre words of arcs: from the start as written
        if (axes[0])
            move.writtenStart.x = axes[0]->writtenValue(move.start.x);
        if (axes[1])
            move.writtenStart.y = axes[1]->writtenValue(move.start.y);
        if (axes[2])
            move.writtenStart.z = axes[2]->writtenValue(move.start.z);
    }
    if (move.helical)
        for (VariableObject* variable : forceOnHelical)
            variable->modal().reset();
    constexpr std::size_t kSize = base::NumberFormat::kBufferSize;
    if (m_texts.size() != words.size()) {
        m_buffers.resize(words.size() * kSize);
        m_texts.resize(words.size());
        m_skip.resize(words.size());
        std::size_t blockBytes = 0;  // every word at its longest, with a blank before it
        for (const Word& word : words)
            blockBytes += 1 + (word.variable ? word.variable->modal().prefix().size() + kSize : word.literal.size());
        m_block.resize(blockBytes);
    }
    bool axisChanges = false;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const Word& word = words[i];
        m_skip[i] = 0;
        if (!word.variable)
            continue;
        if (isAxis(word.value) && !move.known.has(static_cast<int>(word.value))) {
            m_skip[i] = 1;
            continue;
        }
        if (word.value == MoveValue::Feed && !(move.feed > 0)) {
            m_skip[i] = 1;
            missingFeed = true;
            continue;
        }
        char* buffer = m_buffers.data() + i * kSize;
        m_texts[i] = std::string_view(buffer, word.variable->textOf(move.value(word.value), buffer));
        if (isAxis(word.value) && word.variable->modal().wouldWrite(m_texts[i]))
            axisChanges = true;
    }
    if (straight && !axisChanges)
        return false;
    char* const block = m_block.data();
    char* end = block;
    auto put = [&end, block](std::string_view text) {
        std::memcpy(end, text.data(), text.size());
        end += text.size();
    };
    for (std::size_t i = 0; i < words.size(); ++i) {
        const Word& word = words[i];
        const bool written =
            word.variable ? !m_skip[i] && word.variable->modal().update(m_texts[i]) : !word.literal.empty();
        if (!written)
            continue;
        if (end != block)
            *end++ = ' ';
        if (word.variable) {
            put(word.variable->modal().prefix());
            put(m_texts[i]);
        } else {
            put(word.literal);
        }
    }
    if (end == block)
        return false;
    out.writeCleanBlock(std::string_view(block, static_cast<std::size_t>(end - block)));
    return true;
}

int BlockTemplates::planeIndex(const std::string& plane)
{
    if (plane == "XY")
        return 0;
    if (plane == "ZX")
        return 1;
    if (plane == "YZ")
        return 2;
    return -1;
}

base::Result<BlockTemplates> parseBlockTemplates(const QJSValue& blocks, const std::string& postFile, int line)
{
    BlockTemplates templates;
    if (blocks.isUndefined() || blocks.isNull())
        return templates;
    if (!blocks.isObject())
        return base::makeError("post.blocks must be an object {rapid, linear, circular}", postFile, line);
    for (const char* kind : {"rapid", "linear"}) {
        const QJSValue list = blocks.property(kind);
        if (list.isUndefined())
            continue;
        auto block = parseWords(list, kind, std::string("post.blocks.") + kind, postFile, line);
        if (!block)
            return block.error();
        (std::string(kind) == "rapid" ? templates.rapid : templates.linear) = std::move(block).value();
    }
    const QJSValue circular = blocks.property("circular");
    if (circular.isUndefined())
        return templates;
    if (!circular.isObject())
        return base::makeError("post.blocks.circular must be an object {XY, ZX, YZ, forceOnHelical}", postFile, line);
    std::vector<VariableObject*> force;
    std::vector<QJSValue> forceAlive;
    const QJSValue forceList = circular.property("forceOnHelical");
    if (!forceList.isUndefined()) {
        const int length = forceList.isArray() ? forceList.property("length").toInt() : -1;
        for (int i = 0; i < length; ++i) {
            const QJSValue item = forceList.property(static_cast<quint32>(i));
            auto* object = qobject_cast<VariableObject*>(item.toQObject());
            if (!object)
                return base::makeError("post.blocks.circular.forceOnHelical[" + std::to_string(i) +
                                           "]: expected a variable from createVariable()",
                                       postFile, line);
            force.push_back(object);
            forceAlive.push_back(item);
        }
        if (length < 0)
            return base::makeError("post.blocks.circular.forceOnHelical must be an array of variables", postFile, line);
    }
    for (const char* plane : {"XY", "ZX", "YZ"}) {
        const QJSValue list = circular.property(plane);
        if (list.isUndefined())
            continue;
        auto block = parseWords(list, "circular", std::string("post.blocks.circular.") + plane, postFile, line);
        if (!block)
            return block.error();
        block->forceOnHelical = force;
        block->keepAlive.insert(block->keepAlive.end(), forceAlive.begin(), forceAlive.end());
        templates.circular[BlockTemplates::planeIndex(plane)] = std::move(block).value();
    }
    return templates;
}

}  // namespace camwb::post
