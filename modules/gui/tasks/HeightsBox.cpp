#include "gui/tasks/HeightsBox.h"

#include "gui/tasks/LengthSpinBox.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QSignalBlocker>

namespace camwb::gui {

HeightsBox::HeightsBox(document::HeightOverrides& overrides, QWidget* parent) :
    QWidget(parent),
    m_overrides(overrides),
    m_rows{Row{&document::HeightOverrides::clearanceZ, &ops::Heights::clearanceZ},
           Row{&document::HeightOverrides::safeZ, &ops::Heights::safeZ},
           Row{&document::HeightOverrides::startZ, &ops::Heights::startZ},
           Row{&document::HeightOverrides::finalZ, &ops::Heights::finalZ}}
{
    const QString labels[4]{tr("Clearance Z"), tr("Safe Z"), tr("Start Z"), tr("Final Z")};
    const char* names[4]{"clearance", "safe", "start", "final"};
    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    for (int i = 0; i < 4; ++i) {
        Row& row = m_rows[i];
        row.automatic = new QCheckBox(tr("auto"), this);
        row.automatic->setObjectName(QLatin1String(names[i]) + QStringLiteral("Auto"));
        row.automatic->setToolTip(tr("Derived from the model and the stock; uncheck to set it"));
        row.value = new LengthSpinBox(this);
        row.value->setObjectName(QLatin1String(names[i]) + QStringLiteral("Box"));
        row.value->setRange(-10000, 10000);
        row.value->setKeyboardTracking(false);
        const std::optional<double>& set = overrides.*row.override;
        row.automatic->setChecked(!set);
        row.value->setEnabled(set.has_value());
        if (set)
            row.value->setValue(*set);
        grid->addWidget(new QLabel(labels[i], this), i, 0);
        grid->addWidget(row.value, i, 1);
        grid->addWidget(row.automatic, i, 2);

        connect(row.automatic, &QCheckBox::toggled, this, [this, i](bool automatic) {
            Row& r = m_rows[i];
            r.value->setEnabled(!automatic);
            // Unchecked: the shown (derived) value becomes the user's, to be edited from there.
            m_overrides.*r.override = automatic ? std::nullopt : std::optional<double>(r.value->value());
            emit changed();
        });
        connect(row.value, &QDoubleSpinBox::valueChanged, this, [this, i](double value) {
            Row& r = m_rows[i];
            if (r.automatic->isChecked())
                return;
            m_overrides.*r.override = value;
            emit changed();
        });
    }
    grid->setColumnStretch(1, 1);
}

void HeightsBox::setDerived(const ops::Heights& heights)
{
    for (Row& row : m_rows) {
        if (!row.automatic->isChecked())
            continue;
        const QSignalBlocker quiet(row.value);
        row.value->setValue(heights.*row.derived);
    }
}

}  // namespace camwb::gui
