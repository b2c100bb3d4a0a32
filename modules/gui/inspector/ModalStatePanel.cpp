#include "gui/inspector/ModalStatePanel.h"

#include "gui/inspector/NcTrace.h"

#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace camwb::gui {

namespace {

QString mm(double value) { return QString::number(value, 'f', 3); }

QString position(const ModalState& state)
{
    if (!state.hasPosition)
        return ModalStatePanel::tr("unknown (no move yet)");
    return QStringLiteral("X%1 Y%2 Z%3").arg(mm(state.position.x), mm(state.position.y), mm(state.position.z));
}

QString feedText(const ModalState& state)
{
    switch (state.feedMode) {
    case toolpath::FeedMode::PerMinute:
        return ModalStatePanel::tr("%1 mm/min (G94)").arg(state.feed, 0, 'f', 1);
    case toolpath::FeedMode::PerRevolution:
        return ModalStatePanel::tr("%1 mm/rev (G95)").arg(state.feed, 0, 'f', 3);
    case toolpath::FeedMode::InverseTime:
        return ModalStatePanel::tr("%1 1/min (G93)").arg(state.feed, 0, 'f', 3);
    }
    return {};
}

QString spindleText(const ModalState& state)
{
    if (state.spindleRpm <= 0 && state.surfaceSpeedMPerMin <= 0)
        return ModalStatePanel::tr("stopped (M5)");
    const QString direction = state.spindleClockwise ? ModalStatePanel::tr("CW (M3)") : ModalStatePanel::tr("CCW (M4)");
    if (state.surfaceSpeedMPerMin > 0)
        return ModalStatePanel::tr("%1 m/min constant surface speed, %2").arg(state.surfaceSpeedMPerMin).arg(direction);
    return ModalStatePanel::tr("%1 rpm %2").arg(state.spindleRpm, 0, 'f', 0).arg(direction);
}

QString coolantText(toolpath::CoolantMode mode)
{
    switch (mode) {
    case toolpath::CoolantMode::Off:
        return ModalStatePanel::tr("off (M9)");
    case toolpath::CoolantMode::Flood:
        return ModalStatePanel::tr("flood (M8)");
    case toolpath::CoolantMode::Mist:
        return ModalStatePanel::tr("mist (M7)");
    case toolpath::CoolantMode::ThroughTool:
        return ModalStatePanel::tr("through tool");
    }
    return {};
}

QString compensationText(toolpath::CutterCompSide side)
{
    switch (side) {
    case toolpath::CutterCompSide::Off:
        return ModalStatePanel::tr("off (G40)");
    case toolpath::CutterCompSide::Left:
        return ModalStatePanel::tr("left (G41)");
    case toolpath::CutterCompSide::Right:
        return ModalStatePanel::tr("right (G42)");
    }
    return {};
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

void ModalStatePanel::showState(const LineState& state, const NcTrace& trace)
{
    auto set = [this](const char* key, const QString& text) {
        if (auto* label = findChild<QLabel*>(QStringLiteral("modal_") + QLatin1String(key)))
            label->setText(text);
    };
    const ModalState& s = state.after;
    QString block = tr("line %1").arg(state.line);
    if (state.runs > 1)
        block += tr(", runs %1 times (first run shown)").arg(state.runs);
    set("block", block);
    set("move", state.move.empty() ? tr("no motion") : QString::fromStdString(state.move));
    set("tool", s.tool > 0 ? QStringLiteral("T%1").arg(s.tool) : tr("none called yet"));
    set("feed", feedText(s));
    set("spindle", spindleText(s));
    set("coolant", coolantText(s.coolant));
    set("workOffset", s.workOffset > 0 ? tr("%1 (G%2)").arg(s.workOffset).arg(53 + s.workOffset)
                                       : tr("none in the trace (control default)"));
    set("compensation", compensationText(s.compensation));
    // The records carry no plane, units or distance mode: say what they do carry.
    set("plane", s.hasArcNormal ? tr("%1, from the last arc").arg(QString::fromStdString(planeOfNormal(s.arcNormal)))
                                : tr("no arc yet (not in the trace)"));
    set("units", tr("mm (inch programs converted)"));
    set("distance", tr("not in the trace; positions absolute"));
    set("before", position(state.before));
    set("after", position(state.after));
    showMessage(trace.result.completed || trace.result.diagnostics.empty()
                    ? QString()
                    : tr("%n diagnostic(s) in this program.", nullptr, int(trace.result.diagnostics.size())));
}

}  // namespace camwb::gui
