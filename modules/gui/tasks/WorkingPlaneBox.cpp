#include "gui/tasks/WorkingPlaneBox.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSpinBox>

namespace camwb::gui {

using Mode = document::WorkingPlaneSpec::Mode;

WorkingPlaneBox::WorkingPlaneBox(document::WorkingPlaneSpec& spec, int faceCount, QWidget* parent) :
    QWidget(parent),
    m_spec(spec)
{
    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("planeMode"));
    m_mode->addItem(tr("Flat (tool along Z)"), static_cast<int>(Mode::Flat));
    m_mode->addItem(tr("Along a face's normal"), static_cast<int>(Mode::Face));
    m_mode->addItem(tr("Spatial angles"), static_cast<int>(Mode::Angles));
    m_mode->setCurrentIndex(m_mode->findData(static_cast<int>(spec.mode)));
    m_mode->setToolTip(tr("3+2: the plane the operation is computed in; the post tilts the machine to it. "
                          "Flat drilling turns to each hole's own axis."));
    form->addRow(tr("Plane"), m_mode);

    m_face = new QSpinBox(this);
    m_face->setObjectName(QStringLiteral("planeFace"));
    m_face->setRange(1, std::max(1, faceCount));
    m_face->setValue(std::max(1, spec.face));
    m_face->setToolTip(tr("The planar face whose outward normal the tool follows"));
    form->addRow(tr("Face"), m_face);

    const QString names[3] = {tr("A (about X)"), tr("B (about Y)"), tr("C (about Z)")};
    double* values[3] = {&spec.aDeg, &spec.bDeg, &spec.cDeg};
    for (int i = 0; i < 3; ++i) {
        auto* box = new QDoubleSpinBox(this);
        box->setObjectName(QStringLiteral("planeAngle%1").arg(QChar('A' + i)));
        box->setRange(-360, 360);
        box->setDecimals(4);
        box->setSuffix(QStringLiteral("°"));
        box->setKeyboardTracking(false);
        box->setValue(*values[i]);
        form->addRow(names[i], box);
        m_angles[i] = box;
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, values, i](double v) {
            *values[i] = v;
            emit changed();
        });
    }
    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] {
        m_spec.mode = static_cast<Mode>(m_mode->currentData().toInt());
        if (m_spec.mode == Mode::Face)
            m_spec.face = m_face->value();
        showMode();
        emit changed();
    });
    connect(m_face, &QSpinBox::valueChanged, this, [this](int face) {
        m_spec.face = face;
        emit changed();
    });
    showMode();
}

void WorkingPlaneBox::showMode()
{
    auto* form = static_cast<QFormLayout*>(layout());
    form->setRowVisible(m_face, m_spec.mode == Mode::Face);
    for (QDoubleSpinBox* box : m_angles)
        form->setRowVisible(box, m_spec.mode == Mode::Angles);
}

}  // namespace camwb::gui
