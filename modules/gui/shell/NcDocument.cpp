#include "gui/shell/NcDocument.h"

#include "base/AtomicFile.h"
#include "gui/editor/NcEditor.h"
#include "gui/shell/Prompter.h"

#include <QFileInfo>

#include <string_view>

namespace camwb::gui {

NcDocument::NcDocument(NcEditor* editor, std::function<Prompter&()> prompter, QObject* parent) :
    QObject(parent),
    m_editor(editor),
    m_prompter(std::move(prompter))
{
    connect(m_editor, &NcEditor::modificationChanged, this, [this] { emit titleChanged(title()); });
}

void NcDocument::openedFile(const QString& path)
{
    m_path = QFileInfo(path).absoluteFilePath();
    m_editor->setReadOnly(false);
    emit titleChanged(title());
}

void NcDocument::showsPostedProgram()
{
    // Edits of the posted program would be lost at the next post and Save NC Program would not
    // write them: it stays what the post made. Open a saved copy to edit it.
    m_path.clear();
    m_editor->setReadOnly(true);
    emit titleChanged(title());
}

bool NcDocument::hasUnsavedEdits() const { return !m_editor->isReadOnly() && m_editor->isModified(); }

bool NcDocument::save()
{
    QString path = m_path;
    if (path.isEmpty())
        path = m_prompter().saveFileName(tr("Save NC program"), QString(),
                                         tr("NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;"
                                            "All files (*)"));
    if (path.isEmpty())
        return false;
    const QByteArray bytes = m_editor->utf8Text();
    const base::Status written = base::writeFileAtomically(
        path.toStdString(), std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (!written) {
        emit message(Workbench::Severity::Error, QString::fromStdString(written.error().toString()));
        return false;
    }
    m_path = QFileInfo(path).absoluteFilePath();
    m_editor->markSaved();
    emit message(Workbench::Severity::Note, tr("Saved NC program %1").arg(m_path));
    emit titleChanged(title());
    return true;
}

bool NcDocument::mayReplace(const QString& consequence)
{
    if (!hasUnsavedEdits())
        return true;
    const QString name = m_path.isEmpty() ? tr("The NC program") : QFileInfo(m_path).fileName();
    const Prompter::Answer answer = m_prompter().ask(
        {tr("Unsaved NC edits"), tr("%1 has edits that are not saved. %2\n\nSave them first?").arg(name, consequence),
         QString(), QString()});
    switch (answer) {
    case Prompter::Answer::Accept:
        return save();
    case Prompter::Answer::Discard:
        m_editor->markSaved();  // what replaces the text next needs no second question
        return true;
    case Prompter::Answer::Cancel:
        break;
    }
    return false;
}

QString NcDocument::title() const
{
    const QString name = m_path.isEmpty() ? QString() : QFileInfo(m_path).fileName();
    return name + (hasUnsavedEdits() ? QStringLiteral("*") : QString());
}

}  // namespace camwb::gui
