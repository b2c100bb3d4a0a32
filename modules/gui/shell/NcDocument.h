// The NC program in the editor as a document of its own: a file opened from disk (editable) or
// the job's posted program (read-only; Save NC Program writes it). It knows whether the editor
// holds unsaved edits, saves them, and asks (Save / Discard / Cancel, through the window's
// Prompter) before anything replaces them: another NC file, a post, another job, closing.
#pragma once

#include "gui/shell/Workbench.h"

#include <QObject>
#include <QString>

#include <functional>

namespace camwb::gui {

class NcEditor;
class Prompter;

class NcDocument : public QObject {
    Q_OBJECT
public:
    NcDocument(NcEditor* editor, std::function<Prompter&()> prompter, QObject* parent);

    // The editor now holds the program read from `path` (editable) / the job's posted program.
    void openedFile(const QString& path);
    void showsPostedProgram();
    QString filePath() const { return m_path; }  // empty: the posted program (or nothing)

    bool hasUnsavedEdits() const;
    // Writes the editor's text to its file (asks for one when it has none); false when not saved.
    bool save();
    // True when the editor may show another program: no unsaved edits, or the user saved them
    // (and saving worked) or chose to discard them. False: the user cancelled, keep everything.
    // `consequence` tells the user what happens to the edits ("Posting the job replaces them.").
    bool mayReplace(const QString& consequence);

    // "part.ngc*": the program's name and a star while it has unsaved edits.
    QString title() const;

signals:
    void message(camwb::gui::Workbench::Severity severity, const QString& text);
    void titleChanged(const QString& title);

private:
    NcEditor* m_editor;
    std::function<Prompter&()> m_prompter;
    QString m_path;
};

}  // namespace camwb::gui
