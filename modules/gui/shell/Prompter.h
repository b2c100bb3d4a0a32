// Every question the window asks the user (file names, "save the changes?", "drop these
// operations?") and every error it shows goes through this interface, so tests answer the
// questions and read the errors without a person and without a modal dialog blocking them.
// DialogPrompter is the real one: file dialogs, message boxes, errors in a non-modal box.
#pragma once

#include <QPointer>
#include <QString>

class QMessageBox;
class QWidget;

namespace camwb::gui {

class Prompter {
public:
    // A question with three answers: keep the work (Save/Apply/Keep), throw it away
    // (Discard/Delete) or go back (Cancel). Empty texts use the standard Save and Discard buttons.
    struct Question {
        QString title;
        QString text;
        QString acceptText;   // e.g. "Apply", "Keep the operations"; empty: Save
        QString discardText;  // e.g. "Delete them"; empty: Discard
    };
    enum class Answer { Accept, Discard, Cancel };

    virtual ~Prompter() = default;
    virtual Answer ask(const Question& question) = 0;
    // A file to read or to write; empty when the user cancelled.
    virtual QString openFileName(const QString& title, const QString& filter) = 0;
    virtual QString saveFileName(const QString& title, const QString& suggested, const QString& filter) = 0;
    // An error that stopped what the user asked for, shown where they look; never blocks.
    virtual void showError(const QString& title, const QString& text) = 0;
};

class DialogPrompter : public Prompter {
public:
    explicit DialogPrompter(QWidget* parent);
    Answer ask(const Question& question) override;
    QString openFileName(const QString& title, const QString& filter) override;
    QString saveFileName(const QString& title, const QString& suggested, const QString& filter) override;
    void showError(const QString& title, const QString& text) override;

private:
    QWidget* m_parent;
    QPointer<QMessageBox> m_error;  // one box: later errors are added to it while it is open
};

}  // namespace camwb::gui
