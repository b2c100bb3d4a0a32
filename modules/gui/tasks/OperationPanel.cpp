#include "gui/tasks/OperationPanel.h"

#include "document/JobFile.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/GeometryList.h"
#include "gui/tasks/HeightsBox.h"
#include "gui/tasks/ParamForm.h"
#include "gui/tasks/PreviewRunner.h"
#include "gui/tasks/WorkingPlaneBox.h"
#include "gui/tasks/detail/KindPanels.h"
#include "gui/view3d/TaskOverlay.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace camwb::gui {

namespace {

QString kindTitle(document::OperationKind kind)
{
    switch (kind) {
    case document::OperationKind::Contour:
        return OperationPanel::tr("Contour");
    case document::OperationKind::Pocket:
        return OperationPanel::tr("Pocket");
    case document::OperationKind::Helix:
        return OperationPanel::tr("Helix");
    case document::OperationKind::Swarf:
        return OperationPanel::tr("Swarf (simultaneous five-axis)");
    case document::OperationKind::Pocket3d:
        return OperationPanel::tr("3D Pocket");
    case document::OperationKind::Waterline:
        return OperationPanel::tr("Waterline");
    case document::OperationKind::Parallel:
        return OperationPanel::tr("Parallel");
    case document::OperationKind::Groove:
        return OperationPanel::tr("Groove roughing (turning)");
    case document::OperationKind::Drill:
        break;
    }
    return OperationPanel::tr("Drilling");
}

QGroupBox* group(const QString& title, QWidget* content)
{
    auto* box = new QGroupBox(title);
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(content);
    return box;
}

}  // namespace

OperationPanel* OperationPanel::create(Workbench& workbench, TaskOverlay* overlay, int index,
                                       const document::Operation& operation,
                                       const std::optional<ops::ToolController>& newTool, QWidget* parent)
{
    const OperationPanelArgs args{workbench, overlay, index, operation, newTool, parent};
    OperationPanel* panel = nullptr;
    switch (operation.kind()) {
    case document::OperationKind::Contour:
        panel = makeContourPanel(args);
        break;
    case document::OperationKind::Pocket:
        panel = makePocketPanel(args);
        break;
    case document::OperationKind::Helix:
        panel = makeHelixPanel(args);
        break;
    case document::OperationKind::Drill:
        panel = makeDrillPanel(args);
        break;
    case document::OperationKind::Swarf:
        panel = makeSwarfPanel(args);
        break;
    case document::OperationKind::Pocket3d:
        panel = makePocket3dPanel(args);
        break;
    case document::OperationKind::Waterline:
        panel = makeWaterlinePanel(args);
        break;
    case document::OperationKind::Parallel:
        panel = makeParallelPanel(args);
        break;
    case document::OperationKind::Groove:
        panel = makeGroovePanel(args);
        break;
    }
    panel->build();
    return panel;
}

OperationPanel::OperationPanel(const OperationPanelArgs& args) :
    QWidget(args.parent),
    m_op(args.operation),
    m_workbench(args.workbench),
    m_overlay(args.overlay),
    m_index(args.index),
    m_newTool(args.newTool),
    m_preview(new PreviewRunner(this)),
    m_original(args.operation)
{
    setObjectName(QStringLiteral("operationPanel"));
}

OperationPanel::~OperationPanel()
{
    if (!m_finished && m_overlay != nullptr)
        m_overlay->clearPreview();
}

void OperationPanel::build()
{
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);
    auto* title = new QLabel(
        QStringLiteral("<b>%1</b> — %2")
            .arg(kindTitle(m_op.kind()), m_index < 0 ? tr("new operation") : tr("operation %1").arg(m_index + 1)),
        this);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setObjectName(QStringLiteral("okButton"));
    buttons->button(QDialogButtonBox::Cancel)->setObjectName(QStringLiteral("cancelButton"));
    connect(buttons, &QDialogButtonBox::accepted, this, &OperationPanel::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &OperationPanel::reject);
    outer->addWidget(title);
    outer->addWidget(buttons);

    // Preview status first: it answers "did my change work" without scrolling.
    auto* previewBox = new QWidget;
    auto* previewLayout = new QVBoxLayout(previewBox);
    previewLayout->setContentsMargins(0, 0, 0, 0);
    m_status = new QLabel(tr("Preview pending…"));
    m_status->setObjectName(QStringLiteral("previewStatus"));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_progress = new QProgressBar;
    m_progress->setObjectName(QStringLiteral("previewProgress"));
    m_progress->setRange(0, 100);
    m_cancelCompute = new QPushButton(tr("Cancel"));
    m_cancelCompute->setObjectName(QStringLiteral("cancelPreviewButton"));
    m_cancelCompute->setToolTip(tr("Stop computing the preview (the operation stays as edited)"));
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(m_progress, 1);
    progressRow->addWidget(m_cancelCompute);
    previewLayout->addWidget(m_status);
    previewLayout->addLayout(progressRow);
    outer->addWidget(group(tr("Preview"), previewBox));

    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->setContentsMargins(0, 0, 0, 0);

    auto* general = new QWidget;
    auto* generalForm = new QFormLayout(general);
    m_name = new QLineEdit(QString::fromStdString(m_op.name()));
    m_name->setObjectName(QStringLiteral("nameEdit"));
    generalForm->addRow(tr("Name"), m_name);
    m_tool = new QComboBox;
    m_tool->setObjectName(QStringLiteral("toolCombo"));
    std::vector<ops::ToolController> tools = m_workbench.job().tools;
    if (m_newTool)
        tools.push_back(*m_newTool);
    for (const ops::ToolController& tc : tools) {
        // A grooving insert's diameter field holds its width.
        m_tool->addItem((tc.tool.kind == "groove" ? tr("T%1 %2 (width %3 mm)") : tr("T%1 %2 (Ø%3 mm)"))
                            .arg(tc.tool.number)
                            .arg(QString::fromStdString(tc.tool.name))
                            .arg(tc.tool.diameterMm, 0, 'g', 4),
                        tc.tool.number);
        if (tc.tool.number == m_op.toolNumber)
            m_tool->setCurrentIndex(m_tool->count() - 1);
    }
    generalForm->addRow(tr("Tool"), m_tool);
    column->addWidget(group(tr("Operation"), general));

    m_geometry = new GeometryList(m_op.geometry, geometryKinds(), m_workbench.model(), m_overlay);
    QGroupBox* geometryGroup = group(tr("Geometry"), m_geometry);
    geometryGroup->setVisible(geometryKinds() != 0);
    column->addWidget(geometryGroup);

    m_plane = new WorkingPlaneBox(m_op.plane, m_workbench.model().faceCount());
    QGroupBox* planeGroup = group(tr("Working plane (3+2)"), m_plane);
    planeGroup->setVisible(takesWorkingPlane());
    column->addWidget(planeGroup);

    auto* params = new QWidget;
    auto* paramsForm = new QFormLayout(params);
    m_form = std::make_unique<ParamForm>(paramsForm, [this] { parametersChanged(); });
    buildParameters(*m_form);
    column->addWidget(group(tr("Parameters"), params));

    m_heights = new HeightsBox(m_op.heights);
    QGroupBox* heightsGroup = group(tr("Heights"), m_heights);
    heightsGroup->setVisible(takesHeights());
    column->addWidget(heightsGroup);
    column->addStretch(1);

    auto* scroll = new QScrollArea(this);
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // the dock's width; rows shrink
    outer->addWidget(scroll, 1);

    connect(m_name, &QLineEdit::textEdited, this, [this](const QString& text) { m_op.setName(text.toStdString()); });
    connect(m_tool, &QComboBox::currentIndexChanged, this, [this] {
        m_op.toolNumber = m_tool->currentData().toInt();
        toolChanged();
        parametersChanged();
    });
    connect(m_geometry, &GeometryList::changed, this, &OperationPanel::parametersChanged);
    connect(m_geometry, &GeometryList::rejected, this, [this](const QString& why) { m_status->setText(why); });
    connect(m_heights, &HeightsBox::changed, this, &OperationPanel::parametersChanged);
    connect(m_plane, &WorkingPlaneBox::changed, this, &OperationPanel::parametersChanged);
    connect(m_cancelCompute, &QPushButton::clicked, m_preview, &PreviewRunner::cancel);
    connect(m_preview, &PreviewRunner::started, this, [this] { setComputing(true); });
    connect(m_preview, &PreviewRunner::progress, m_progress, &QProgressBar::setValue);
    connect(m_preview, &PreviewRunner::finished, this, &OperationPanel::showOutcome);
    connect(m_preview, &PreviewRunner::cancelled, this, [this] {
        setComputing(false);
        m_status->setStyleSheet({});
        m_status->setText(tr("Preview cancelled; change a parameter to compute it again."));
    });
    // An undo or another edit underneath: preview against the job as it is now.
    connect(&m_workbench, &Workbench::jobChanged, this, [this] {
        if (m_finished)
            return;
        if (m_index >= static_cast<int>(m_workbench.job().operations.size()))
            reject();  // the operation is gone
        else
            parametersChanged();
    });
    setComputing(false);
    parametersChanged();
}

document::Job OperationPanel::previewJob(int* index) const
{
    document::Job job = m_workbench.job();
    if (m_newTool && job.tool(m_newTool->tool.number) == nullptr)
        job.tools.push_back(*m_newTool);
    if (m_index < 0) {
        job.operations.push_back(m_op);
        *index = static_cast<int>(job.operations.size()) - 1;
    } else {
        job.operations[static_cast<std::size_t>(m_index)] = m_op;
        *index = m_index;
    }
    return job;
}

void OperationPanel::parametersChanged()
{
    if (m_finished)
        return;
    m_outcomeCurrent = false;
    int index = 0;
    document::Job job = previewJob(&index);
    m_preview->request(std::move(job), index, m_workbench.model());
    emit edited();
}

document::Job OperationPanel::editedJob() const
{
    int index = 0;
    return previewJob(&index);
}

void OperationPanel::setComputing(bool computing)
{
    m_progress->setValue(0);
    m_progress->setVisible(computing);
    m_cancelCompute->setVisible(computing);
    if (computing) {
        m_status->setStyleSheet({});
        m_status->setText(tr("Computing…"));
    }
}

void OperationPanel::showOutcome()
{
    setComputing(false);
    const auto& outcome = m_preview->lastOutcome();
    if (!outcome)
        return;
    m_outcomeCurrent = true;
    if (outcome->heightsKnown)
        m_heights->setDerived(outcome->heights);
    if (!outcome->ok) {
        m_status->setStyleSheet(QStringLiteral("color: #b00020;"));
        m_status->setText(QString::fromStdString(outcome->error));
        if (m_overlay != nullptr)
            m_overlay->clearPreview();
        return;
    }
    const ops::MotionCounts& c = outcome->result.counts;
    QStringList lines{
        tr("%1 lines, %2 arcs, %3 helices, %4 cycles").arg(c.lines).arg(c.arcs).arg(c.helices).arg(c.cycles) +
        tr(" (%1 rapids; %2 ms)").arg(c.rapids).arg(qRound(outcome->seconds * 1000))};
    for (const base::Diagnostic& warning : outcome->result.warnings)
        lines << tr("Warning: %1").arg(QString::fromStdString(warning.message));
    m_status->setStyleSheet(outcome->result.warnings.empty() ? QString() : QStringLiteral("color: #8a5a00;"));
    m_status->setText(lines.join(QLatin1Char('\n')));
    if (m_overlay != nullptr)
        m_overlay->showPreview(outcome->scene, outcome->turning);
}

const ops::ToolController* OperationPanel::selectedTool() const
{
    if (const ops::ToolController* tc = m_workbench.job().tool(m_op.toolNumber))
        return tc;
    return m_newTool && m_newTool->tool.number == m_op.toolNumber ? &*m_newTool : nullptr;
}

QString OperationPanel::statusText() const { return m_status != nullptr ? m_status->text() : QString(); }

document::Operation OperationPanel::current() const
{
    document::Operation op = m_op;
    op.setName(m_name->text().toStdString());
    return op;
}

bool OperationPanel::hasUnappliedChanges() const
{
    if (m_finished)
        return false;
    // Compared as the job file writes them: every field, no hand-kept list to forget one in.
    document::Job before, after;
    before.operations = {m_original};
    after.operations = {current()};
    return document::serializeJob(before) != document::serializeJob(after);
}

bool OperationPanel::accept()
{
    if (m_finished)
        return false;
    const auto& outcome = m_preview->lastOutcome();
    if (m_outcomeCurrent && outcome && !outcome->ok) {
        m_status->setStyleSheet(QStringLiteral("color: #b00020;"));
        m_status->setText(tr("Not applied: this operation cannot be made. Change it, or Cancel.\n%1")
                              .arg(QString::fromStdString(outcome->error)));
        return false;
    }
    m_op = current();
    finish();
    if (m_index < 0)
        m_workbench.addOperation(m_op, m_newTool);
    else
        m_workbench.updateOperation(m_index, m_op);
    emit closed();
    return true;
}

void OperationPanel::reject()
{
    if (m_finished)
        return;
    finish();
    emit closed();
}

void OperationPanel::finish()
{
    m_finished = true;
    m_preview->cancel();
    if (m_overlay != nullptr)
        m_overlay->clearPreview();
}

}  // namespace camwb::gui
