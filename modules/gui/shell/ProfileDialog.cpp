#include "gui/shell/ProfileDialog.h"

#include "occ/Model.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLineEdit>
#include <QMessageBox>

namespace camwb::gui {

namespace {

QDoubleSpinBox* heightBox(double value, QWidget* parent)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(-10000, 10000);
    box->setDecimals(3);
    box->setSuffix(QStringLiteral(" mm"));
    box->setValue(value);
    return box;
}

}  // namespace

ProfileDialog::ProfileDialog(const document::Operation& operation, const document::Job& job, const occ::Model& model,
                             QWidget* parent) :
    QDialog(parent),
    m_operation(operation)
{
    setWindowTitle(tr("Profile: %1").arg(QString::fromStdString(operation.profile.name)));
    auto* form = new QFormLayout(this);

    m_name = new QLineEdit(QString::fromStdString(operation.profile.name), this);
    form->addRow(tr("Name"), m_name);

    m_face = new QComboBox(this);
    for (int i = 1; i <= model.faceCount(); ++i) {
        const occ::FaceInfo face = model.face(i);
        const bool horizontal = face.planar && std::abs(std::abs(face.normal.z) - 1.0) < 1e-9;
        if (!horizontal)
            continue;
        m_face->addItem(tr("Face %1 at Z %2 (%3 mm²)").arg(i).arg(face.planeZ, 0, 'f', 3).arg(face.areaMm2, 0, 'f', 1),
                        i);
    }
    m_face->setCurrentIndex(std::max(0, m_face->findData(operation.profile.faceIndex)));
    form->addRow(tr("Boundary of face"), m_face);

    m_tool = new QComboBox(this);
    for (const ops::ToolController& tc : job.tools)
        m_tool->addItem(QStringLiteral("T%1 %2").arg(tc.tool.number).arg(QString::fromStdString(tc.tool.name)),
                        tc.tool.number);
    m_tool->setCurrentIndex(std::max(0, m_tool->findData(operation.toolNumber)));
    form->addRow(tr("Tool"), m_tool);

    m_direction = new QComboBox(this);
    m_direction->addItem(tr("Climb"), true);
    m_direction->addItem(tr("Conventional"), false);
    m_direction->setCurrentIndex(operation.profile.climb ? 0 : 1);
    form->addRow(tr("Direction"), m_direction);

    m_depth = heightBox(operation.profile.finalDepthZ, this);
    m_safe = heightBox(operation.profile.safeZ, this);
    m_clearance = heightBox(operation.profile.clearanceZ, this);
    m_name->setObjectName(QStringLiteral("nameEdit"));
    m_face->setObjectName(QStringLiteral("faceCombo"));
    m_depth->setObjectName(QStringLiteral("finalDepthBox"));
    m_safe->setObjectName(QStringLiteral("safeHeightBox"));
    m_clearance->setObjectName(QStringLiteral("clearanceHeightBox"));
    form->addRow(tr("Final depth (Z)"), m_depth);
    form->addRow(tr("Safe height (Z)"), m_safe);
    form->addRow(tr("Clearance height (Z)"), m_clearance);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        if (!(m_clearance->value() >= m_safe->value() && m_safe->value() > m_depth->value())) {
            QMessageBox::warning(this, windowTitle(),
                                 tr("Heights must satisfy clearance ≥ safe height > final depth."));
            return;
        }
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    form->addRow(buttons);
}

document::Operation ProfileDialog::operation() const
{
    document::Operation op = m_operation;
    op.profile.name = m_name->text().toStdString();
    op.profile.faceIndex = m_face->currentData().toInt();
    op.toolNumber = m_tool->currentData().toInt();
    op.profile.climb = m_direction->currentData().toBool();
    op.profile.finalDepthZ = m_depth->value();
    op.profile.safeZ = m_safe->value();
    op.profile.clearanceZ = m_clearance->value();
    return op;
}

}  // namespace camwb::gui
