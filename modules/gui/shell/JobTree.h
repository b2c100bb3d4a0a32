// The job tree dock's widget: model, stock, tools and operations of the current job, rebuilt
// from the Workbench on every change. An operation that cannot be made (and a model that cannot
// be read) is shown in red with the reason. Double-clicking an operation asks to edit it.
#pragma once

#include <QTreeWidget>

namespace camwb::gui {

class Workbench;

class JobTree : public QTreeWidget {
    Q_OBJECT
public:
    explicit JobTree(Workbench& workbench, QWidget* parent = nullptr);

    // Index of the selected operation, -1 when none is selected.
    int selectedOperation() const;

signals:
    void editOperationRequested(int index);

private:
    void rebuild();

    Workbench& m_workbench;
};

}  // namespace camwb::gui
