// The questions the window asks the user (unsaved changes, a file to open or save, a yes/no before
// something is lost) behind one interface: DialogPrompter shows the usual message boxes and file
// dialogs; a test gives the window its own Prompter and answers them without a modal dialog.
#pragma once

#include <QString>

class QWidget;

namespace camwb::gui {

enum class SaveChoice { Save, Discard, Cancel };

class Prompter {
public:
    virtual ~Prompter() = default;

    // `text` says what has unsaved changes and what would lose them; Cancel is the safe answer.
    virtual SaveChoice askSaveChanges(QWidget* parent, const QString& title, const QString& text) = 0;
    // An action whose consequence `text` states: true to go on.
    virtual bool confirm(QWidget* parent, const QString& title, const QString& text) = 0;
    // A file to read or to write (`suggested`: the proposed name or folder); empty when cancelled.
    virtual QString openFileName(QWidget* parent, const QString& caption, const QString& suggested,
                                 const QString& filter) = 0;
    virtual QString saveFileName(QWidget* parent, const QString& caption, const QString& suggested,
                                 const QString& filter) = 0;
};

// Message boxes and file dialogs.
class DialogPrompter : public Prompter {
public:
    SaveChoice askSaveChanges(QWidget* parent, const QString& title, const QString& text) override;
    bool confirm(QWidget* parent, const QString& title, const QString& text) override;
    QString openFileName(QWidget* parent, const QString& caption, const QString& suggested,
                         const QString& filter) override;
    QString saveFileName(QWidget* parent, const QString& caption, const QString& suggested,
                         const QString& filter) override;
};

}  // namespace camwb::gui
