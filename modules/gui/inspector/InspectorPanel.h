// The inspector dock's content: the dialect the program is read in (auto or a chosen one), the
// machine it is traced on (its limits, and its kinematics for five-axis NC), what the 3D view
// shows (the NC trace or the operations' toolpath), a checkable list of the tools in the
// backplot and the modal state of the cursor's block. Emits choices; decides nothing.
#pragma once

#include "nc/Dialect.h"

#include <QWidget>

#include <optional>
#include <utility>
#include <vector>

class QComboBox;
class QListWidget;
class QListWidgetItem;

namespace camwb::gui {

class ModalStatePanel;

class InspectorPanel : public QWidget {
    Q_OBJECT
public:
    explicit InspectorPanel(QWidget* parent = nullptr);

    ModalStatePanel* modalPanel() const { return m_modal; }

    std::optional<nc::Dialect> dialect() const;  // nullopt = automatic
    void setDialect(std::optional<nc::Dialect> dialect);
    bool showsNcTrace() const;
    void setShowsNcTrace(bool show);
    // Replaces the tool list; `hidden` are unchecked.
    void setTools(const std::vector<int>& tools, const std::vector<int>& hidden);
    void setToolChecked(int tool, bool checked);
    QListWidget* toolList() const { return m_tools; }
    // The machines to choose from (id and shown name); the choice is kept where the id still is.
    void setMachines(const std::vector<std::pair<QString, QString>>& machines);
    // The machine the program is traced on (empty: none), shown without emitting machineChosen.
    void setMachineId(const QString& id);
    QString machineId() const;

signals:
    void dialectChosen(std::optional<camwb::nc::Dialect> dialect);
    void showNcTraceChosen(bool show);
    void toolVisibilityChanged(int tool, bool visible);
    void machineChosen(const QString& id);  // empty: none

private:
    QComboBox* m_dialect;
    QComboBox* m_source;
    QListWidget* m_tools;
    QComboBox* m_machine;
    ModalStatePanel* m_modal;
    bool m_filling = false;
};

}  // namespace camwb::gui
