#include "post/detail/BlockTemplates.h"

#include "post/detail/ScriptBindings.h"

#include <QJSValueIterator>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace camwb::post {

namespace {

constexpr const char* kValueNames[] = {"x",     "y",      "z",    "i",      "j",     "k",     "cx",    "cy",
                                       "cz",    "radius", "feed", "motion", "plane", "comp",  "sweep", "angle",
                                       "axial", "a",      "b",    "c",      "toolx", "tooly", "toolz"};
static_assert(std::size(kValueNames) == static_cast<std::size_t>(MoveValue::ToolZ) + 1);

bool isAxis(MoveValue v) { return v == MoveValue::X || v == MoveValue::Y || v == MoveValue::Z; }
bool isRotary(MoveValue v) { return v == MoveValue::A || v == MoveValue::B || v == MoveValue::C; }
bool isFiveAxisOnly(MoveValue v) { return v >= MoveValue::A; }

// Which move values each kind of block may use: a rapid has no feed, straight moves no centre,
// only five-axis blocks rotary axes and tool vectors.
bool allowed(MoveValue v, const std::string& kind)
{
    const bool fiveAxis = kind == "rapid5D" || kind == "linear5D";
    if (isFiveAxisOnly(v))
        return fiveAxis;
    if (kind == "circular")
        return v != MoveValue::Comp;
    if (v == MoveValue::Angle || v == MoveValue::Axial)
        return false;
    if (isAxis(v) || v == MoveValue::Motion || v == MoveValue::Comp)
        return true;
    return (kind == "linear" || kind == "linear5D") && v == MoveValue::Feed;
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
        } else if (auto* pending = qobject_cast<PendingObject*>(item.toQObject())) {
            word.pending = pending;
            block.keepAlive.push_back(item);
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
            word.force = item.property("force").toBool();
            const QJSValue texts = item.property("texts");
            if (texts.isObject()) {
                QJSValueIterator it(texts);
                while (it.hasNext()) {
                    it.next();
                    bool isCode = false;
                    const int code = it.name().toInt(&isCode);
                    if (!isCode)
                        return base::makeError(at + ": texts keys must be whole numbers (codes of '" +
                                                   item.property("value").toString().toStdString() + "')",
                                               postFile, line);
                    word.texts.emplace_back(code, it.value().toString().toStdString());
                }
            }
            hasAxis = hasAxis || isAxis(*value);
            if (isAxis(*value) && !block.axes[static_cast<int>(*value)])
                block.axes[static_cast<int>(*value)] = object;
            block.keepAlive.push_back(variable);
        }
        block.words.push_back(std::move(word));
    }
    if (!hasAxis && block.straight)
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
    case MoveValue::Angle:
        return motion == 2 ? -sweepDeg : sweepDeg;
    case MoveValue::Axial:
        return axialRise;
    case MoveValue::A:
    case MoveValue::B:
    case MoveValue::C:
        return rotaryDeg[static_cast<int>(which) - static_cast<int>(MoveValue::A)];
    case MoveValue::ToolX:
        return toolAxis.x;
    case MoveValue::ToolY:
        return toolAxis.y;
    case MoveValue::ToolZ:
        return toolAxis.z;
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
        const VariableObject* variable = writtenAxes[axis];
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

bool BlockTemplate::write(const MoveValues& given, OutputWriter& out, Issues& issues)
{
    MoveValues move = given;
    move.writtenStart = move.start;
    if (!straight) {
        // The control measures centre words and helix rises from the start as it was written.
        const double start[3] = {move.start.x, move.start.y, move.start.z};
        const double end[3] = {move.end.x, move.end.y, move.end.z};
        double written[3], writtenEnd[3];
        for (int a = 0; a < 3; ++a) {
            written[a] = writtenAxes[a] ? writtenAxes[a]->writtenValue(start[a]) : start[a];
            writtenEnd[a] = writtenAxes[a] ? writtenAxes[a]->writtenValue(end[a]) : end[a];
        }
        move.writtenStart = {written[0], written[1], written[2]};
        const int normalAxis = move.plane == 17 ? 2 : move.plane == 18 ? 1 : 0;
        move.axialRise = writtenEnd[normalAxis] - written[normalAxis];
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
            issues.missingFeed = true;
            continue;
        }
        const double value = move.value(word.value);
        if (word.variable->beyondMax(value)) {
            issues.beyondMax = word.variable->modal().prefix() + base::NumberFormat{4, true}.format(value) +
                               " is beyond the largest value the control reads (" +
                               base::NumberFormat{4, true}.format(word.variable->max()) + ")";
            return false;
        }
        if (!word.texts.empty()) {
            const int code = static_cast<int>(std::lround(value));
            const auto text = std::find_if(word.texts.begin(), word.texts.end(),
                                           [code](const auto& entry) { return entry.first == code; });
            m_skip[i] = text == word.texts.end();
            if (!m_skip[i])
                m_texts[i] = text->second;
            continue;
        }
        if (word.value == MoveValue::Feed)
            if (const std::string* parameter = word.variable->feedParameter(move.feedKind, move.feed)) {
                m_texts[i] = *parameter;
                continue;
            }
        char* buffer = m_buffers.data() + i * kSize;
        m_texts[i] = std::string_view(buffer, word.variable->textOf(value, buffer));
        if ((isAxis(word.value) || isRotary(word.value)) && word.variable->modal().wouldWrite(m_texts[i]))
            axisChanges = true;
    }
    if (straight && !axisChanges)
        return false;
    // Decide what is written first (modal updates), then copy it into the block buffer in one go.
    std::size_t needed = 0;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const Word& word = words[i];
        std::size_t length = 0;
        if (word.variable) {
            if (!m_skip[i] && (word.variable->modal().update(m_texts[i]) || word.force))
                length = word.variable->modal().prefix().size() + m_texts[i].size();
        } else {
            length = word.pending ? word.pending->text().size() : word.literal.size();
        }
        m_skip[i] = length == 0;
        needed += length ? length + 1 : 0;
    }
    if (m_block.size() < needed)
        m_block.resize(needed);
    char* const block = m_block.data();
    char* end = block;
    auto put = [&end](std::string_view text) {
        std::memcpy(end, text.data(), text.size());
        end += text.size();
    };
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (m_skip[i])
            continue;
        const Word& word = words[i];
        if (end != block)
            *end++ = ' ';
        if (word.variable) {
            put(word.variable->modal().prefix());
            put(m_texts[i]);
        } else if (word.pending) {
            put(word.pending->text());
            word.pending->text().clear();
        } else {
            put(word.literal);
        }
    }
    if (end == block)
        return false;
    out.writeCleanBlock(std::string_view(block, static_cast<std::size_t>(end - block)));
    return true;
}

ArcBlocks* BlockTemplates::arcBlocks(int planeIndex, bool helical)
{
    if (planeIndex < 0)
        return nullptr;
    ArcBlocks& blocks = helical && !helix[planeIndex].empty() ? helix[planeIndex] : circular[planeIndex];
    return blocks.empty() ? nullptr : &blocks;
}

namespace {

void writePending(const std::vector<PendingObject*>& list, OutputWriter& out)
{
    for (PendingObject* pending : list)
        if (!pending->text().empty()) {
            out.writeBlock({pending->text()});
            pending->text().clear();
        }
}

}  // namespace

void BlockTemplates::writeBefore(OutputWriter& out) { writePending(before, out); }

void BlockTemplates::resetUnwrittenAndWriteAfter(unsigned boundAxes, const toolpath::Vec3& start,
                                                 const toolpath::Vec3& end, OutputWriter& out)
{
    const double moved[3] = {end.x - start.x, end.y - start.y, end.z - start.z};
    for (int axis = 0; axis < 3; ++axis)
        if (moved[axis] != 0 && !((boundAxes >> axis) & 1))
            for (VariableObject* variable : axisVariables[axis])
                variable->modal().reset();
    if (!after.empty())
        writePending(after, out);
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

namespace {

// One plane's arc: a word list (one block) or a list of word lists (CC X Y, then C X Y DR+).
base::Result<ArcBlocks> parseArcBlocks(const QJSValue& list, const std::string& where, const std::string& postFile,
                                       int line)
{
    ArcBlocks blocks;
    const bool nested = list.isArray() && list.property("length").toInt() > 0 && list.property(0).isArray();
    const int count = nested ? list.property("length").toInt() : 1;
    for (int i = 0; i < count; ++i) {
        const std::string at = nested ? where + "[" + std::to_string(i) + "]" : where;
        auto block = parseWords(nested ? list.property(static_cast<quint32>(i)) : list, "circular", at, postFile, line);
        if (!block)
            return block.error();
        blocks.push_back(std::move(block).value());
    }
    return blocks;
}

base::Result<std::vector<VariableObject*>> parseVariables(const QJSValue& list, const std::string& where,
                                                          const std::string& postFile, int line,
                                                          std::vector<QJSValue>& keepAlive)
{
    std::vector<VariableObject*> variables;
    if (list.isUndefined())
        return variables;
    const int length = list.isArray() ? list.property("length").toInt() : -1;
    if (length < 0)
        return base::makeError(where + " must be an array of variables", postFile, line);
    for (int i = 0; i < length; ++i) {
        const QJSValue item = list.property(static_cast<quint32>(i));
        auto* object = qobject_cast<VariableObject*>(item.toQObject());
        if (!object)
            return base::makeError(where + "[" + std::to_string(i) + "]: expected a variable from createVariable()",
                                   postFile, line);
        variables.push_back(object);
        keepAlive.push_back(item);
    }
    return variables;
}

}  // namespace

base::Result<BlockTemplates> parseBlockTemplates(const QJSValue& blocks, const std::string& postFile, int line)
{
    BlockTemplates templates;
    if (blocks.isUndefined() || blocks.isNull())
        return templates;
    if (!blocks.isObject())
        return base::makeError("post.blocks must be an object {rapid, linear, circular, after}", postFile, line);
    const std::pair<const char*, std::optional<BlockTemplate>*> straight[] = {{"rapid", &templates.rapid},
                                                                              {"linear", &templates.linear},
                                                                              {"rapid5D", &templates.rapid5D},
                                                                              {"linear5D", &templates.linear5D}};
    for (const auto& [kind, slot] : straight) {
        const QJSValue list = blocks.property(kind);
        if (list.isUndefined())
            continue;
        auto block = parseWords(list, kind, std::string("post.blocks.") + kind, postFile, line);
        if (!block)
            return block.error();
        *slot = std::move(block).value();
    }
    for (const char* key : {"before", "after"}) {
        const QJSValue list = blocks.property(key);
        if (list.isUndefined())
            continue;
        const std::string where = std::string("post.blocks.") + key;
        const int length = list.isArray() ? list.property("length").toInt() : -1;
        for (int i = 0; i < length; ++i) {
            const QJSValue item = list.property(static_cast<quint32>(i));
            auto* pending = qobject_cast<PendingObject*>(item.toQObject());
            if (!pending)
                return base::makeError(where + "[" + std::to_string(i) + "]: expected createPending()", postFile, line);
            (std::string(key) == "before" ? templates.before : templates.after).push_back(pending);
            templates.keepAlive.push_back(item);
        }
        if (length < 0)
            return base::makeError(where + " must be an array of createPending() objects", postFile, line);
    }
    const QJSValue circular = blocks.property("circular");
    if (!circular.isUndefined()) {
        if (!circular.isObject())
            return base::makeError("post.blocks.circular must be an object {XY, ZX, YZ, helix, forceOnHelical}",
                                   postFile, line);
        auto force = parseVariables(circular.property("forceOnHelical"), "post.blocks.circular.forceOnHelical",
                                    postFile, line, templates.keepAlive);
        if (!force)
            return force.error();
        const QJSValue helix = circular.property("helix");
        if (!helix.isUndefined() && !helix.isObject())
            return base::makeError("post.blocks.circular.helix must be an object {XY, ZX, YZ}", postFile, line);
        for (const char* plane : {"XY", "ZX", "YZ"}) {
            const int index = BlockTemplates::planeIndex(plane);
            for (const bool helical : {false, true}) {
                const QJSValue list = helical ? helix.property(plane) : circular.property(plane);
                if (list.isUndefined())
                    continue;
                const std::string where = std::string("post.blocks.circular.") + (helical ? "helix." : "") + plane;
                auto parsed = parseArcBlocks(list, where, postFile, line);
                if (!parsed)
                    return parsed.error();
                for (BlockTemplate& block : parsed.value())
                    block.forceOnHelical = force.value();
                (helical ? templates.helix : templates.circular)[index] = std::move(parsed).value();
            }
        }
    }
    // Every variable bound to an axis anywhere; the first of each axis tells how it was written.
    templates.forEach([&templates](BlockTemplate& block) {
        for (int axis = 0; axis < 3; ++axis) {
            std::vector<VariableObject*>& list = templates.axisVariables[axis];
            if (VariableObject* v = block.axes[axis]; v && std::find(list.begin(), list.end(), v) == list.end())
                list.push_back(v);
        }
    });
    templates.forEach([&templates](BlockTemplate& block) {
        for (int axis = 0; axis < 3; ++axis)
            block.writtenAxes[axis] =
                templates.axisVariables[axis].empty() ? nullptr : templates.axisVariables[axis][0];
    });
    return templates;
}

}  // namespace camwb::post
