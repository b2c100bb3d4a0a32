// The job's post and its property values in one dialog (action Cam.Job.PostSettings, menu Job):
// a post combo offering the posts that serve the job's machine ("Show all posts" lifts the
// filter) and the post's PostPropertiesForm. OK applies both as one undo step.
#pragma once

#include "kinematics/Machine.h"
#include "post/PostInfo.h"

#include <QDialog>

#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;

namespace camwb::gui {

class ActionRegistry;
class PostPropertiesForm;
class Workbench;

class PostSettingsPanel : public QDialog {
    Q_OBJECT
public:
    PostSettingsPanel(Workbench& workbench, QWidget* parent = nullptr);

    PostPropertiesForm* form() const { return m_form; }
    QComboBox* postCombo() const { return m_posts; }
    QCheckBox* showAllPosts() const { return m_showAll; }
    // The posts the combo offers now, by id.
    QStringList offeredPosts() const;
    // Picks post `id` in the combo (shown even when filtered out); false when no such post loads.
    bool choosePost(const QString& id);

    void accept() override;

private:
    void fillPosts(const QString& keep);
    void postChosen();
    void showMachine(const post::PostInfo& chosen);
    const post::PostInfo* info(const QString& id) const;

    Workbench& m_workbench;
    std::vector<post::PostInfo> m_all;                // every post that loads, by id
    std::optional<kinematics::Machine> m_jobMachine;  // the job's (or its post's default), if found
    QComboBox* m_posts = nullptr;
    QCheckBox* m_showAll = nullptr;
    QLabel* m_machineNote = nullptr;
    QLabel* m_dropped = nullptr;
    PostPropertiesForm* m_form = nullptr;
};

// Registers Cam.Job.PostSettings ("Post && Properties…"), which opens the panel over `parent`.
void registerPostSettingsActions(ActionRegistry& registry, Workbench* workbench, QWidget* parent);

}  // namespace camwb::gui
