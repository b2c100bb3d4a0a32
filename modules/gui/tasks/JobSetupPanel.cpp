#include "gui/tasks/JobSetupPanel.h"

#include "document/JobFile.h"
#include "document/JobSetup.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/LengthSpinBox.h"
#include "gui/tasks/PostPropertiesForm.h"
#include "gui/tasks/detail/JobSetupFields.h"
#include "gui/view3d/TaskOverlay.h"
#include "kinematics/Machine.h"
#include "post/PostProcessor.h"
#include "post/PostRegistry.h"
#include "post/PostSwitch.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QStandardItemModel>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <iterator>

namespace camwb::gui {

using namespace jobsetup;

namespace {

QGroupBox* group(const QString& title, QWidget* content)
{
    auto* box = new QGroupBox(title);
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(6, 6, 6, 6);
    layout->addWidget(content);
    return box;
}

}  // namespace

JobSetupPanel::JobSetupPanel(Workbench& workbench, TaskOverlay* overlay, QWidget* parent) :
    QWidget(parent),
    m_workbench(workbench),
    m_overlay(overlay),
    m_setup(workbench.job())
{
    setObjectName(QStringLiteral("jobSetupPanel"));
    resolveStock();
    m_original = m_setup;

    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);
    outer->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Job setup"))));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->button(QDialogButtonBox::Ok)->setObjectName(QStringLiteral("okButton"));
    buttons->button(QDialogButtonBox::Cancel)->setObjectName(QStringLiteral("cancelButton"));
    connect(buttons, &QDialogButtonBox::accepted, this, &JobSetupPanel::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &JobSetupPanel::reject);
    outer->addWidget(buttons);

    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    column->setContentsMargins(0, 0, 0, 0);
    column->addWidget(group(tr("Model"), buildModel()));
    column->addWidget(group(tr("Stock"), buildStock()));
    column->addWidget(group(tr("Work coordinate system"), buildWcs()));
    column->addWidget(group(tr("Machine"), buildMachine()));
    column->addWidget(group(tr("Post"), buildPost()));
    column->addWidget(group(tr("Output"), buildOutput()));
    column->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_scroll = scroll;
    outer->addWidget(scroll, 1);

    // A model imported while the panel is open: a "from model" stock follows it.
    connect(&m_workbench, &Workbench::modelChanged, this, [this] {
        const std::string& path = m_workbench.job().modelPath;
        m_modelLabel->setText(path.empty() ? tr("No model") : QFileInfo(qs(path)).fileName());
        resolveStock();
        showValues();
    });
    showValues();
}

// The dock grows to the panel's rows (the post's properties included) instead of cutting them off
// on the right. Queued: the form's rows, just made, give their sizes once the layouts have run.
void JobSetupPanel::fitWidth() { QTimer::singleShot(0, this, &JobSetupPanel::fitWidthNow); }

void JobSetupPanel::fitWidthNow()
{
    QWidget* content = m_scroll->widget();
    content->ensurePolished();
    m_scroll->setMinimumWidth(content->minimumSizeHint().width() + m_scroll->verticalScrollBar()->sizeHint().width());
}

JobSetupPanel::Vec3Fields JobSetupPanel::vec3Fields(const char* objectName, double min, double max)
{
    Vec3Fields fields{};
    const char* axes[] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        auto* spin = new LengthSpinBox;  // in the display unit, the value in mm
        spin->setObjectName(QString::fromLatin1(objectName) + QLatin1String(axes[i]));
        spin->setRange(min, max);
        spin->setKeyboardTracking(false);  // one change per value typed, not per digit
        fields[static_cast<std::size_t>(i)] = spin;
    }
    return fields;
}

QLabel* JobSetupPanel::warningLabel(const char* objectName)
{
    auto* label = new QLabel;
    label->setObjectName(QString::fromLatin1(objectName));
    label->setWordWrap(true);
    label->setStyleSheet(QStringLiteral("color: #b00020;"));
    label->hide();
    return label;
}

QWidget* JobSetupPanel::buildModel()
{
    auto* widget = new QWidget;
    auto* layout = new QHBoxLayout(widget);
    layout->setContentsMargins(0, 0, 0, 0);
    const std::string& path = m_setup.modelPath;
    m_modelLabel = new QLabel(path.empty() ? tr("No model") : QFileInfo(qs(path)).fileName());
    m_modelLabel->setObjectName(QStringLiteral("modelLabel"));
    m_modelLabel->setToolTip(qs(path));
    auto* import = new QPushButton(tr("Import…"));
    import->setObjectName(QStringLiteral("importModelButton"));
    import->setToolTip(tr("Import a STEP, IGES, BREP or STL model as the job's model"));
    connect(import, &QPushButton::clicked, this, &JobSetupPanel::importRequested);
    layout->addWidget(m_modelLabel, 1);
    layout->addWidget(import);
    return widget;
}

QWidget* JobSetupPanel::buildWcs()
{
    auto* widget = new QWidget;
    auto* form = new QFormLayout(widget);
    m_originAnchor = new QComboBox;
    m_originAnchor->setObjectName(QStringLiteral("originAnchor"));
    m_originAnchor->addItem(tr("Typed (model coordinates)"));
    m_originAnchor->addItem(tr("Stock: top front left corner"));
    m_originAnchor->addItem(tr("Stock: bottom front left corner"));
    m_originAnchor->addItem(tr("Stock: top centre"));
    m_originAnchor->addItem(tr("Stock: centre"));
    m_originAnchor->addItem(tr("Stock: bottom centre"));
    m_originAnchor->addItem(tr("On the model vertex picked in the view"));
    m_originAnchor->addItem(tr("Z0 on the face picked in the view"));
    m_originAnchor->setToolTip(tr("Program zero: a point of the stock (it follows the stock), or typed"));
    form->addRow(tr("Origin at"), m_originAnchor);
    m_origin = vec3Fields("origin", -10000, 10000);
    form->addRow(tr("Origin"), axisGrid({{QString(), m_origin}}));
    m_originNote = new QLabel;
    m_originNote->setObjectName(QStringLiteral("originNote"));
    m_originNote->setWordWrap(true);
    m_originNote->hide();
    form->addRow(m_originNote);
    m_workOffset = new QComboBox;
    m_workOffset->setObjectName(QStringLiteral("workOffset"));
    for (int i = 1; i <= 6; ++i)
        m_workOffset->addItem(QString(), i);
    if (m_setup.workOffset > 6)
        m_workOffset->addItem(QString(), m_setup.workOffset);
    nameWorkOffsets();
    form->addRow(tr("Work offset"), m_workOffset);

    connect(m_originAnchor, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (m_showing || index <= 0)
            return;
        if (index == kPickedFace) {
            originOnPickedFace();
            return;
        }
        if (index == kPickedVertex) {
            originOnPickedVertex();
            return;
        }
        moveOrigin(document::stockAnchor(m_setup.stock, kAnchors[index - 1]));
        showValues();
    });
    if (m_overlay != nullptr)
        connect(m_overlay, &TaskOverlay::selectionChanged, this, [this] {
            if (m_originAnchor->currentIndex() == kPickedFace)
                originOnPickedFace();
        });
    if (m_overlay != nullptr)
        connect(m_overlay, &TaskOverlay::pointPicked, this, [this] {
            if (m_originAnchor->currentIndex() == kPickedVertex)
                originOnPickedVertex();
        });
    for (QDoubleSpinBox* spin : m_origin)
        connect(spin, &QDoubleSpinBox::valueChanged, this, &JobSetupPanel::originEdited);
    connect(m_workOffset, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_showing)
            m_setup.workOffset = m_workOffset->currentData().toInt();
    });
    return widget;
}

QWidget* JobSetupPanel::buildMachine()
{
    auto* widget = new QWidget;
    auto* layout = new QVBoxLayout(widget);
    layout->setContentsMargins(0, 0, 0, 0);
    m_machine = new QComboBox;
    m_machine->setObjectName(QStringLiteral("machine"));
    m_machine->addItem(tr("The post's default machine"), QString());
    for (const base::DataFile& file : kinematics::listMachineFiles())
        m_machine->addItem(qs(file.id), qs(file.path));
    if (!m_setup.machineId.empty() && m_machine->findText(qs(m_setup.machineId)) < 0)
        m_machine->addItem(qs(m_setup.machineId), qs(m_setup.machineId));
    m_travelWarning = warningLabel("travelWarning");
    layout->addWidget(m_machine);
    layout->addWidget(m_travelWarning);
    connect(m_machine, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (m_showing)
            return;
        m_setup.machineId = index <= 0 ? std::string() : m_machine->currentText().toStdString();
        checkTravels();
        filterPosts();
    });
    return widget;
}

QWidget* JobSetupPanel::buildPost()
{
    auto* widget = new QWidget;
    auto* layout = new QVBoxLayout(widget);
    layout->setContentsMargins(0, 0, 0, 0);
    m_post = new QComboBox;
    m_post->setObjectName(QStringLiteral("post"));
    for (const post::PostEntry& entry : post::listPosts(post::defaultPostDirs())) {
        // The post's own declarations: the machines and controls it serves, its description.
        post::PostInfo info;
        info.id = entry.id;
        if (auto loaded = post::PostProcessor::load(entry.path))
            info = loaded->info();
        m_post->addItem(qs(entry.id));
        m_post->setItemData(m_post->count() - 1, qs(info.description), Qt::ToolTipRole);
        m_postInfos.push_back(std::move(info));
    }
    if (m_post->findText(qs(m_setup.postId)) < 0) {
        m_post->addItem(qs(m_setup.postId));
        m_postInfos.emplace_back().id = m_setup.postId;
    }
    m_postWarning = warningLabel("postWarning");
    layout->addWidget(m_post);
    layout->addWidget(m_postWarning);
    // The post's properties, as Post Settings shows them; a change of post keeps the values the
    // new post takes (post::switchPost) and says which it drops.
    m_postPropertiesSlot = new QWidget;
    m_postPropertiesSlot->setObjectName(QStringLiteral("postPropertiesSlot"));
    auto* slotLayout = new QVBoxLayout(m_postPropertiesSlot);
    slotLayout->setContentsMargins(0, 0, 0, 0);
    m_postDropped = new QLabel;
    m_postDropped->setObjectName(QStringLiteral("postDropped"));
    m_postDropped->setWordWrap(true);
    m_postDropped->hide();
    slotLayout->addWidget(m_postDropped);
    m_postProperties = new PostPropertiesForm;
    m_postProperties->setCompact(true);
    slotLayout->addWidget(m_postProperties);
    layout->addWidget(m_postPropertiesSlot);
    connect(m_postProperties, &PostPropertiesForm::changed, this,
            [this] { m_setup.postProperties = m_postProperties->values(); });
    connect(m_post, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_showing)
            switchPostTo(m_post->currentIndex());
        filterPosts();
    });
    return widget;
}

QWidget* JobSetupPanel::buildOutput()
{
    auto* widget = new QWidget;
    auto* form = new QFormLayout(widget);
    m_outputName = new QLineEdit(qs(m_setup.outputName));
    m_outputName->setObjectName(QStringLiteral("outputName"));
    m_outputName->setPlaceholderText(tr("the job file's name"));
    m_outputName->setToolTip(tr("The NC program's file name; the post's extension is added when it has none"));
    m_outputFolder = new QLineEdit(qs(m_setup.outputFolder));
    m_outputFolder->setObjectName(QStringLiteral("outputFolder"));
    m_outputFolder->setPlaceholderText(tr("the job file's folder"));
    m_outputFolder->setToolTip(tr("Relative to the job file's folder, or absolute"));
    form->addRow(tr("File name"), m_outputName);
    form->addRow(tr("Folder"), m_outputFolder);
    connect(m_outputName, &QLineEdit::textChanged, this,
            [this](const QString& text) { m_setup.outputName = text.trimmed().toStdString(); });
    connect(m_outputFolder, &QLineEdit::textChanged, this,
            [this](const QString& text) { m_setup.outputFolder = text.trimmed().toStdString(); });
    return widget;
}

// Z0 at the level of the flat horizontal face picked in the 3D view; X and Y stay.
void JobSetupPanel::originOnPickedFace()
{
    const std::vector<int> faces = m_overlay ? m_overlay->selectedFaces() : std::vector<int>{};
    const occ::FaceInfo face = faces.empty() ? occ::FaceInfo{} : m_workbench.model().face(faces.back());
    const bool level = face.index > 0 && face.planar && std::abs(std::abs(face.normal.z) - 1) < 1e-9;
    m_originNote->setText(level ? tr("Z0 on face %1").arg(face.index)
                                : tr("Pick a flat horizontal face of the model in the 3D view."));
    m_originNote->show();
    if (!level)
        return;
    // The model is shown in the coordinates of the origin it was loaded with.
    const double z = face.planeZ + m_workbench.modelOrigin().z;
    moveOrigin({0, 0, z - m_setup.origin.z});
    showValues();
}

// The origin on the model vertex nearest to the point picked in the 3D view: the ends of the
// model's edges as the view draws them (occ's feature edges) are its B-rep vertices.
void JobSetupPanel::originOnPickedVertex()
{
    const std::optional<base::Vec3> point = m_overlay ? m_overlay->pickedPoint() : std::nullopt;
    std::optional<base::Vec3> vertex;
    for (const std::vector<base::Vec3>& edge : m_workbench.displayMesh().featureEdges) {
        if (!point || edge.empty())
            continue;
        for (const base::Vec3& end : {edge.front(), edge.back()})
            if (!vertex || (end - *point).length() < (*vertex - *point).length())
                vertex = end;
    }
    m_originNote->setText(vertex ? tr("Origin on the vertex at (%1, %2, %3) of the model")
                                       .arg(vertex->x + m_workbench.modelOrigin().x, 0, 'g', 6)
                                       .arg(vertex->y + m_workbench.modelOrigin().y, 0, 'g', 6)
                                       .arg(vertex->z + m_workbench.modelOrigin().z, 0, 'g', 6)
                                 : tr("Click the model near a vertex in the 3D view."));
    m_originNote->show();
    if (!vertex)
        return;
    // The model is shown in the coordinates of the origin it was loaded with.
    moveOrigin(*vertex + m_workbench.modelOrigin() - m_setup.origin);
    showValues();
}

void JobSetupPanel::originEdited()
{
    if (m_showing)
        return;
    moveOrigin(valueOf(m_origin) - m_setup.origin);
    m_showing = true;
    m_originAnchor->setCurrentIndex(0);  // typed
    m_showing = false;
    showValues();
}

void JobSetupPanel::moveOrigin(const base::Vec3& delta)
{
    document::moveOrigin(m_setup, m_setup.origin + delta);
    resolveStock();  // a "from model" stock in the new coordinates
}

void JobSetupPanel::showValues()
{
    m_showing = true;
    showStock();
    showVec3(m_origin, m_setup.origin);
    m_workOffset->setCurrentIndex(std::max(0, m_workOffset->findData(m_setup.workOffset)));
    m_machine->setCurrentIndex(m_setup.machineId.empty() ? 0 : std::max(0, m_machine->findText(qs(m_setup.machineId))));
    const int postIndex = std::max(0, m_post->findText(qs(m_setup.postId)));
    m_post->setCurrentIndex(postIndex);
    if (postIndex < static_cast<int>(m_postInfos.size()))
        m_postProperties->setPost(m_postInfos[static_cast<std::size_t>(postIndex)], m_setup.postProperties);
    m_showing = false;
    fitWidth();
    checkTravels();
    filterPosts();
}

// The form follows the post chosen; values the new post does not take are dropped, and listed.
void JobSetupPanel::switchPostTo(int index)
{
    if (index < 0 || index >= static_cast<int>(m_postInfos.size()))
        return;
    const post::PostInfo& to = m_postInfos[static_cast<std::size_t>(index)];
    const post::PostInfo* from = nullptr;
    for (const post::PostInfo& info : m_postInfos)
        if (info.id == m_setup.postId)
            from = &info;
    const post::PostSwitch moved = post::switchPost(m_setup.postProperties, from ? *from : post::PostInfo{}, to);
    m_setup.postId = to.id;
    m_setup.postProperties = moved.kept;
    QStringList dropped;
    for (const post::DroppedProperty& property : moved.dropped)
        dropped << tr("%1 = %2 (%3)").arg(qs(property.name), qs(property.value), qs(property.reason));
    m_postDropped->setText(dropped.isEmpty() ? QString()
                                             : tr("Dropped with the change of post:\n%1").arg(dropped.join('\n')));
    m_postDropped->setVisible(!dropped.isEmpty());
    m_postProperties->setPost(to, m_setup.postProperties);
    fitWidth();
}

// Each offset by the name the chosen post gives it in the NC (SINUMERIK's fifth is G505, not G58).
void JobSetupPanel::nameWorkOffsets()
{
    for (int i = 0; i < m_workOffset->count(); ++i)
        m_workOffset->setItemText(i, qs(document::workOffsetName(m_workOffset->itemData(i).toInt(), m_setup.postId)));
}

// Posts that name the machines they post for and not the chosen one are greyed out; the chosen
// post, when it is one of them, is warned about (posting would fail).
void JobSetupPanel::filterPosts()
{
    nameWorkOffsets();
    auto* model = qobject_cast<QStandardItemModel*>(m_post->model());
    auto serves = [this](int index) {
        return !m_chosenMachine || index < 0 || index >= static_cast<int>(m_postInfos.size()) ||
               post::servesMachine(m_postInfos[static_cast<std::size_t>(index)], *m_chosenMachine);
    };
    for (int i = 0; model != nullptr && i < m_post->count(); ++i)
        model->item(i)->setEnabled(serves(i) || i == m_post->currentIndex());
    const bool ok = serves(m_post->currentIndex());
    m_postWarning->setText(
        ok ? QString() : tr("%1 does not post for the machine %2.").arg(m_post->currentText(), qs(m_setup.machineId)));
    m_postWarning->setVisible(!ok);
}

void JobSetupPanel::checkTravels()
{
    QStringList problems;
    const QString path = m_machine->currentData().toString();
    m_chosenMachine.reset();
    if (!path.isEmpty()) {
        auto machine = kinematics::loadMachine(path.toStdString());
        if (!machine)
            problems << qs(machine.error().toString());
        else
            m_chosenMachine = std::move(machine).value();
    }
    if (m_chosenMachine)
        for (const std::string& shortfall : document::travelShortfalls(*m_chosenMachine, m_setup.stock))
            problems << qs(shortfall);
    m_travelWarning->setText(problems.isEmpty()
                                 ? QString()
                                 : tr("The stock does not fit the machine's travels:\n%1").arg(problems.join('\n')));
    m_travelWarning->setVisible(!problems.isEmpty());
}

bool JobSetupPanel::hasUnappliedChanges() const
{
    // The jobs as written: a setup field added later counts without being listed here.
    return document::serializeJob(m_setup) != document::serializeJob(m_original);
}

bool JobSetupPanel::accept()
{
    if (m_finished)
        return true;
    if (document::stockProblem(m_setup.stock))
        return false;  // said under the stock's fields: the panel stays
    if (!m_workbench.setJobSetup(m_setup))
        return false;  // the post cannot be loaded (shown): the panel stays
    finish();
    return true;
}

void JobSetupPanel::reject()
{
    if (!m_finished)
        finish();
}

void JobSetupPanel::finish()
{
    m_finished = true;
    emit closed();
}

}  // namespace camwb::gui
