#include "gui/shell/JobTree.h"

#include "document/JobPipeline.h"
#include "gui/editor/ProgramInfoDialog.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/Workbench.h"
#include "kinematics/Machine.h"

#include <QDropEvent>
#include <QFileInfo>
#include <QHeaderView>
#include <QKeyEvent>
#include <QScrollBar>
#include <QStyle>

namespace camwb::gui {

namespace {

constexpr int kOperationRole = Qt::UserRole + 1;
constexpr int kKindRole = Qt::UserRole + 2;

// A length in the display unit (gui/shell/Preferences.h), without the unit / with it.
QString qs(const std::string& s) { return QString::fromStdString(s); }

QString indexList(const std::vector<int>& indices)
{
    QStringList parts;
    for (int i : indices)
        parts << QString::number(i);
    return parts.join(QLatin1Char(' '));
}

QString geometrySummary(const document::GeometryRefs& geometry)
{
    QStringList parts;
    if (!geometry.faces.empty())
        parts << JobTree::tr("faces %1").arg(indexList(geometry.faces));
    if (!geometry.edges.empty())
        parts << JobTree::tr("edges %1").arg(indexList(geometry.edges));
    if (!geometry.holes.empty())
        parts << JobTree::tr("holes %1").arg(indexList(geometry.holes));
    return parts.isEmpty() ? JobTree::tr("no geometry") : parts.join(QStringLiteral(", "));
}

// In red with the error icon, and the reason as a child row (read without hovering) and tooltip.
void markProblem(QTreeWidgetItem* item, const QString& problem)
{
    const QBrush red(QColor(0xb0, 0x00, 0x20));
    item->setIcon(0, item->treeWidget()->style()->standardIcon(QStyle::SP_MessageBoxCritical));
    for (int column : {0, 1}) {
        item->setForeground(column, red);
        item->setToolTip(column, problem);
    }
    auto* reason = new QTreeWidgetItem(item, {JobTree::tr("Error"), problem});
    reason->setForeground(0, red);
    reason->setForeground(1, red);
    reason->setToolTip(1, problem);
    reason->setData(0, Qt::UserRole, QStringLiteral("problem"));
}

QTreeWidgetItem* row(QTreeWidgetItem* parent, JobTree::ItemKind kind, const QString& label, const QString& value)
{
    auto* item = new QTreeWidgetItem(parent, {label, value});
    item->setData(0, kKindRole, static_cast<int>(kind));
    return item;
}

// The job's values of the post's properties that differ from its defaults ("name = value"); all
// the job's values while the post is not known yet.
QStringList nonDefaultProperties(const document::Job& job, const post::PostInfo* info)
{
    QStringList out;
    for (const auto& [name, value] : job.postProperties) {
        const post::PropertyDef* def = info ? info->property(name) : nullptr;
        if (def != nullptr) {
            auto parsed = post::parsePropertyValue(*def, value);
            if (parsed && parsed->text == def->defaultValue)
                continue;
        }
        out << QStringLiteral("%1 = %2").arg(qs(name), qs(value));
    }
    return out;
}

}  // namespace

JobTree::JobTree(Workbench& workbench, QWidget* parent) : QTreeWidget(parent), m_workbench(workbench)
{
    setObjectName(QStringLiteral("jobTree"));
    setColumnCount(2);
    setHeaderLabels({tr("Item"), tr("Value")});
    header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    // Operations are renamed in place only through Rename (F2 edits the operation's panel).
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setDragEnabled(true);
    setAcceptDrops(true);
    setDropIndicatorShown(true);
    setDragDropMode(QAbstractItemView::InternalMove);
    setDefaultDropAction(Qt::MoveAction);
    connect(&m_workbench, &Workbench::jobChanged, this, &JobTree::rebuild);
    connect(&m_workbench, &Workbench::modelChanged, this, &JobTree::rebuild);
    connect(&m_workbench, &Workbench::programStateChanged, this, &JobTree::rebuild);
    connect(this, &QTreeWidget::itemDoubleClicked, this, &JobTree::openItem);
    connect(this, &QTreeWidget::itemChanged, this, &JobTree::onItemChanged);
    rebuild();
}

JobTree::ItemKind JobTree::kindOf(const QTreeWidgetItem* item)
{
    return item ? static_cast<ItemKind>(item->data(0, kKindRole).toInt()) : ItemKind::Other;
}

QTreeWidgetItem* JobTree::itemOf(ItemKind kind) const
{
    for (QTreeWidgetItemIterator it(const_cast<JobTree*>(this)); *it; ++it)
        if (kindOf(*it) == kind)
            return *it;
    return nullptr;
}

QTreeWidgetItem* JobTree::operationItem(int index) const
{
    QTreeWidgetItem* operations = itemOf(ItemKind::Operations);
    return operations && index >= 0 && index < operations->childCount() ? operations->child(index) : nullptr;
}

int JobTree::selectedOperation() const
{
    const QTreeWidgetItem* item = currentItem();
    // A problem row under an operation stands for its operation.
    if (item && kindOf(item) != ItemKind::Operation && kindOf(item->parent()) == ItemKind::Operation)
        item = item->parent();
    const QVariant op = item ? item->data(0, kOperationRole) : QVariant();
    return op.isValid() ? op.toInt() : -1;
}

void JobTree::selectOperation(int index)
{
    if (QTreeWidgetItem* item = operationItem(index))
        setCurrentItem(item);
}

void JobTree::rebuild()
{
    if (state() == QAbstractItemView::EditingState) {
        m_rebuildPending = true;  // not under the user's typing: when the editor closes
        return;
    }
    m_rebuildPending = false;
    const ItemKind kind = kindOf(currentItem());
    const int operation = m_selectAfterRebuild >= 0 ? m_selectAfterRebuild : selectedOperation();
    m_selectAfterRebuild = -1;
    const int scroll = verticalScrollBar()->value();

    m_rebuilding = true;
    clear();
    const document::Job& job = m_workbench.job();
    auto* jobItem = row(invisibleRootItem(), ItemKind::Job, tr("Job"), qs(job.name));
    addSetupItems(jobItem);
    addOperationItems(jobItem);
    expandAll();
    m_rebuilding = false;

    if (operation >= 0 && operationItem(operation) != nullptr)
        selectOperation(operation);
    else if (kind != ItemKind::Other && itemOf(kind) != nullptr)
        setCurrentItem(itemOf(kind));
    verticalScrollBar()->setValue(scroll);
}

void JobTree::addSetupItems(QTreeWidgetItem* jobItem)
{
    const document::Job& job = m_workbench.job();
    auto* model = row(jobItem, ItemKind::Model, tr("Model"),
                      job.modelPath.empty() ? tr("(none)") : QFileInfo(qs(job.modelPath)).fileName());
    model->setToolTip(1, qs(job.modelPath));
    if (!m_workbench.modelProblem().isEmpty())
        markProblem(model, tr("not loaded: %1").arg(m_workbench.modelProblem()));
    if (m_workbench.model().hasBRep())
        new QTreeWidgetItem(model, {tr("Faces"), QString::number(m_workbench.model().faceCount())});

    const base::Vec3 size = job.stock.max - job.stock.min;
    // A lathe job's stock is the shaft its grooves are cut in, made from their parameters.
    const bool lathe = !job.operations.empty() && !document::jobNeedsModel(job);
    using Shape = document::Stock::Shape;
    const QString boxText =
        tr("box %1 × %2 × %3 %4")
            .arg(formatLengthNumber(size.x), formatLengthNumber(size.y), formatLengthNumber(size.z), unitSymbol());
    auto* stock =
        row(jobItem, ItemKind::Stock, tr("Stock"),
            lathe              ? tr("the grooves' shaft (revolved)")
            : !job.stock.box() ? tr("(none)")
            : job.stock.shape == Shape::Cylinder
                ? tr("cylinder Ø%1 × %2 %3").arg(formatLengthNumber(size.x), formatLengthNumber(size.z), unitSymbol())
            : job.stock.shape == Shape::Blank
                ? tr("blank %1 in a %2").arg(QFileInfo(QString::fromStdString(job.stock.blankPath)).fileName(), boxText)
                : boxText);
    if (!lathe) {
        new QTreeWidgetItem(
            stock, {tr("Min"), QStringLiteral("%1, %2, %3 %4")
                                   .arg(formatLengthNumber(job.stock.min.x), formatLengthNumber(job.stock.min.y),
                                        formatLengthNumber(job.stock.min.z), unitSymbol())});
        new QTreeWidgetItem(
            stock, {tr("Max"), QStringLiteral("%1, %2, %3 %4")
                                   .arg(formatLengthNumber(job.stock.max.x), formatLengthNumber(job.stock.max.y),
                                        formatLengthNumber(job.stock.max.z), unitSymbol())});
    }
    row(jobItem, ItemKind::Wcs, tr("Work offset"),
        QString::fromStdString(document::workOffsetName(job.workOffset, job.postId)));

    // The job's machine, else the one its post chose for the last program.
    const auto machine = m_workbench.machine();
    const QString machineName =
        machine ? qs(machine->name.empty() ? machine->id : machine->name) : tr("(not posted yet)");
    row(jobItem, ItemKind::Machine, tr("Machine"),
        job.machineId.empty() ? tr("post default: %1").arg(machineName) : qs(job.machineId));

    const auto info = m_workbench.postInfo();
    const bool postKnown = info && info->id == job.postId;
    auto* post = row(jobItem, ItemKind::Post, tr("Post"), qs(job.postId));
    if (postKnown)
        post->setToolTip(1, qs(info->description));
    for (const QString& property : nonDefaultProperties(job, postKnown ? info.get() : nullptr)) {
        const QString name = property.section(QStringLiteral(" = "), 0, 0);
        row(post, ItemKind::Post, name, property.section(QStringLiteral(" = "), 1));
    }

    auto* tools = row(jobItem, ItemKind::Tools, tr("Tools"), QString::number(job.tools.size()));
    for (const ops::ToolController& tc : job.tools) {
        QString text = tr("%1, Ø%2").arg(qs(tc.tool.name), formatLength(tc.tool.diameterMm));
        if (!tc.tool.holder.empty())
            text += tr(", holder %1").arg(qs(tc.tool.holder));
        auto* tool = row(tools, ItemKind::Tool, QStringLiteral("T%1").arg(tc.tool.number), text);
        tool->setToolTip(1, tr("S%1, F%2 %3/min")
                                .arg(tc.spindleRpm)
                                .arg(toDisplayUnit(tc.cuttingFeedMmPerMin, displayUnit()), 0, 'g', 6)
                                .arg(unitSymbol()));
    }
}

void JobTree::addOperationItems(QTreeWidgetItem* jobItem)
{
    const document::Job& job = m_workbench.job();
    auto* operations = row(jobItem, ItemKind::Operations, tr("Operations"), QString::number(job.operations.size()));
    operations->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsDropEnabled);
    const QBrush grey = palette().brush(QPalette::Disabled, QPalette::Text);
    for (std::size_t i = 0; i < job.operations.size(); ++i) {
        const int index = static_cast<int>(i);
        const document::Operation& op = job.operations[i];
        QStringList value{qs(document::kindLabel(op.kind())), QStringLiteral("T%1").arg(op.toolNumber)};
        if (const double seconds = m_workbench.operationSeconds(index); op.enabled && seconds >= 0)
            value << formatDuration(seconds);
        if (const auto* groove = std::get_if<ops::GrooveParams>(&op.params))  // given by numbers, not faces
            value << tr("depth %1, bottom width %2")
                         .arg(formatLength(groove->groove.r3), formatLength(groove->groove.r4));
        else
            value << geometrySummary(op.geometry);
        if (!op.enabled)
            value.prepend(tr("(disabled)"));
        auto* item = row(operations, ItemKind::Operation, qs(op.name()), value.join(QStringLiteral(" · ")));
        item->setData(0, kOperationRole, index);
        item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsDragEnabled |
                       Qt::ItemIsEditable);
        item->setCheckState(0, op.enabled ? Qt::Checked : Qt::Unchecked);
        item->setToolTip(0, op.enabled ? tr("Posted; uncheck to leave it out of the program")
                                       : tr("Disabled: not computed and not posted"));
        if (const ops::ToolController* tc = job.tool(op.toolNumber))
            item->setToolTip(
                1, tr("T%1 %2, Ø%3").arg(tc->tool.number).arg(qs(tc->tool.name), formatLength(tc->tool.diameterMm)));
        if (!op.enabled) {
            item->setForeground(0, grey);
            item->setForeground(1, grey);
            continue;  // its problems are not the program's
        }
        const QString problem = m_workbench.operationProblem(index);
        if (!problem.isEmpty())
            markProblem(item, problem);
    }
}

// The check box toggles the operation; an edited name renames it. Both are applied after the
// item's signal has returned: the edit rebuilds the tree, which deletes this item.
void JobTree::onItemChanged(QTreeWidgetItem* item, int column)
{
    if (m_rebuilding || column != 0 || kindOf(item) != ItemKind::Operation)
        return;
    const int index = item->data(0, kOperationRole).toInt();
    if (index < 0 || index >= static_cast<int>(m_workbench.job().operations.size()))
        return;
    const document::Operation& op = m_workbench.job().operations[static_cast<std::size_t>(index)];
    const bool enabled = item->checkState(0) == Qt::Checked;
    const QString name = item->text(0);
    QMetaObject::invokeMethod(
        this,
        [this, index, enabled, name, wasEnabled = op.enabled, oldName = qs(op.name())] {
            m_selectAfterRebuild = index;
            if (enabled != wasEnabled)
                m_workbench.setOperationEnabled(index, enabled);
            if (name != oldName)
                m_workbench.renameOperation(index, name);
            if (name.trimmed().isEmpty())
                rebuild();  // refused: show the name again
        },
        Qt::QueuedConnection);
}

void JobTree::openItem(QTreeWidgetItem* item)
{
    if (item && kindOf(item) == ItemKind::Other)
        item = item->parent();  // a detail row opens what it details
    switch (kindOf(item)) {
    case ItemKind::Operation:
        emit editOperationRequested(item->data(0, kOperationRole).toInt());
        break;
    case ItemKind::Job:
    case ItemKind::Model:
    case ItemKind::Stock:
    case ItemKind::Wcs:
    case ItemKind::Machine:
        emit editJobSetupRequested();
        break;
    case ItemKind::Post:
        emit editPostRequested();
        break;
    case ItemKind::Tools:
    case ItemKind::Tool:
        if (QAction* library = registered("Cam.Tools.Library"))
            library->trigger();
        break;
    default:
        break;
    }
}

void JobTree::keyPressEvent(QKeyEvent* event)
{
    const bool enter = event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    if (enter && state() != QAbstractItemView::EditingState && currentItem() != nullptr) {
        openItem(currentItem());
        event->accept();
        return;
    }
    QTreeWidget::keyPressEvent(event);
}

void JobTree::closeEditor(QWidget* editor, QAbstractItemDelegate::EndEditHint hint)
{
    QTreeWidget::closeEditor(editor, hint);
    if (m_rebuildPending)
        QMetaObject::invokeMethod(this, &JobTree::rebuild, Qt::QueuedConnection);
}

int JobTree::dropTarget(const QPoint& pos) const
{
    const int from = selectedOperation();
    const int count = static_cast<int>(m_workbench.job().operations.size());
    QTreeWidgetItem* item = itemAt(pos);
    if (from < 0 || item == nullptr)
        return -1;
    if (kindOf(item) != ItemKind::Operation && kindOf(item->parent()) == ItemKind::Operation)
        item = item->parent();
    int slot = -1;  // the gap it goes into: 0 before the first operation, count after the last
    if (kindOf(item) == ItemKind::Operations)
        slot = count;
    else if (kindOf(item) == ItemKind::Operation) {
        const int index = item->data(0, kOperationRole).toInt();
        slot = pos.y() < visualItemRect(item).center().y() ? index : index + 1;
    }
    if (slot < 0)
        return -1;
    const int to = slot > from ? slot - 1 : slot;
    return to == from ? -1 : to;
}

void JobTree::dragEnterEvent(QDragEnterEvent* event)
{
    if (selectedOperation() < 0)
        return event->ignore();
    QTreeWidget::dragEnterEvent(event);
}

void JobTree::dragMoveEvent(QDragMoveEvent* event)
{
    QTreeWidget::dragMoveEvent(event);  // draws the drop indicator
    if (dropTarget(event->position().toPoint()) < 0)
        event->ignore();
}

bool JobTree::dropSelectedOperationAt(const QPoint& pos)
{
    const int from = selectedOperation();
    const int to = dropTarget(pos);
    if (to < 0)
        return false;
    m_selectAfterRebuild = to;
    m_workbench.moveOperation(from, to);
    return true;
}

// Operations are moved in the job, not as rows: the tree is rebuilt from it. Accepted as a copy,
// so the view does not remove the dragged row itself.
void JobTree::dropEvent(QDropEvent* event)
{
    if (!dropSelectedOperationAt(event->position().toPoint())) {
        event->ignore();
        return;
    }
    event->setDropAction(Qt::CopyAction);
    event->accept();
}

}  // namespace camwb::gui
