// Edit ▸ Preferences: display units, the default post and machine of new jobs, the tool
// library's file, the language (applied at the next start, which the dialog says) and the
// autosave interval. The dialog only edits a Preferences value; the Session stores it.
#pragma once

#include "gui/shell/Preferences.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace camwb::gui {

class Prompter;

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    PreferencesDialog(const Preferences& current, Prompter& prompter, QWidget* parent = nullptr);

    // What the dialog shows now.
    Preferences preferences() const;

private:
    QWidget* toolLibraryRow();
    void fillPosts();
    void fillMachines();

    Preferences m_initial;
    Prompter& m_prompter;
    QComboBox* m_units;
    QComboBox* m_post;
    QComboBox* m_machine;
    QLineEdit* m_toolLibrary;
    QComboBox* m_language;
    QSpinBox* m_autosave;
    QLabel* m_restartNotice;
};

}  // namespace camwb::gui
