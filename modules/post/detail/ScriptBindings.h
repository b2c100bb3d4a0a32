// Private: the kernel services a post script sees (createFormat, createVariable, createModal,
// writeBlock, getProperty, expandCyclePoint, ...), as QObjects for QJSEngine. State lives in
// Qt-free classes (OutputWriter, ModalValue, base::NumberFormat) that the C++ block templates share.
#pragma once

#include "base/NumberFormat.h"
#include "post/ModalValue.h"
#include "post/OutputWriter.h"
#include "post/PostProcessor.h"
#include "toolpath/KnownPosition.h"

#include <QJSEngine>
#include <QJSValue>
#include <QObject>
#include <QString>

#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace camwb::post {

class FormatObject : public QObject {
    Q_OBJECT
public:
    FormatObject(QJSEngine* engine, base::NumberFormat format, double max) :
        m_engine(engine),
        m_format(format),
        m_max(max)
    {
    }
    const base::NumberFormat& numberFormat() const { return m_format; }
    // createFormat({max}): the largest magnitude the control reads in this format (0: any).
    double max() const { return m_max; }

    Q_INVOKABLE QString format(const QJSValue& value);

private:
    QJSEngine* m_engine;
    base::NumberFormat m_format;
    double m_max = 0;
};

// A modal word: createVariable (numbers through a format) and createModal (G/M codes: strings or
// numbers, numbers through the optional format). bind() names a move value for block templates.
class VariableObject : public QObject {
    Q_OBJECT
public:
    VariableObject(QJSEngine* engine, std::string prefix, bool force, std::optional<base::NumberFormat> format,
                   bool acceptsText, double max) :
        m_engine(engine),
        m_value(std::move(prefix), force),
        m_format(format),
        m_max(max),
        m_resolution(resolutionOf(format)),
        m_acceptsText(acceptsText)
    {
    }

    Q_INVOKABLE QString format(const QJSValue& value);
    Q_INVOKABLE void reset() { m_value.reset(); }
    Q_INVOKABLE QJSValue bind(const QJSValue& valueName) { return bind(valueName, QJSValue()); }
    // bind(name, {force: true, texts: {code: text}}): see BlockTemplate::Word.
    Q_INVOKABLE QJSValue bind(const QJSValue& valueName, const QJSValue& options);
    // Parametric feeds: {cutting: {text: "+Q601", feed: 900}, ...} by CL feed kind. A move of a
    // listed kind at exactly that feed writes the text instead of the number; {} ends them. The
    // last value is forgotten, so the next feed word is written: a control keeps the feed it read,
    // not the parameter, and a parameter defined again must be read again.
    Q_INVOKABLE void setFeedParameters(const QJSValue& parameters);
    // A new number format from now on (feeds per minute vs per revolution); forgets the last value.
    Q_INVOKABLE void setFormat(const QJSValue& format);
    // Written in every block from now on (true), or only when it changes (false).
    Q_INVOKABLE void setForce(bool force) { m_value.setForce(force); }

    // The C++ side of format(): the number's text (into a kBufferSize buffer), then modal().
    std::size_t textOf(double value, char* out) const;
    // Whether `value` is beyond the format's max (as written, scale applied).
    bool beyondMax(double value) const
    {
        return m_max > 0 && !(std::abs(value * (m_format ? m_format->scale : 1.0)) <= m_max);
    }
    double max() const { return m_max; }
    // The smallest difference two values need to be written differently (one unit of the last
    // decimal, scale undone); values further apart never have the same text.
    double resolution() const { return m_resolution; }
    // The value as the control reads it back from that text (rounded, scale undone).
    double writtenValue(double value) const;
    ModalValue& modal() { return m_value; }
    // The parameter text for a move of `feedKind` at `feed` (setFeedParameters), else null.
    const std::string* feedParameter(int feedKind, double feed) const;

private:
    static double resolutionOf(const std::optional<base::NumberFormat>& format);

    QJSEngine* m_engine;
    ModalValue m_value;
    std::optional<base::NumberFormat> m_format;
    double m_max = 0;
    double m_resolution;  // of m_format, kept: block templates ask for it on every move
    bool m_acceptsText;
    // The last number formatted and its text: a block template formats the same Z or F block after
    // block, and copying the text is cheaper than formatting it again.
    mutable double m_cachedValue = 0;
    mutable std::size_t m_cachedLength = 0;  // 0: nothing cached
    mutable char m_cachedText[32];
    struct FeedParameter {
        int kind;
        std::string text;
        double feed;
    };
    std::vector<FeedParameter> m_feedParameters;
};

// A one-shot word or block (createPending()): the script sets it (M3 when the spindle starts),
// the next block template that lists it writes it and clears it; take() hands it to the script
// instead, for blocks the script writes itself.
class PendingObject : public QObject {
    Q_OBJECT
public:
    Q_INVOKABLE void set(const QJSValue& text);
    Q_INVOKABLE QString take() { return QString::fromStdString(std::exchange(m_text, std::string())); }
    Q_INVOKABLE bool isSet() const { return !m_text.empty(); }
    std::string& text() { return m_text; }

private:
    std::string m_text;
};

// A file the post writes beside the main program (openFile/closeFile), kept in memory until the
// run has succeeded.
struct CompanionWriter {
    std::string name;
    OutputWriter writer;
};

class ScriptKernel : public QObject {
    Q_OBJECT
public:
    ScriptKernel(QJSEngine* engine, std::string postFile) : m_engine(engine), m_postFile(std::move(postFile)) {}

    // Where writeBlock, writeln, writeComment and the block templates write now: the companion
    // file openFile() opened, else the main program.
    OutputWriter& writer() { return m_open >= 0 ? m_companions[static_cast<std::size_t>(m_open)].writer : m_writer; }
    OutputWriter& mainWriter() { return m_writer; }
    std::vector<CompanionWriter>& companions() { return m_companions; }
    // The companion file still open (no closeFile() before the end of the run); empty: none.
    std::string openCompanion() const
    {
        return m_open >= 0 ? m_companions[static_cast<std::size_t>(m_open)].name : std::string();
    }
    std::vector<base::Diagnostic>& messages() { return m_messages; }
    // Where the kernel believes the tool is, axis by axis (unknown at the start and after a tool
    // change, until a move gives the axis).
    void setPosition(const toolpath::Vec3& position) { m_position.set(position); }
    void setPosition(const toolpath::KnownPosition& position) { m_position = position; }
    void forgetPosition() { m_position.forget(); }
    const toolpath::KnownPosition& position() const { return m_position; }
    // Text of the last error() call by the post; cleared by takePostError().
    std::optional<std::string> takePostError() { return std::exchange(m_postError, std::nullopt); }
    // Property values for getProperty(); before a run sets them, it answers the declared defaults.
    void setProperties(QJSValue values) { m_properties = std::move(values); }
    // The current section's own values (an operation's), answered before the job's; undefined: none.
    void setSectionProperties(QJSValue values) { m_sectionProperties = std::move(values); }
    // What expandCyclePoint(x, y, z) does; empty outside onCyclePoint.
    void setCycleExpander(std::function<void(const toolpath::Vec3&)> expander) { m_expandCycle = std::move(expander); }
    // File and line of the innermost script frame calling into the kernel now (the post, or a
    // file it included).
    std::pair<std::string, int> callerLocation();

    // Overloads by argument count: QJSEngine requires every declared argument.
    Q_INVOKABLE QJSValue createFormat() { return createFormat(QJSValue()); }
    Q_INVOKABLE QJSValue createFormat(const QJSValue& spec);
    Q_INVOKABLE QJSValue createVariable(const QJSValue& spec) { return createVariable(spec, QJSValue()); }
    Q_INVOKABLE QJSValue createVariable(const QJSValue& spec, const QJSValue& format);
    Q_INVOKABLE QJSValue createModal(const QJSValue& spec) { return createModal(spec, QJSValue()); }
    Q_INVOKABLE QJSValue createModal(const QJSValue& spec, const QJSValue& format);
    Q_INVOKABLE QJSValue createPending();
    Q_INVOKABLE void writeBlockWords(const QJSValue& words);
    Q_INVOKABLE void writeComment(const QJSValue& text);
    Q_INVOKABLE void writeln(const QJSValue& text);
    Q_INVOKABLE void warning(const QJSValue& text);
    Q_INVOKABLE void error(const QJSValue& text);
    Q_INVOKABLE void setBlockNumbering(const QJSValue& start) { setBlockNumbering(start, QJSValue(), QJSValue()); }
    Q_INVOKABLE void setBlockNumbering(const QJSValue& start, const QJSValue& step)
    {
        setBlockNumbering(start, step, QJSValue());
    }
    Q_INVOKABLE void setBlockNumbering(const QJSValue& start, const QJSValue& step, const QJSValue& enabled)
    {
        setBlockNumbering(start, step, enabled, QJSValue());
    }
    // prefix: what comes before the number ("N" by default; "" for Klartext's "0 BEGIN PGM").
    Q_INVOKABLE void setBlockNumbering(const QJSValue& start, const QJSValue& step, const QJSValue& enabled,
                                       const QJSValue& prefix);
    // {x, y, z} when every axis is known, else null; getCurrentAxis("z") answers one axis (null
    // while unknown), e.g. the height after a retract that gave only Z.
    Q_INVOKABLE QJSValue getCurrentPosition();
    Q_INVOKABLE QJSValue getCurrentAxis(const QJSValue& axis);
    Q_INVOKABLE QJSValue getProperty(const QJSValue& name);
    Q_INVOKABLE void expandCyclePoint(const QJSValue& x, const QJSValue& y, const QJSValue& z);
    // The program's machining time in seconds: toolpath::programStats with the machine's rapid,
    // the editor's Program Information estimate.
    Q_INVOKABLE double machiningSeconds();
    void setMachiningTime(std::function<double()> estimate)
    {
        m_machiningTime = std::move(estimate);
        m_machiningSeconds.reset();
    }
    // Five-axis blocks (FiveAxisWriter): the axes X Y Z A B C (bits 0..5 of `mask`) as written.
    void noteMachineAxes(const std::array<double, 6>& values, unsigned mask);
    // {x: {min, max}, ..., c: {min, max}} of the axes five-axis blocks wrote (X Y Z as written:
    // tips with TCPM, machine coordinates without), for travel reports; null before any.
    Q_INVOKABLE QJSValue getFiveAxisTravel();
    // The axes of the last five-axis block {x, y, z, a, b, c} (an axis it never wrote: absent);
    // null before any, e.g. for the post that returns the rotaries home after a section.
    Q_INVOKABLE QJSValue getMachinePose();
    // include("name"): evaluates include/<name>.js, shared code of several posts, in the post's
    // global scope, once per run. Looked up in the post's own folder's include/, then in the
    // include/ of every post folder (a user's post may include a built-in library). Names are
    // plain ([a-z0-9_-]), so no other file can be reached.
    Q_INVOKABLE void include(const QJSValue& name);
    // readPostFile("sub/NAME.SPF"): the text of a file the post ships beside itself (NC code it
    // copies into the output), looked up as include() looks up libraries: the post's own folder,
    // then every post folder. A relative path without '.' or '..' parts; a missing file, an
    // absolute path or one that leaves the folder (also through a link) is an error at the
    // post's line.
    Q_INVOKABLE QString readPostFile(const QJSValue& relativePath);
    // openFile("NAME.SPF"): from now on writeBlock, writeln, writeComment and the block templates
    // write the companion file NAME.SPF, beside the main output, until closeFile(). Its block
    // numbers restart: the numbering the main program last set (start, step, on/off, prefix) from
    // its start; setBlockNumbering() while it is open changes it for that file only. A plain file
    // name ([A-Za-z0-9_.-], not starting with '.'), each name once per run (compared without
    // case: controls and some file systems do), one file open at a time; every file must be
    // closed before the run ends.
    Q_INVOKABLE void openFile(const QJSValue& name);
    Q_INVOKABLE void closeFile();

private:
    QJSValue makeVariable(const QJSValue& spec, const QJSValue& format, bool acceptsText);

    QJSEngine* m_engine;
    std::string m_postFile;
    OutputWriter m_writer;
    std::vector<base::Diagnostic> m_messages;
    toolpath::KnownPosition m_position;
    std::optional<std::string> m_postError;
    QJSValue m_properties;
    QJSValue m_sectionProperties;
    std::function<void(const toolpath::Vec3&)> m_expandCycle;
    std::function<double()> m_machiningTime;
    std::optional<double> m_machiningSeconds;
    std::array<double, 6> m_axisMin{}, m_axisMax{}, m_axisLast{};
    unsigned m_axesSeen = 0;
    std::vector<std::string> m_included;
    std::vector<CompanionWriter> m_companions;
    int m_open = -1;  // index into m_companions of the file being written, -1: the main program
};

// Text of a script value for NC words: undefined and null are "", whole numbers without decimals,
// other numbers with 3 decimals.
std::string wordText(const QJSValue& value);

// The file an Error object says it was thrown in, as a plain path (the engine keeps it as a
// file:// URL); `fallback` when it names none or the kernel's own prelude.
std::string errorFile(const QJSValue& error, const std::string& fallback);
// The same for a number, into a base::NumberFormat::kBufferSize buffer; returns the length.
std::size_t numberWordText(double value, char* out);

// A point {x, y, z} as a script object.
QJSValue scriptPoint(QJSEngine& engine, const toolpath::Vec3& p);

}  // namespace camwb::post
