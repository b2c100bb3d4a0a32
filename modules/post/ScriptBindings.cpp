#include "post/detail/ScriptBindings.h"

#include <cmath>

namespace camwb::post {

namespace {

bool isIntegral(double value) { return std::isfinite(value) && value == std::floor(value) && std::abs(value) < 1e15; }

}  // namespace

std::string wordText(const QJSValue& value)
{
    if (value.isUndefined() || value.isNull())
        return {};
    if (value.isNumber()) {
        const double number = value.toNumber();
        return isIntegral(number) ? std::to_string(static_cast<long long>(number)) : base::formatFixed(number, 3);
    }
    return value.toString().toStdString();
}

QString FormatObject::format(const QJSValue& value)
{
    if (!value.isNumber() || !std::isfinite(value.toNumber())) {
        m_engine->throwError(QJSValue::TypeError,
                             QStringLiteral("format() needs a finite number, got '%1'").arg(value.toString()));
        return {};
    }
    return QString::fromStdString(m_format.format(value.toNumber()));
}

QString VariableObject::format(const QJSValue& value)
{
    std::string text;
    if (value.isNumber() && std::isfinite(value.toNumber())) {
        const double number = value.toNumber();
        text = m_format ? m_format->format(number) : wordText(value);
    } else if (m_acceptsText && value.isString()) {
        text = value.toString().toStdString();
    } else {
        m_engine->throwError(QJSValue::TypeError,
                             QStringLiteral("format() needs a finite number%1, got '%2'")
                                 .arg(m_acceptsText ? QStringLiteral(" or a string") : QString(), value.toString()));
        return {};
    }
    return QString::fromStdString(m_value.output(text));
}

QJSValue ScriptKernel::createFormat(const QJSValue& spec)
{
    base::NumberFormat format;
    if (!spec.isUndefined() && !spec.isObject()) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("createFormat() needs an object"));
        return {};
    }
    if (spec.hasProperty("decimals")) {
        const double decimals = spec.property("decimals").toNumber();
        if (!isIntegral(decimals) || decimals < 0 || decimals > 12) {
            m_engine->throwError(QJSValue::RangeError, QStringLiteral("createFormat(): decimals must be 0..12"));
            return {};
        }
        format.decimals = static_cast<int>(decimals);
    }
    format.trimTrailingZeros = spec.property("trim").toBool();
    format.keepDecimalPoint = spec.property("keepDecimalPoint").toBool();
    format.forceSign = spec.property("forceSign").toBool();
    if (spec.hasProperty("leadingZero"))
        format.leadingZero = spec.property("leadingZero").toBool();
    return m_engine->newQObject(new FormatObject(m_engine, format));  // owned by the script engine
}

QJSValue ScriptKernel::makeVariable(const QJSValue& spec, const QJSValue& format, bool acceptsText)
{
    if (!spec.isUndefined() && !spec.isObject()) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("createVariable()/createModal() needs an object"));
        return {};
    }
    std::optional<base::NumberFormat> numberFormat;
    if (!format.isUndefined() && !format.isNull()) {
        auto* formatObject = qobject_cast<FormatObject*>(format.toQObject());
        if (!formatObject) {
            m_engine->throwError(QJSValue::TypeError, QStringLiteral("the format must come from createFormat()"));
            return {};
        }
        numberFormat = formatObject->numberFormat();
    } else if (!acceptsText) {
        numberFormat = base::NumberFormat{};
    }
    const std::string prefix = spec.hasProperty("prefix") ? spec.property("prefix").toString().toStdString() : "";
    const bool force = spec.property("force").toBool();
    return m_engine->newQObject(new VariableObject(m_engine, prefix, force, numberFormat, acceptsText));
}

QJSValue ScriptKernel::createVariable(const QJSValue& spec, const QJSValue& format)
{
    return makeVariable(spec, format, false);
}

QJSValue ScriptKernel::createModal(const QJSValue& spec, const QJSValue& format)
{
    return makeVariable(spec, format, true);
}

void ScriptKernel::writeBlockWords(const QJSValue& words)
{
    std::vector<std::string> texts;
    const int length = words.property("length").toInt();
    texts.reserve(length);
    for (int i = 0; i < length; ++i)
        texts.push_back(wordText(words.property(i)));
    m_writer.writeBlock(texts);
}

void ScriptKernel::writeComment(const QJSValue& text) { m_writer.writeComment(wordText(text)); }

void ScriptKernel::writeln(const QJSValue& text) { m_writer.writeLine(wordText(text)); }

int ScriptKernel::callerLine()
{
    // QJSEngine has no public call-stack API: an Error created now carries the calling script line.
    m_engine->throwError(QJSValue::GenericError, QStringLiteral("location"));
    const QJSValue located = m_engine->catchError();
    return located.property("lineNumber").toInt();
}

void ScriptKernel::warning(const QJSValue& text)
{
    m_messages.push_back({PostMessage::Severity::Warning, wordText(text), m_postFile, callerLine()});
}

void ScriptKernel::error(const QJSValue& text)
{
    m_postError = wordText(text);
    m_engine->throwError(QJSValue::GenericError, QString::fromStdString(*m_postError));
}

void ScriptKernel::setBlockNumbering(const QJSValue& start, const QJSValue& step, const QJSValue& enabled)
{
    const double first = start.isUndefined() ? 10 : start.toNumber();
    const double increment = step.isUndefined() ? 10 : step.toNumber();
    if (!isIntegral(first) || !isIntegral(increment) || first < 0 || increment <= 0) {
        m_engine->throwError(
            QJSValue::RangeError,
            QStringLiteral("setBlockNumbering(start, step, enabled): start >= 0 and step > 0, integers"));
        return;
    }
    m_writer.setBlockNumbering(static_cast<long long>(first), static_cast<long long>(increment),
                               enabled.isUndefined() ? true : enabled.toBool());
}

QJSValue ScriptKernel::getCurrentPosition()
{
    if (!m_position)
        return QJSValue(QJSValue::NullValue);
    QJSValue point = m_engine->newObject();
    point.setProperty("x", m_position->x);
    point.setProperty("y", m_position->y);
    point.setProperty("z", m_position->z);
    return point;
}

}  // namespace camwb::post
