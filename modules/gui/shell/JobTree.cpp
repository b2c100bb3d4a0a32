#include "gui/shell/JobTree.h"

#include "gui/shell/Workbench.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QStyle>

namespace camwb::gui {

namespace {

constexpr int kOperationRole = Qt::UserRole + 1;

QString mm(double v) { return QString::number(v, 'f', 3); }

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

}  // namespace

JobTree::JobTree(Workbench& workbench, QWidget* parent) : QTreeWidget(parent), m_workbench(workbench)
{
    setObjectName(QStringLiteral("jobTree"));
    setColumnCount(2);
    setHeaderLabels({tr("Item"), tr("Value")});
    header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    connect(&m_workbench, &Workbench::jobChanged, this, &JobTree::rebuild);
    connect(&m_workbench, &Workbench::modelChanged, this, &JobTree::rebuild);
    connect(&m_workbench, &Workbench::programStateChanged, this, &JobTree::rebuild);
    connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        const QVariant op = item->data(0, kOperationRole);
        if (op.isValid())
            emit editOperationRequested(op.toInt());
    });
    rebuild();
}

int JobTree::selectedOperation() const
{
    const QTreeWidgetItem* item = currentItem();
    const QVariant op = item ? item->data(0, kOperationRole) : QVariant();
    return op.isValid() ? op.toInt() : -1;
}

void JobTree::rebuild()
{
    clear();
    const document::Job& job = m_workbench.job();

    auto* jobItem = new QTreeWidgetItem(this, {tr("Job"), QString::fromStdString(job.name)});
    auto* model = new QTreeWidgetItem(
        jobItem, {tr("Model"),
                  job.modelPath.empty() ? tr("(none)") : QFileInfo(QString::fromStdString(job.modelPath)).fileName()});
    model->setToolTip(1, QString::fromStdString(job.modelPath));
    if (!m_workbench.modelProblem().isEmpty())
        markProblem(model, tr("not loaded: %1").arg(m_workbench.modelProblem()));
    if (m_workbench.model().hasBRep())
        new QTreeWidgetItem(model, {tr("Faces"), QString::number(m_workbench.model().faceCount())});

    const base::Vec3 size = job.stock.max - job.stock.min;
    auto* stock = new QTreeWidgetItem(
        jobItem, {tr("Stock"), QStringLiteral("%1 × %2 × %3 mm").arg(mm(size.x), mm(size.y), mm(size.z))});
    new QTreeWidgetItem(
        stock,
        {tr("Min"), QStringLiteral("%1, %2, %3").arg(mm(job.stock.min.x), mm(job.stock.min.y), mm(job.stock.min.z))});
    new QTreeWidgetItem(
        stock,
        {tr("Max"), QStringLiteral("%1, %2, %3").arg(mm(job.stock.max.x), mm(job.stock.max.y), mm(job.stock.max.z))});
    new QTreeWidgetItem(jobItem, {tr("Work offset"), QStringLiteral("G%1").arg(53 + job.workOffset)});
    new QTreeWidgetItem(jobItem, {tr("Post"), QString::fromStdString(job.postId)});

    auto* tools = new QTreeWidgetItem(jobItem, {tr("Tools"), QString::number(job.tools.size())});
    for (const ops::ToolController& tc : job.tools)
        new QTreeWidgetItem(tools, {QStringLiteral("T%1").arg(tc.tool.number),
                                    tr("%1, Ø%2 mm, S%3, F%4")
                                        .arg(QString::fromStdString(tc.tool.name), mm(tc.tool.diameterMm))
                                        .arg(tc.spindleRpm)
                                        .arg(tc.cuttingFeedMmPerMin)});

    auto* operations = new QTreeWidgetItem(jobItem, {tr("Operations"), QString::number(job.operations.size())});
    for (std::size_t i = 0; i < job.operations.size(); ++i) {
        const document::Operation& op = job.operations[i];
        auto* item = new QTreeWidgetItem(operations, {QString::fromStdString(op.name()),
                                                      tr("%1, T%2, %3")
                                                          .arg(QString::fromLatin1(document::kindLabel(op.kind())))
                                                          .arg(op.toolNumber)
                                                          .arg(geometrySummary(op.geometry))});
        item->setData(0, kOperationRole, static_cast<int>(i));
        const QString problem = m_workbench.operationProblem(static_cast<int>(i));
        if (!problem.isEmpty())
            markProblem(item, problem);
    }
    expandAll();
}

}  // namespace camwb::gui
