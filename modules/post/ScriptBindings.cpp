#include "post/detail/ScriptBindings.h"

#include "post/detail/BlockTemplates.h"
#include "toolpath/RecordNames.h"

#include <QJSValueIterator>
#include <QUrl>

#include <charconv>
#include <cmath>
#include <cstring>

namespace camwb::post {

namespace {

bool isIntegral(double value) { return std::isfinite(value) && value == std::floor(value) && std::abs(value) < 1e15; }

}  // namespace

std::size_t numberWordText(double value, char* out)
{
    if (isIntegral(value)) {
        const auto result = std::to_chars(out, out + base::NumberFormat::kBufferSize, static_cast<long long>(value));
        return static_cast<std::size_t>(result.ptr - out);
    }
    return base::NumberFormat{3}.formatTo(value, out);
}

std::string wordText(const QJSValue& value)
{
    if (value.isUndefined() || value.isNull())
        return {};
    if (value.isNumber()) {
        char buffer[base::NumberFormat::kBufferSize];
        return std::string(buffer, numberWordText(value.toNumber(), buffer));
    }
    return value.toString().toStdString();
}

QJSValue scriptPoint(QJSEngine& engine, const toolpath::Vec3& p)
{
    QJSValue point = engine.newObject();
    point.setProperty("x", p.x);
    point.setProperty("y", p.y);
    point.setProperty("z", p.z);
    return point;
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

std::size_t VariableObject::textOf(double value, char* out) const
{
    if (m_cachedLength > 0 && value == m_cachedValue) {  // -0 and 0 have the same text: "-0" is never written
        std::memcpy(out, m_cachedText, m_cachedLength);
        return m_cachedLength;
    }
    const std::size_t length = m_format ? m_format->formatTo(value, out) : numberWordText(value, out);
    if (length > 0 && length <= sizeof m_cachedText) {
        std::memcpy(m_cachedText, out, length);
        m_cachedValue = value;
        m_cachedLength = length;
    }
    return length;
}

double VariableObject::resolutionOf(const std::optional<base::NumberFormat>& format)
{
    if (!format)
        return 0.001;  // numberWordText: whole numbers or 3 decimals
    return std::pow(10.0, -format->decimals) / std::abs(format->scale);
}

double VariableObject::writtenValue(double value) const
{
    if (m_format)
        return m_format->roundedValue(value);
    // Without a format numbers are written as whole numbers or with 3 decimals (numberWordText).
    return isIntegral(value) ? value : base::NumberFormat{3}.roundedValue(value);
}

QString VariableObject::format(const QJSValue& value)
{
    // null: an axis the move does not give (onRapid/onLinear pass null for it): no word.
    if (value.isNull())
        return {};
    std::string text;
    if (value.isNumber() && beyondMax(value.toNumber())) {
        m_engine->throwError(QJSValue::RangeError,
                             QStringLiteral("%1%2 is beyond the largest value the control reads (%3)")
                                 .arg(QString::fromStdString(m_value.prefix()))
                                 .arg(value.toNumber())
                                 .arg(m_max));
        return {};
    }
    if (value.isNumber() && std::isfinite(value.toNumber())) {
        char buffer[base::NumberFormat::kBufferSize];
        text.assign(buffer, textOf(value.toNumber(), buffer));
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

QJSValue VariableObject::bind(const QJSValue& valueName, const QJSValue& options)
{
    const std::string name = valueName.toString().toStdString();
    if (!valueName.isString() || !moveValueFromName(name)) {
        m_engine->throwError(QJSValue::TypeError,
                             QStringLiteral("bind(): unknown move value '%1'; known: %2")
                                 .arg(valueName.toString(), QString::fromStdString(moveValueNames())));
        return {};
    }
    if (!options.isUndefined() && !options.isObject()) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("bind(name, options): options must be an object"));
        return {};
    }
    QJSValue bound = m_engine->newObject();
    bound.setProperty(QStringLiteral("__camwbVariable"), m_engine->newQObject(this));
    bound.setProperty(QStringLiteral("value"), valueName);
    if (options.isObject()) {
        bound.setProperty(QStringLiteral("force"), options.property(QStringLiteral("force")).toBool());
        const QJSValue texts = options.property(QStringLiteral("texts"));
        if (!texts.isUndefined() && !texts.isObject()) {
            m_engine->throwError(QJSValue::TypeError, QStringLiteral("bind(): texts must be an object {code: text}"));
            return {};
        }
        bound.setProperty(QStringLiteral("texts"), texts);
    }
    return bound;
}

void VariableObject::setFeedParameters(const QJSValue& parameters)
{
    if (!parameters.isObject()) {
        m_engine->throwError(QJSValue::TypeError,
                             QStringLiteral("setFeedParameters() needs an object {kind: {text, feed}}"));
        return;
    }
    std::vector<FeedParameter> list;
    QJSValueIterator it(parameters);
    while (it.hasNext()) {
        it.next();
        const std::optional<toolpath::FeedKind> kind = toolpath::feedKindNamed(it.name().toStdString());
        const QJSValue text = it.value().property(QStringLiteral("text"));
        const QJSValue feed = it.value().property(QStringLiteral("feed"));
        if (!kind || !text.isString() || !feed.isNumber() || !(feed.toNumber() > 0)) {
            m_engine->throwError(QJSValue::TypeError,
                                 QStringLiteral("setFeedParameters(): '%1' needs a feed kind (cutting, plunge, entry, "
                                                "exit, finishing) with {text: string, feed: number > 0}")
                                     .arg(it.name()));
            return;
        }
        list.push_back({static_cast<int>(*kind), text.toString().toStdString(), feed.toNumber()});
    }
    m_feedParameters = std::move(list);
    m_value.reset();
}

const std::string* VariableObject::feedParameter(int feedKind, double feed) const
{
    for (const FeedParameter& p : m_feedParameters)
        if (p.kind == feedKind && std::abs(p.feed - feed) <= 1e-9 * std::max(1.0, p.feed))
            return &p.text;
    return nullptr;
}

void PendingObject::set(const QJSValue& text) { m_text = wordText(text); }

void VariableObject::setFormat(const QJSValue& format)
{
    auto* formatObject = qobject_cast<FormatObject*>(format.toQObject());
    if (!formatObject) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("setFormat() needs a format from createFormat()"));
        return;
    }
    m_format = formatObject->numberFormat();
    m_max = formatObject->max();
    m_resolution = resolutionOf(m_format);
    m_value.reset();
    m_cachedLength = 0;
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
    if (spec.hasProperty("scale")) {
        const double scale = spec.property("scale").toNumber();
        if (!std::isfinite(scale) || scale == 0) {
            m_engine->throwError(QJSValue::RangeError,
                                 QStringLiteral("createFormat(): scale must be a finite, non-zero number"));
            return {};
        }
        format.scale = scale;
    }
    format.trimTrailingZeros = spec.property("trim").toBool();
    format.keepDecimalPoint = spec.property("keepDecimalPoint").toBool();
    format.forceSign = spec.property("forceSign").toBool();
    if (spec.hasProperty("leadingZero"))
        format.leadingZero = spec.property("leadingZero").toBool();
    double max = 0;
    if (spec.hasProperty("max")) {
        max = spec.property("max").toNumber();
        if (!std::isfinite(max) || max <= 0) {
            m_engine->throwError(QJSValue::RangeError, QStringLiteral("createFormat(): max must be a positive number"));
            return {};
        }
    }
    return m_engine->newQObject(new FormatObject(m_engine, format, max));  // owned by the script engine
}

QJSValue ScriptKernel::makeVariable(const QJSValue& spec, const QJSValue& format, bool acceptsText)
{
    if (!spec.isUndefined() && !spec.isObject()) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("createVariable()/createModal() needs an object"));
        return {};
    }
    std::optional<base::NumberFormat> numberFormat;
    double max = 0;
    if (!format.isUndefined() && !format.isNull()) {
        auto* formatObject = qobject_cast<FormatObject*>(format.toQObject());
        if (!formatObject) {
            m_engine->throwError(QJSValue::TypeError, QStringLiteral("the format must come from createFormat()"));
            return {};
        }
        numberFormat = formatObject->numberFormat();
        max = formatObject->max();
    } else if (!acceptsText) {
        numberFormat = base::NumberFormat{};
    }
    const std::string prefix = spec.hasProperty("prefix") ? spec.property("prefix").toString().toStdString() : "";
    if (prefix.find_first_of("\r\n") != std::string::npos) {
        // Block templates write prefixes without scanning them: a line break must not get in.
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("a prefix cannot hold a line break"));
        return {};
    }
    const bool force = spec.property("force").toBool();
    return m_engine->newQObject(new VariableObject(m_engine, prefix, force, numberFormat, acceptsText, max));
}

QJSValue ScriptKernel::createPending() { return m_engine->newQObject(new PendingObject); }

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
    writer().writeBlock(texts);
}

void ScriptKernel::writeComment(const QJSValue& text) { writer().writeComment(wordText(text)); }

void ScriptKernel::writeln(const QJSValue& text) { writer().writeLine(wordText(text)); }

std::string errorFile(const QJSValue& error, const std::string& fallback)
{
    const QString name = error.property("fileName").toString();
    if (name.isEmpty() || name.startsWith(QLatin1String("<camwb-kernel>")))
        return fallback;
    const QUrl url(name);
    return url.isLocalFile() ? url.toLocalFile().toStdString() : name.toStdString();
}

std::pair<std::string, int> ScriptKernel::callerLocation()
{
    // QJSEngine has no public call-stack API: an Error created now carries the calling script's
    // file and line.
    m_engine->throwError(QJSValue::GenericError, QStringLiteral("location"));
    const QJSValue located = m_engine->catchError();
    return {errorFile(located, m_postFile), located.property("lineNumber").toInt()};
}

void ScriptKernel::warning(const QJSValue& text)
{
    const auto [file, line] = callerLocation();
    m_messages.push_back(base::warningDiagnostic(wordText(text), file, line));
}

void ScriptKernel::error(const QJSValue& text)
{
    m_postError = wordText(text);
    m_engine->throwError(QJSValue::GenericError, QString::fromStdString(*m_postError));
}

void ScriptKernel::setBlockNumbering(const QJSValue& start, const QJSValue& step, const QJSValue& enabled,
                                     const QJSValue& prefix)
{
    const double first = start.isUndefined() ? 10 : start.toNumber();
    const double increment = step.isUndefined() ? 10 : step.toNumber();
    if (!isIntegral(first) || !isIntegral(increment) || first < 0 || increment <= 0) {
        m_engine->throwError(
            QJSValue::RangeError,
            QStringLiteral("setBlockNumbering(start, step, enabled): start >= 0 and step > 0, integers"));
        return;
    }
    const std::string prefixText = prefix.isUndefined() ? "N" : prefix.toString().toStdString();
    if (prefixText.find_first_of("\r\n") != std::string::npos) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("a block number prefix cannot hold a line break"));
        return;
    }
    writer().setBlockNumbering(static_cast<long long>(first), static_cast<long long>(increment),
                               enabled.isUndefined() ? true : enabled.toBool(), prefixText);
}

QJSValue ScriptKernel::getCurrentPosition()
{
    const std::optional<toolpath::Vec3> point = m_position.point();
    if (!point)
        return QJSValue(QJSValue::NullValue);
    return scriptPoint(*m_engine, *point);
}

QJSValue ScriptKernel::getCurrentAxis(const QJSValue& axis)
{
    const QString name = axis.toString().toLower();
    const int index = name == QLatin1String("x")   ? 0
                      : name == QLatin1String("y") ? 1
                      : name == QLatin1String("z") ? 2
                                                   : -1;
    if (!axis.isString() || index < 0) {
        m_engine->throwError(
            QJSValue::TypeError,
            QStringLiteral("getCurrentAxis() needs \"x\", \"y\" or \"z\", got '%1'").arg(axis.toString()));
        return {};
    }
    if (!m_position.known(index))
        return QJSValue(QJSValue::NullValue);
    return QJSValue(m_position.value(index));
}

QJSValue ScriptKernel::getProperty(const QJSValue& name)
{
    const QString key = name.toString();
    if (m_sectionProperties.isObject() && m_sectionProperties.hasOwnProperty(key))
        return m_sectionProperties.property(key);
    if (m_properties.isObject() && m_properties.hasOwnProperty(key))
        return m_properties.property(key);
    // While the post is only being loaded, getProperty() answers the declared default.
    const QJSValue declared = m_engine->globalObject().property("post").property("properties");
    if (!m_properties.isObject() && declared.isObject() && declared.hasOwnProperty(key))
        return declared.property(key).property("default");
    m_engine->throwError(
        QJSValue::ReferenceError,
        QStringLiteral("getProperty(): the post declares no property '%1' in post.properties").arg(key));
    return {};
}

double ScriptKernel::machiningSeconds()
{
    if (!m_machiningSeconds)
        m_machiningSeconds = m_machiningTime ? m_machiningTime() : 0.0;
    return *m_machiningSeconds;
}

void ScriptKernel::expandCyclePoint(const QJSValue& x, const QJSValue& y, const QJSValue& z)
{
    if (!m_expandCycle) {
        m_engine->throwError(QJSValue::GenericError,
                             QStringLiteral("expandCyclePoint() works only inside onCyclePoint()"));
        return;
    }
    if (!x.isNumber() || !y.isNumber() || !z.isNumber()) {
        m_engine->throwError(QJSValue::TypeError, QStringLiteral("expandCyclePoint(x, y, z) needs three numbers"));
        return;
    }
    m_expandCycle({x.toNumber(), y.toNumber(), z.toNumber()});
}

}  // namespace camwb::post
