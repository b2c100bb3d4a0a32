// Private: the kernel services a post script sees (createFormat, createVariable, createModal,
// writeBlock, ...), as QObjects for QJSEngine. State lives in Qt-free classes (OutputWriter,
// ModalValue, base::NumberFormat) so that C++ block templates can share it later.
#pragma once

#include "base/NumberFormat.h"
#include "post/ModalValue.h"
#include "post/OutputWriter.h"
#include "post/PostProcessor.h"

#include <QJSEngine>
#include <QJSValue>
#include <QObject>
#include <QString>

#include <optional>
#include <vector>

namespace camwb::post {

class FormatObject : public QObject {
    Q_OBJECT
public:
    FormatObject(QJSEngine* engine, base::NumberFormat format) : m_engine(engine), m_format(format) {}
    const base::NumberFormat& numberFormat() const { return m_format; }

    Q_INVOKABLE QString format(const QJSValue& value);

private:
    QJSEngine* m_engine;
    base::NumberFormat m_format;
};

// A modal word: createVariable (numbers through a format) and createModal (G/M codes: strings or
// numbers, numbers through the optional format).
class VariableObject : public QObject {
    Q_OBJECT
public:
    VariableObject(QJSEngine* engine, std::string prefix, bool force, std::optional<base::NumberFormat> format,
                   bool acceptsText) :
        m_engine(engine),
        m_value(std::move(prefix), force),
        m_format(format),
        m_acceptsText(acceptsText)
    {
    }

    Q_INVOKABLE QString format(const QJSValue& value);
    Q_INVOKABLE void reset() { m_value.reset(); }

private:
    QJSEngine* m_engine;
    ModalValue m_value;
    std::optional<base::NumberFormat> m_format;
    bool m_acceptsText;
};

class ScriptKernel : public QObject {
    Q_OBJECT
public:
    ScriptKernel(QJSEngine* engine, std::string postFile) : m_engine(engine), m_postFile(std::move(postFile)) {}

    OutputWriter& writer() { return m_writer; }
    std::vector<PostMessage>& messages() { return m_messages; }
    void setPosition(std::optional<toolpath::Vec3> position) { m_position = position; }
    const std::optional<toolpath::Vec3>& position() const { return m_position; }
    // Text of the last error() call by the post; cleared by takePostError().
    std::optional<std::string> takePostError() { return std::exchange(m_postError, std::nullopt); }

    // Overloads by argument count: QJSEngine requires every declared argument.
    Q_INVOKABLE QJSValue createFormat() { return createFormat(QJSValue()); }
    Q_INVOKABLE QJSValue createFormat(const QJSValue& spec);
    Q_INVOKABLE QJSValue createVariable(const QJSValue& spec) { return createVariable(spec, QJSValue()); }
    Q_INVOKABLE QJSValue createVariable(const QJSValue& spec, const QJSValue& format);
    Q_INVOKABLE QJSValue createModal(const QJSValue& spec) { return createModal(spec, QJSValue()); }
    Q_INVOKABLE QJSValue createModal(const QJSValue& spec, const QJSValue& format);
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
    Q_INVOKABLE void setBlockNumbering(const QJSValue& start, const QJSValue& step, const QJSValue& enabled);
    Q_INVOKABLE QJSValue getCurrentPosition();

private:
    QJSValue makeVariable(const QJSValue& spec, const QJSValue& format, bool acceptsText);
    int callerLine();

    QJSEngine* m_engine;
    std::string m_postFile;
    OutputWriter m_writer;
    std::vector<PostMessage> m_messages;
    std::optional<toolpath::Vec3> m_position;
    std::optional<std::string> m_postError;
};

// Text of a script value for NC words: undefined and null are "".
std::string wordText(const QJSValue& value);

}  // namespace camwb::post
