// The tool library dialog: the user's library as a table (filter, add, edit in place, duplicate,
// delete), each tool's cutting data per material, import from FreeCAD (.fctl) and Fusion 360
// (.tools/.json), export to our format, "Add to Job" (copies, one undo step), the job's stock
// material and the job's tools' speeds and feeds (computed, then editable). A library file that
// cannot be read is reported and never saved over.
#pragma once

#include "document/ToolLibrary.h"

#include <QDialog>
#include <QString>

class QComboBox;
class QLabel;
class QLineEdit;
class QSortFilterProxyModel;
class QTabWidget;
class QTableView;

namespace camwb::gui {

class CuttingDataModel;
class Prompter;
class ToolTableModel;
class Workbench;

class ToolLibraryDialog : public QDialog {
    Q_OBJECT
public:
    // Reads `libraryPath`; when it does not exist yet, starts from `defaultPath` (the shipped
    // library; saving writes `libraryPath`).
    ToolLibraryDialog(Workbench& workbench, Prompter& prompter, QString libraryPath, QString defaultPath,
                      QWidget* parent = nullptr);
    ~ToolLibraryDialog() override;

    const document::ToolLibrary& library() const { return m_library; }
    const QString& libraryPath() const { return m_path; }
    // False when the library file could not be read: then nothing is written over it.
    bool canSave() const { return m_canSave; }
    bool isModified() const { return m_modified; }
    QTableView* toolView() const { return m_tools; }
    // The job's tools with their speeds and feeds (editable).
    QTableView* jobToolView() const { return m_jobTools; }
    // Selects the library's rows (indices into library().tools), as the user would.
    void selectTools(const QList<int>& rows);
    QList<int> selectedTools() const;

    void addTool();
    void duplicateTools();
    void deleteTools();
    bool importFrom(const QString& path);
    bool exportTo(const QString& path);
    void addSelectedToJob();
    bool save();

    // Close asks to save a modified library (through the prompter); Cancel keeps it open.
    void reject() override;

private:
    void buildUi();
    void load(const QString& defaultPath);
    void markModified();
    void showCuttingDataOfCurrent();
    void refreshMaterials();
    void appendTools(std::vector<ops::ToolController> tools);

    Workbench& m_workbench;
    Prompter& m_prompter;
    QString m_path;
    document::ToolLibrary m_library;
    bool m_canSave = true;
    bool m_modified = false;
    ToolTableModel* m_model = nullptr;
    QSortFilterProxyModel* m_proxy = nullptr;
    CuttingDataModel* m_cutting = nullptr;
    QTableView* m_tools = nullptr;
    QTableView* m_cuttingView = nullptr;
    QTableView* m_jobTools = nullptr;
    QTabWidget* m_tabs = nullptr;
    QLineEdit* m_filter = nullptr;
    QComboBox* m_material = nullptr;
    QLabel* m_status = nullptr;
};

}  // namespace camwb::gui
