// Rows generated from the post's property definitions; values travel as the kernel's canonical
// text (post::parsePropertyValue), so the form, the job file and --property agree on "10" vs "10.0".
#include "gui/tasks/PostPropertiesForm.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QToolButton>

#include <climits>
#include <cmath>

namespace camwb::gui {

namespace {

QString q(const std::string& text) { return QString::fromStdString(text); }

// `text` as the property's canonical text, or empty when the property refuses it.
std::optional<std::string> canonical(const post::PropertyDef& def, const std::string& text)
{
    auto parsed = post::parsePropertyValue(def, text);
    return parsed ? std::optional<std::string>(parsed->text) : std::nullopt;
}

QString rangeText(const post::PropertyDef& def)
{
    if (!def.min && !def.max)
        return {};
    auto bound = [](const std::optional<double>& b) { return b ? QString::number(*b, 'g', 12) : QString(); };
    return QStringLiteral(" [%1..%2]").arg(bound(def.min), bound(def.max));
}

}  // namespace

PostPropertiesForm::PostPropertiesForm(QWidget* parent) : QWidget(parent)
{
    m_grid = new QGridLayout(this);
    m_grid->setColumnStretch(1, 1);
    m_empty = new QLabel(tr("This post has no properties."), this);
    m_grid->addWidget(m_empty, 0, 0, 1, 4);
}

void PostPropertiesForm::setPost(const post::PostInfo& info, const std::map<std::string, std::string>& values)
{
    for (const Row& row : m_rows)
        for (QWidget* widget : {static_cast<QWidget*>(row.label), row.editor, static_cast<QWidget*>(row.reset)})
            delete widget;
    qDeleteAll(findChildren<QLabel*>(QStringLiteral("defaultHint"), Qt::FindDirectChildrenOnly));
    qDeleteAll(findChildren<QLabel*>(QStringLiteral("sectionHeading"), Qt::FindDirectChildrenOnly));
    m_rows.clear();
    m_info = info;
    m_empty->setVisible(m_info.properties.empty());
    m_rows.reserve(m_info.properties.size());

    // The job's own properties first, then those the operations may override (the job's value is
    // their default), each group in the post's order.
    int gridRow = 1;
    for (bool perOperation : {false, true}) {
        bool headed = false;
        for (const post::PropertyDef& def : m_info.properties) {
            if (def.perOperation != perOperation)
                continue;
            if (perOperation && !headed) {
                auto* heading = new QLabel(tr("<b>Defaults for operations</b> (an operation may set its own)"), this);
                heading->setObjectName(QStringLiteral("sectionHeading"));
                m_grid->addWidget(heading, gridRow++, 0, 1, 4);
                headed = true;
            }
            const auto it = values.find(def.name);
            const std::optional<std::string> given = it == values.end() ? std::nullopt : canonical(def, it->second);
            addRow(def, given ? *given : def.defaultValue, gridRow++);
        }
    }
    // The rows stay together at the top of a tall form.
    for (int r = 0; r < m_grid->rowCount(); ++r)
        m_grid->setRowStretch(r, 0);
    m_grid->setRowStretch(gridRow, 1);
}

void PostPropertiesForm::addRow(const post::PropertyDef& def, const std::string& value, int gridRow)
{
    Row row;
    row.def = &def;
    const QString tip = q(def.description).isEmpty() ? q(def.name) : q(def.description);
    QString fullTip =
        QStringLiteral("%1\n\n%2 (%3%4)").arg(tip, q(def.name), q(post::propertyTypeName(def.type)), rangeText(def));
    if (m_compact)  // no column for the default: it is in the tooltip and on the reset button's
        fullTip += QLatin1Char('\n') + tr("(default: %1)").arg(q(def.defaultValue));
    row.label = new QLabel(q(def.title.empty() ? def.name : def.title), this);
    row.label->setToolTip(fullTip);

    switch (def.type) {
    case post::PropertyType::Bool: {
        auto* box = new QCheckBox(this);
        connect(box, &QCheckBox::toggled, this, [this, name = def.name] { edited(*this->row(name)); });
        row.editor = box;
        break;
    }
    case post::PropertyType::Enum: {
        auto* box = new QComboBox(this);
        for (const std::string& item : def.values)
            box->addItem(q(item));
        connect(box, &QComboBox::currentIndexChanged, this, [this, name = def.name] { edited(*this->row(name)); });
        row.editor = box;
        break;
    }
    case post::PropertyType::Integer: {
        auto* box = new QSpinBox(this);
        box->setRange(def.min ? static_cast<int>(std::ceil(*def.min)) : INT_MIN,
                      def.max ? static_cast<int>(std::floor(*def.max)) : INT_MAX);
        connect(box, &QSpinBox::valueChanged, this, [this, name = def.name] { edited(*this->row(name)); });
        row.editor = box;
        break;
    }
    case post::PropertyType::Number: {
        auto* box = new QDoubleSpinBox(this);
        box->setDecimals(4);
        box->setRange(def.min ? *def.min : -1e9, def.max ? *def.max : 1e9);
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, name = def.name] { edited(*this->row(name)); });
        row.editor = box;
        break;
    }
    case post::PropertyType::String: {
        auto* edit = new QLineEdit(this);
        edit->setPlaceholderText(tr("(empty)"));
        connect(edit, &QLineEdit::textEdited, this, [this, name = def.name] { edited(*this->row(name)); });
        row.editor = edit;
        break;
    }
    }
    row.editor->setObjectName(QStringLiteral("property.") + q(def.name));
    row.editor->setToolTip(fullTip);
    row.label->setBuddy(row.editor);

    QLabel* hint = nullptr;
    if (!m_compact) {
        hint = new QLabel(tr("(default: %1)").arg(q(def.defaultValue)), this);
        hint->setObjectName(QStringLiteral("defaultHint"));
        hint->setEnabled(false);  // greyed: a hint, not a value
    }

    row.reset = new QToolButton(this);
    row.reset->setObjectName(QStringLiteral("reset.") + q(def.name));
    row.reset->setText(tr("Reset"));
    row.reset->setToolTip(tr("Reset %1 to its default, %2").arg(row.label->text(), q(def.defaultValue)));
    connect(row.reset, &QToolButton::clicked, this, [this, name = def.name] { resetToDefault(name); });

    m_grid->addWidget(row.label, gridRow, 0);
    m_grid->addWidget(row.editor, gridRow, 1);
    if (hint != nullptr)
        m_grid->addWidget(hint, gridRow, 2);
    m_grid->addWidget(row.reset, gridRow, hint != nullptr ? 3 : 2);
    m_rows.push_back(row);
    show(m_rows.back(), value);
}

void PostPropertiesForm::show(const Row& row, const std::string& value)
{
    m_showing = true;
    if (auto* box = qobject_cast<QCheckBox*>(row.editor))
        box->setChecked(value == "true");
    else if (auto* combo = qobject_cast<QComboBox*>(row.editor))
        combo->setCurrentIndex(combo->findText(q(value)));
    else if (auto* spin = qobject_cast<QSpinBox*>(row.editor))
        spin->setValue(q(value).toInt());
    else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(row.editor))
        dspin->setValue(q(value).toDouble());
    else if (auto* edit = qobject_cast<QLineEdit*>(row.editor))
        edit->setText(q(value));
    m_showing = false;
    markDefault(row);
}

std::string PostPropertiesForm::value(const std::string& name) const
{
    const Row* r = row(name);
    if (!r)
        return {};
    std::string text;
    if (auto* box = qobject_cast<QCheckBox*>(r->editor))
        text = box->isChecked() ? "true" : "false";
    else if (auto* combo = qobject_cast<QComboBox*>(r->editor))
        text = combo->currentText().toStdString();
    else if (auto* spin = qobject_cast<QSpinBox*>(r->editor))
        text = std::to_string(spin->value());
    else if (auto* dspin = qobject_cast<QDoubleSpinBox*>(r->editor))
        text = QString::number(dspin->value(), 'g', 12).toStdString();
    else if (auto* edit = qobject_cast<QLineEdit*>(r->editor))
        text = edit->text().toStdString();
    return canonical(*r->def, text).value_or(r->def->defaultValue);
}

std::map<std::string, std::string> PostPropertiesForm::values() const
{
    std::map<std::string, std::string> result;
    for (const Row& r : m_rows)
        if (std::string text = value(r.def->name); text != r.def->defaultValue)
            result[r.def->name] = std::move(text);
    return result;
}

void PostPropertiesForm::resetToDefault(const std::string& name)
{
    const Row* r = row(name);
    if (!r || value(name) == r->def->defaultValue)
        return;
    show(*r, r->def->defaultValue);
    emit changed();
}

QWidget* PostPropertiesForm::editor(const std::string& name) const
{
    const Row* r = row(name);
    return r ? r->editor : nullptr;
}

void PostPropertiesForm::edited(const Row& row)
{
    if (m_showing)
        return;
    markDefault(row);
    emit changed();
}

void PostPropertiesForm::markDefault(const Row& row)
{
    const bool isDefault = value(row.def->name) == row.def->defaultValue;
    for (QWidget* widget : {static_cast<QWidget*>(row.label), row.editor}) {
        QFont font = widget->font();
        font.setBold(!isDefault);
        widget->setFont(font);
    }
    row.reset->setEnabled(!isDefault);
}

const PostPropertiesForm::Row* PostPropertiesForm::row(const std::string& name) const
{
    for (const Row& r : m_rows)
        if (r.def->name == name)
            return &r;
    return nullptr;
}

}  // namespace camwb::gui
