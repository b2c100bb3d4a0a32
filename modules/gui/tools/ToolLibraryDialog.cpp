#include "gui/tools/ToolLibraryDialog.h"

#include "document/ToolLibraryImport.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/Workbench.h"
#include "gui/tools/ToolModels.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QVBoxLayout>

#include <algorithm>
#include <set>

namespace camwb::gui {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

QPushButton* button(QWidget* parent, QLayout* layout, const QString& text, const char* name)
{
    auto* b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(name));
    b->setAutoDefault(false);
    layout->addWidget(b);
    return b;
}

}  // namespace

ToolLibraryDialog::ToolLibraryDialog(Workbench& workbench, Prompter& prompter, QString libraryPath, QString defaultPath,
                                     QWidget* parent) :
    QDialog(parent),
    m_workbench(workbench),
    m_prompter(prompter),
    m_path(std::move(libraryPath))
{
    setObjectName(QStringLiteral("ToolLibraryDialog"));
    setWindowTitle(tr("Tool Library"));
    load(defaultPath);
    buildUi();
    refreshMaterials();
}

ToolLibraryDialog::~ToolLibraryDialog() = default;

void ToolLibraryDialog::load(const QString& defaultPath)
{
    const bool exists = QFileInfo::exists(m_path);
    const QString from = exists ? m_path : defaultPath;
    if (from.isEmpty())
        return;  // a new, empty library
    auto library = document::loadToolLibrary(from.toStdString());
    if (library) {
        m_library = std::move(library.value());
        return;
    }
    if (exists) {
        // Never write over a file we could not read: the user may repair it by hand.
        m_canSave = false;
        m_prompter.showError(tr("Tool library"),
                             tr("The tool library cannot be read, so it is shown empty and will not be saved "
                                "over (the file is left as it is; use Export to save tools elsewhere):\n%1")
                                 .arg(qs(library.error().toString())));
    } else {
        m_prompter.showError(tr("Tool library"),
                             tr("The default tool library cannot be read:\n%1").arg(qs(library.error().toString())));
    }
}

void ToolLibraryDialog::buildUi()
{
    auto* layout = new QVBoxLayout(this);
    m_filter = new QLineEdit(this);
    m_filter->setObjectName(QStringLiteral("toolFilter"));
    m_filter->setPlaceholderText(tr("Filter tools by name, kind or holder"));
    m_filter->setClearButtonEnabled(true);
    layout->addWidget(m_filter);

    m_model = new ToolTableModel(&m_library.tools, this);
    m_proxy = new QSortFilterProxyModel(this);
    m_proxy->setSourceModel(m_model);
    m_proxy->setFilterCaseSensitivity(Qt::CaseInsensitive);
    m_proxy->setFilterKeyColumn(-1);  // any column: name, kind, holder, diameter
    m_tools = new QTableView(this);
    m_tools->setObjectName(QStringLiteral("toolTable"));
    m_tools->setModel(m_proxy);
    m_tools->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_tools->setSortingEnabled(true);
    m_tools->sortByColumn(ToolTableModel::Number, Qt::AscendingOrder);
    m_tools->verticalHeader()->hide();
    m_tools->setWordWrap(false);
    m_tools->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    m_tools->horizontalHeader()->setSectionResizeMode(ToolTableModel::Name, QHeaderView::Stretch);
    m_tools->resizeColumnsToContents();

    auto* cuttingBox = new QGroupBox(tr("Cutting data of the current library tool"), this);
    auto* cuttingLayout = new QVBoxLayout(cuttingBox);
    m_cutting = new CuttingDataModel(this);
    m_cuttingView = new QTableView(cuttingBox);
    m_cuttingView->setObjectName(QStringLiteral("cuttingDataTable"));
    m_cuttingView->setModel(m_cutting);
    m_cuttingView->verticalHeader()->hide();
    m_cuttingView->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    m_cuttingView->setMinimumHeight(4 * (fontMetrics().height() + 8));
    m_cuttingView->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    cuttingLayout->addWidget(m_cuttingView);
    auto* cuttingButtons = new QHBoxLayout;
    QPushButton* addData = button(cuttingBox, cuttingButtons, tr("Add Material"), "addCuttingData");
    QPushButton* removeData = button(cuttingBox, cuttingButtons, tr("Remove Material"), "removeCuttingData");
    cuttingButtons->addStretch();
    cuttingLayout->addLayout(cuttingButtons);

    // The job's tools beside the library's: their computed speeds and feeds, edited in place.
    m_jobTools = new QTableView(this);
    m_jobTools->setObjectName(QStringLiteral("jobToolTable"));
    m_jobTools->setModel(new JobToolsModel(m_workbench, this));
    m_jobTools->verticalHeader()->hide();
    m_jobTools->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_jobTools->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_jobTools->horizontalHeader()->setSectionResizeMode(JobToolsModel::Name, QHeaderView::Stretch);
    m_jobTools->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("toolTabs"));
    m_tabs->addTab(m_tools, tr("Library"));
    m_tabs->addTab(m_jobTools, tr("Job Tools"));

    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(m_tabs);
    splitter->addWidget(cuttingBox);
    splitter->setStretchFactor(0, 2);
    splitter->setStretchFactor(1, 1);
    layout->addWidget(splitter, 1);

    auto* editRow = new QHBoxLayout;
    QPushButton* add = button(this, editRow, tr("&Add"), "addTool");
    QPushButton* duplicate = button(this, editRow, tr("D&uplicate"), "duplicateTool");
    QPushButton* remove = button(this, editRow, tr("&Delete"), "deleteTool");
    editRow->addSpacing(12);
    QPushButton* import = button(this, editRow, tr("&Import…"), "importTools");
    QPushButton* exportButton = button(this, editRow, tr("&Export…"), "exportTools");
    editRow->addStretch();
    QPushButton* toJob = button(this, editRow, tr("Add to &Job"), "addToJob");
    toJob->setToolTip(tr("Copy the selected tools into the job (a taken number gets the next free one)"));
    layout->addLayout(editRow);

    auto* jobRow = new QHBoxLayout;
    jobRow->addWidget(new QLabel(tr("Job stock material:"), this));
    m_material = new QComboBox(this);
    m_material->setObjectName(QStringLiteral("jobMaterial"));
    m_material->setEditable(true);
    m_material->setMinimumWidth(160);
    m_material->setToolTip(tr("The material the job's tools' feeds and speeds are computed for"));
    jobRow->addWidget(m_material);
    QPushButton* compute = button(this, jobRow, tr("&Compute Feeds and Speeds"), "computeFeeds");
    compute->setToolTip(tr("Set the job's tools' spindle speed and feeds from their cutting data"));
    jobRow->addStretch();
    QPushButton* saveButton = button(this, jobRow, tr("&Save"), "saveLibrary");
    saveButton->setEnabled(m_canSave);
    QPushButton* close = button(this, jobRow, tr("Close"), "closeLibrary");
    layout->addLayout(jobRow);

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("libraryStatus"));
    m_status->setWordWrap(true);
    m_status->setText(tr("Library: %1").arg(m_path));
    layout->addWidget(m_status);

    // The cutting data below belongs to the library's tools: not shown beside the job's.
    connect(m_tabs, &QTabWidget::currentChanged, cuttingBox,
            [this, cuttingBox](int tab) { cuttingBox->setVisible(m_tabs->widget(tab) == m_tools); });
    connect(&m_workbench, &Workbench::jobChanged, this, &ToolLibraryDialog::refreshMaterials);
    connect(m_filter, &QLineEdit::textChanged, m_proxy, &QSortFilterProxyModel::setFilterFixedString);
    connect(m_model, &ToolTableModel::edited, this, &ToolLibraryDialog::markModified);
    connect(m_cutting, &CuttingDataModel::edited, this, [this] {
        markModified();
        refreshMaterials();
    });
    connect(m_tools->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            &ToolLibraryDialog::showCuttingDataOfCurrent);
    connect(add, &QPushButton::clicked, this, &ToolLibraryDialog::addTool);
    connect(duplicate, &QPushButton::clicked, this, &ToolLibraryDialog::duplicateTools);
    connect(remove, &QPushButton::clicked, this, &ToolLibraryDialog::deleteTools);
    connect(addData, &QPushButton::clicked, m_cutting, &CuttingDataModel::addRow);
    connect(removeData, &QPushButton::clicked, this,
            [this] { m_cutting->removeRow(m_cuttingView->currentIndex().row()); });
    connect(import, &QPushButton::clicked, this, [this] {
        const QString path = m_prompter.openFileName(
            tr("Import tools"),
            tr("Tool libraries (*.fctl *.tools *.json);;FreeCAD ToolBit libraries (*.fctl);;Fusion 360 tool "
               "libraries (*.tools *.json)"));
        if (!path.isEmpty())
            importFrom(path);
    });
    connect(exportButton, &QPushButton::clicked, this, [this] {
        const QString path = m_prompter.saveFileName(tr("Export tools"), QStringLiteral("tools.camwb-tools.json"),
                                                     tr("CAM Workbench tool libraries (*.json)"));
        if (!path.isEmpty())
            exportTo(path);
    });
    connect(toJob, &QPushButton::clicked, this, &ToolLibraryDialog::addSelectedToJob);
    connect(m_material, &QComboBox::textActivated, this,
            [this](const QString& text) { m_workbench.setMaterial(text.trimmed().toStdString()); });
    connect(compute, &QPushButton::clicked, this, [this] {
        m_workbench.setMaterial(m_material->currentText().trimmed().toStdString());
        m_workbench.computeFeeds();
    });
    connect(saveButton, &QPushButton::clicked, this, &ToolLibraryDialog::save);
    connect(close, &QPushButton::clicked, this, &ToolLibraryDialog::reject);
    resize(960, 640);
}

void ToolLibraryDialog::markModified() { m_modified = true; }

void ToolLibraryDialog::showCuttingDataOfCurrent()
{
    const QModelIndex current = m_proxy->mapToSource(m_tools->currentIndex());
    m_cutting->setTool(current.isValid() ? &m_library.tools[current.row()] : nullptr);
}

void ToolLibraryDialog::refreshMaterials()
{
    std::set<QString> materials;
    for (const auto& tc : m_library.tools)
        for (const auto& data : tc.cuttingData)
            materials.insert(qs(data.material));
    const QString job = qs(m_workbench.job().material);
    if (!job.isEmpty())
        materials.insert(job);
    const QSignalBlocker block(m_material);
    m_material->clear();
    for (const QString& m : materials)
        m_material->addItem(m);
    m_material->setCurrentText(job);
}

void ToolLibraryDialog::selectTools(const QList<int>& rows)
{
    m_tools->clearSelection();
    for (int row : rows) {
        const QModelIndex index = m_proxy->mapFromSource(m_model->index(row, 0));
        m_tools->selectionModel()->select(index, QItemSelectionModel::Select | QItemSelectionModel::Rows);
        m_tools->selectionModel()->setCurrentIndex(index, QItemSelectionModel::NoUpdate);
    }
    showCuttingDataOfCurrent();
}

QList<int> ToolLibraryDialog::selectedTools() const
{
    QList<int> rows;
    for (const QModelIndex& index : m_tools->selectionModel()->selectedRows())
        rows << m_proxy->mapToSource(index).row();
    std::sort(rows.begin(), rows.end());
    return rows;
}

void ToolLibraryDialog::appendTools(std::vector<ops::ToolController> tools)
{
    // Library numbers are unique too, so that "Add to Job" keeps them where it can.
    m_cutting->setTool(nullptr);  // the vector may reallocate
    for (ops::ToolController& tc : tools) {
        tc.tool.number = document::nextFreeToolNumber(m_library.tools, tc.tool.number);
        m_library.tools.push_back(std::move(tc));
    }
    m_model->reload();
    markModified();
    refreshMaterials();
}

void ToolLibraryDialog::addTool()
{
    ops::ToolController tc;
    tc.tool.name = tr("New end mill D6").toStdString();
    tc.tool.diameterMm = 6;
    tc.tool.fluteLengthMm = 15;
    tc.tool.lengthMm = 50;
    appendTools({tc});
    selectTools({static_cast<int>(m_library.tools.size()) - 1});
}

void ToolLibraryDialog::duplicateTools()
{
    std::vector<ops::ToolController> copies;
    for (int row : selectedTools()) {
        copies.push_back(m_library.tools[row]);
        copies.back().tool.name += tr(" (copy)").toStdString();
    }
    if (copies.empty())
        return;
    const int first = static_cast<int>(m_library.tools.size());
    appendTools(std::move(copies));
    selectTools({first});
}

void ToolLibraryDialog::deleteTools()
{
    const QList<int> rows = selectedTools();
    if (rows.isEmpty())
        return;
    m_cutting->setTool(nullptr);
    for (auto it = rows.rbegin(); it != rows.rend(); ++it)
        m_library.tools.erase(m_library.tools.begin() + *it);
    m_model->reload();
    markModified();
}

bool ToolLibraryDialog::importFrom(const QString& path)
{
    auto imported = document::importToolLibrary(path.toStdString());
    if (!imported) {
        m_prompter.showError(tr("Import tools"), qs(imported.error().toString()));
        return false;
    }
    const int count = static_cast<int>(imported->library.tools.size());
    QStringList notes;
    for (const std::string& note : imported->notes)
        notes << qs(note);
    appendTools(std::move(imported->library.tools));
    m_status->setText(tr("Imported %n tool(s) from %1.", nullptr, count).arg(QFileInfo(path).fileName()) +
                      (notes.isEmpty() ? QString() : QLatin1Char(' ') + notes.join(QLatin1Char(' '))));
    return true;
}

bool ToolLibraryDialog::exportTo(const QString& path)
{
    const auto status = document::saveToolLibrary(m_library, path.toStdString());
    if (!status) {
        m_prompter.showError(tr("Export tools"), qs(status.error().toString()));
        return false;
    }
    m_status->setText(tr("Exported %n tool(s) to %1.", nullptr, static_cast<int>(m_library.tools.size())).arg(path));
    return true;
}

void ToolLibraryDialog::addSelectedToJob()
{
    std::vector<ops::ToolController> tools;
    for (int row : selectedTools())
        tools.push_back(m_library.tools[row]);
    if (tools.empty()) {
        m_status->setText(tr("Select the tools to add to the job."));
        return;
    }
    m_workbench.addTools(tools);
    m_status->setText(tr("Added %n tool(s) to the job.", nullptr, static_cast<int>(tools.size())));
}

bool ToolLibraryDialog::save()
{
    if (!m_canSave)
        return false;
    QDir().mkpath(QFileInfo(m_path).absolutePath());  // the user data dir on first save
    const auto status = document::saveToolLibrary(m_library, m_path.toStdString());
    if (!status) {
        m_prompter.showError(tr("Save tool library"), qs(status.error().toString()));
        return false;
    }
    m_modified = false;
    m_status->setText(tr("Saved %1.").arg(m_path));
    return true;
}

void ToolLibraryDialog::reject()
{
    if (m_modified && m_canSave) {
        const auto answer = m_prompter.ask({tr("Tool library"), tr("Save the changes to the tool library?"), {}, {}});
        if (answer == Prompter::Answer::Cancel || (answer == Prompter::Answer::Accept && !save()))
            return;
    }
    QDialog::reject();
}

}  // namespace camwb::gui
