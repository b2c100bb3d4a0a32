#include "gui/inspector/ModalStatePanel.h"

#include "document/NcTrace.h"

#include <QFormLayout>
#include <QLabel>
#include <QStringList>
#include <QVBoxLayout>

#include <cmath>
#include <functional>

namespace camwb::gui {

namespace {

// Fixed decimals without a sign on a value that rounds to zero ("-0.000" reads as a position
// on the other side).
QString fixed(double value, int decimals)
{
    const double half = 0.5 * std::pow(10.0, -decimals);
    return QString::number(std::abs(value) < half ? 0.0 : value, 'f', decimals);
}

QString mm(double value) { return fixed(value, 3); }

QString position(const document::ModalState& state)
{
    if (!state.hasPosition)
        return ModalStatePanel::tr("unknown (no move yet)");
    return QStringLiteral("X%1 Y%2 Z%3").arg(mm(state.position.x), mm(state.position.y), mm(state.position.z));
}

QString toolAxisText(const document::ModalState& state)
{
    const QString vector = QStringLiteral("I%1 J%2 K%3")
                               .arg(fixed(state.toolAxis.x, 4), fixed(state.toolAxis.y, 4), fixed(state.toolAxis.z, 4));
    return state.fiveAxis ? ModalStatePanel::tr("%1 (five-axis move)").arg(vector)
                          : ModalStatePanel::tr("%1 (3-axis move)").arg(vector);
}

// The machine's rotary axes the interpreter read through the machine's kinematics.
QString rotaryAxesText(const document::ModalState& state)
{
    const toolpath::RotaryAxes& r = state.rotaryAxes;
    QStringList axes;
    if (r.has(toolpath::RotaryAxes::kA))
        axes << QStringLiteral("A%1").arg(mm(r.aDeg));
    if (r.has(toolpath::RotaryAxes::kB))
        axes << QStringLiteral("B%1").arg(mm(r.bDeg));
    if (r.has(toolpath::RotaryAxes::kC))
        axes << QStringLiteral("C%1").arg(mm(r.cDeg));
    if (axes.isEmpty())
        return ModalStatePanel::tr("none known (trace with a five-axis machine)");
    return axes.join(QLatin1Char(' '));
}

// "meaning (word)"; the meaning alone without a word (a CL file has no NC words).
QString withWord(const QString& meaning, const QString& word)
{
    return word.isEmpty() ? meaning : QStringLiteral("%1 (%2)").arg(meaning, word);
}

// The ISO word a record stands for (G94, M5), none for a CL file (`cl`).
QString isoWord(const char* word, bool cl) { return cl ? QString() : QString::fromLatin1(word); }

// `word`: the program's own word for the feed mode (G94, F, FU ...), else the ISO one; none
// for a CL file (`cl`).
QString feedText(const document::ModalState& state, const char* word, bool cl)
{
    const bool own = word != nullptr && *word != 0;
    const auto wordOr = [&](const char* iso) { return own ? QString::fromLatin1(word) : isoWord(iso, cl); };
    switch (state.feedMode) {
    case toolpath::FeedMode::PerMinute:
        return withWord(ModalStatePanel::tr("%1 mm/min").arg(state.feed, 0, 'f', 1), wordOr("G94"));
    case toolpath::FeedMode::PerRevolution:
        return withWord(ModalStatePanel::tr("%1 mm/rev").arg(state.feed, 0, 'f', 3), wordOr("G95"));
    case toolpath::FeedMode::InverseTime:
        return withWord(ModalStatePanel::tr("%1 1/min").arg(state.feed, 0, 'f', 3), wordOr("G93"));
    }
    return {};
}

QString spindleText(const document::ModalState& state, bool cl)
{
    const auto m = [cl](const char* word) { return isoWord(word, cl); };
    if (state.spindleRpm <= 0 && state.surfaceSpeedMPerMin <= 0)
        return withWord(ModalStatePanel::tr("stopped"), m("M5"));
    const QString direction = state.spindleClockwise ? withWord(ModalStatePanel::tr("CW"), m("M3"))
                                                     : withWord(ModalStatePanel::tr("CCW"), m("M4"));
    if (state.surfaceSpeedMPerMin > 0)
        return ModalStatePanel::tr("%1 m/min constant surface speed, %2").arg(state.surfaceSpeedMPerMin).arg(direction);
    return ModalStatePanel::tr("%1 rpm %2").arg(state.spindleRpm, 0, 'f', 0).arg(direction);
}

QString coolantText(toolpath::CoolantMode mode, bool cl)
{
    const auto m = [cl](const char* word) { return isoWord(word, cl); };
    switch (mode) {
    case toolpath::CoolantMode::Off:
        return withWord(ModalStatePanel::tr("off"), m("M9"));
    case toolpath::CoolantMode::Flood:
        return withWord(ModalStatePanel::tr("flood"), m("M8"));
    case toolpath::CoolantMode::Mist:
        return withWord(ModalStatePanel::tr("mist"), m("M7"));
    case toolpath::CoolantMode::ThroughTool:
        return ModalStatePanel::tr("through tool");
    }
    return {};
}

// "RL (left of the contour)"; without the program's word the meaning alone.
QString compensationText(toolpath::CutterCompSide side, const QString& word)
{
    QString meaning;
    switch (side) {
    case toolpath::CutterCompSide::Off:
        meaning = ModalStatePanel::tr("off");
        break;
    case toolpath::CutterCompSide::Left:
        meaning = ModalStatePanel::tr("left of the contour");
        break;
    case toolpath::CutterCompSide::Right:
        meaning = ModalStatePanel::tr("right of the contour");
        break;
    }
    return word.isEmpty() ? meaning : QStringLiteral("%1 (%2)").arg(word, meaning);
}

QString planeName(int plane)
{
    return plane == 18 ? QStringLiteral("ZX") : plane == 19 ? QStringLiteral("YZ") : QStringLiteral("XY");
}

QString distanceText(const nc::BlockModal& words)
{
    const QString word = QString::fromLatin1(words.distanceWord);
    switch (words.distance) {
    case nc::BlockModal::Distance::Absolute:
        return ModalStatePanel::tr("%1 (absolute)").arg(word);
    case nc::BlockModal::Distance::Incremental:
        return ModalStatePanel::tr("%1 (incremental)").arg(word);
    case nc::BlockModal::Distance::Mixed:
        return ModalStatePanel::tr("%1 (absolute and incremental words)").arg(word);
    case nc::BlockModal::Distance::PerWord:
        return ModalStatePanel::tr("%1 (absolute or incremental per coordinate)").arg(word);
    }
    return {};
}

QString unitsText(const nc::BlockModal& words)
{
    return words.inch
               ? ModalStatePanel::tr("%1 (inch; positions shown in mm)").arg(QString::fromLatin1(words.unitsWord))
               : ModalStatePanel::tr("%1 (mm)").arg(QString::fromLatin1(words.unitsWord));
}

// The state the program set, in its own words (BlockModal); the rows the records cannot fill.
void showWords(const std::function<void(const char*, const QString&)>& set, const nc::BlockModal& words,
               const document::ModalState& s)
{
    set("feed", feedText(s, words.feedModeWord, false));
    set("compensation", compensationText(words.compensation, QString::fromLatin1(words.compensationWord)));
    set("plane", QStringLiteral("%1 (%2)").arg(QString::fromLatin1(words.planeWord), planeName(words.plane)));
    set("units", unitsText(words));
    set("distance", distanceText(words));
    set("workOffset", words.workOffset.empty() ? ModalStatePanel::tr("none programmed (control default)")
                                               : QString::fromStdString(words.workOffset));
}

}  // namespace

ModalStatePanel::ModalStatePanel(QWidget* parent) :
    QWidget(parent),
    m_form(new QFormLayout),
    m_message(new QLabel(this))
{
    auto* layout = new QVBoxLayout(this);
    m_message->setObjectName(QStringLiteral("modalMessage"));
    m_message->setWordWrap(true);
    layout->addWidget(m_message);
    layout->addLayout(m_form);
    layout->addStretch(1);
    m_form->setLabelAlignment(Qt::AlignRight);
    addRow(QStringLiteral("block"), tr("Block"));
    addRow(QStringLiteral("move"), tr("Move"));
    addRow(QStringLiteral("tool"), tr("Tool"));
    addRow(QStringLiteral("feed"), tr("Feed"));
    addRow(QStringLiteral("spindle"), tr("Spindle"));
    addRow(QStringLiteral("coolant"), tr("Coolant"));
    addRow(QStringLiteral("workOffset"), tr("Work offset"));
    addRow(QStringLiteral("compensation"), tr("Compensation"));
    addRow(QStringLiteral("plane"), tr("Plane"));
    addRow(QStringLiteral("units"), tr("Units"));
    addRow(QStringLiteral("distance"), tr("Abs/inc"));
    addRow(QStringLiteral("before"), tr("Before"));
    addRow(QStringLiteral("after"), tr("After"));
    addRow(QStringLiteral("toolAxis"), tr("Tool axis"));
    addRow(QStringLiteral("rotaryAxes"), tr("Rotary axes"));
    showMessage(tr("No NC program traced yet."));
}

QLabel* ModalStatePanel::addRow(const QString& key, const QString& label)
{
    auto* value = new QLabel(this);
    value->setObjectName(QStringLiteral("modal_") + key);
    value->setTextInteractionFlags(Qt::TextSelectableByMouse);
    value->setWordWrap(true);
    m_form->addRow(label, value);
    return value;
}

QString ModalStatePanel::value(const QString& row) const
{
    auto* label = findChild<QLabel*>(QStringLiteral("modal_") + row);
    return label != nullptr ? label->text() : QString();
}

void ModalStatePanel::showMessage(const QString& text)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
}

void ModalStatePanel::showState(const document::LineState& state, const document::NcTrace& trace)
{
    auto set = [this](const char* key, const QString& text) {
        if (auto* label = findChild<QLabel*>(QStringLiteral("modal_") + QLatin1String(key)))
            label->setText(text);
    };
    const document::ModalState& s = state.after;
    QString block = tr("line %1").arg(state.line);
    if (state.runs > 1)
        block += tr(", runs %1 times (first run shown)").arg(state.runs);
    set("block", block);
    set("move", state.move.empty() ? tr("no motion") : QString::fromStdString(state.move));
    set("tool", s.tool > 0 ? QStringLiteral("T%1").arg(s.tool) : tr("none called yet"));
    const bool cl = trace.clFormat.has_value();  // a CL file: what its records say, no NC words
    set("spindle", spindleText(s, cl));
    set("coolant", coolantText(s.coolant, cl));
    if (state.words) {
        showWords(set, *state.words, s);
    } else {
        // A CL file, or no block has run yet (or the trace was cut short): what the records carry.
        set("feed", feedText(s, nullptr, cl));
        set("workOffset", s.workOffset <= 0 ? tr("none in the trace (control default)")
                          : cl              ? QString::number(s.workOffset)
                                            : tr("%1 (G%2)").arg(s.workOffset).arg(53 + s.workOffset));
        set("compensation", compensationText(s.compensation, QString()));
        set("plane", s.hasArcNormal
                         ? tr("%1, from the last arc").arg(QString::fromStdString(document::planeOfNormal(s.arcNormal)))
                         : tr("no arc yet (not in the trace)"));
        set("units", cl ? tr("mm (an inch CL file converted)") : tr("mm (inch programs converted)"));
        set("distance", cl ? tr("absolute (CL positions)") : tr("not in the trace; positions absolute"));
    }
    set("before", position(state.before));
    set("after", position(state.after));
    set("toolAxis", toolAxisText(state.after));
    set("rotaryAxes", rotaryAxesText(state.after));
    showMessage(trace.result.completed || trace.result.diagnostics.empty()
                    ? QString()
                    : tr("%n diagnostic(s) in this program.", nullptr, int(trace.result.diagnostics.size())));
}

}  // namespace camwb::gui
