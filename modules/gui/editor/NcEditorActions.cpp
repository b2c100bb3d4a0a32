#include "gui/editor/NcEditorActions.h"

#include "gui/actions/ActionRegistry.h"
#include "gui/editor/CompareDialog.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/ProgramInfoDialog.h"
#include "gui/editor/RenumberDialog.h"
#include "gui/shell/Prompter.h"
#include "nc/tools/BlockNumbers.h"

#include <QAction>
#include <QCoreApplication>
#include <QFileInfo>
#include <QInputDialog>
#include <QMainWindow>
#include <QPointer>
#include <QStatusBar>

namespace camwb::gui {

namespace {

// Translation context of the strings below (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class Tr {
    Q_DECLARE_TR_FUNCTIONS(NcEditorActions)
};

void showMessage(QWidget* parent, const QString& message)
{
    if (auto* window = qobject_cast<QMainWindow*>(parent))
        window->statusBar()->showMessage(message, 10'000);
}

QString summary(const nc::RenumberReport& report, bool removing)
{
    QString text = removing ? Tr::tr("Removed %1 block number(s)").arg(report.numbersRemoved)
                            : Tr::tr("Numbered %1 block(s)").arg(report.linesNumbered);
    if (report.targetsRemapped > 0)
        text += Tr::tr(", %1 jump target(s) follow their blocks").arg(report.targetsRemapped);
    if (!report.notes.empty()) {
        const nc::RenumberNote& first = report.notes.front();
        text += first.line > 0 ? Tr::tr("; line %1: %2").arg(first.line).arg(QString::fromStdString(first.message))
                               : Tr::tr("; %1").arg(QString::fromStdString(first.message));
        if (report.notes.size() > 1)
            text += Tr::tr(" (and %1 more note(s))").arg(report.notes.size() - 1);
    }
    return text;
}

// Applies a rewrite of the whole program as one undo step; nothing when it changes nothing.
void applyRewrite(NcEditor* editor, QWidget* parent, const nc::RenumberResult& result, bool removing)
{
    const QByteArray bytes = QByteArray::fromStdString(result.text);
    if (bytes != editor->utf8Text())
        editor->replaceUtf8Text(bytes);
    showMessage(parent, summary(result.report, removing));
}

// Block numbers are NC's: a CL file (APT, FreeCAD dump, trace) has none, and numbering its
// statements would break it. True (and says so) when the editor holds one, as it was read.
bool refusedForClFile(const NcEditor* editor, QWidget* parent)
{
    if (!editor->clFormat())
        return false;
    showMessage(
        parent,
        Tr::tr("%1 is a CL file: block numbers are for NC programs").arg(QFileInfo(editor->programPath()).fileName()));
    return true;
}

std::string_view view(const QByteArray& bytes) { return {bytes.constData(), static_cast<std::size_t>(bytes.size())}; }

template <class Dialog> Dialog* reuseOrCreate(QWidget* parent, NcEditor* editor)
{
    // One modeless dialog of each kind; a second trigger refreshes it.
    if (auto* existing = parent->findChild<Dialog*>(QString(), Qt::FindDirectChildrenOnly))
        return existing;
    if constexpr (std::is_same_v<Dialog, CompareDialog>) {
        auto* dialog = new Dialog(editor->dialect(), parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        return dialog;
    } else {
        auto* dialog = new Dialog(parent);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        return dialog;
    }
}

}  // namespace

void registerNcEditorActions(ActionRegistry& registry, NcEditor* editor, QWidget* dialogParent,
                             std::function<Prompter&()> prompter,
                             std::function<std::shared_ptr<const kinematics::Machine>()> machine)
{
    const QString menu = Tr::tr("&NC");
    QPointer<NcEditor> ed(editor);
    QPointer<QWidget> parent(dialogParent);
    auto add = [&registry](const ActionSpec& spec, auto handler) {
        QAction* action = registry.add(spec);
        QObject::connect(action, &QAction::triggered, action, handler);
        return action;
    };

    add({QStringLiteral("Cam.Nc.Find"), Tr::tr("&Find…"), menu, QKeySequence::Find, false, false,
         Tr::tr("Find text in the NC program")},
        [ed] {
            if (ed)
                ed->showFindBar();
        });
    add({QStringLiteral("Cam.Nc.GotoBlock"), Tr::tr("&Go to Block…"), menu, QKeySequence(Qt::CTRL | Qt::Key_G), false,
         false, Tr::tr("Jump to the block with a given number")},
        [ed, parent] {
            if (!ed)
                return;
            bool ok = false;
            const int number =
                QInputDialog::getInt(parent, Tr::tr("Go to Block"), Tr::tr("Block number:"), 0, 0, 999'999'999, 1, &ok);
            if (!ok)
                return;
            const QByteArray text = ed->utf8Text();
            if (const std::optional<int> line = nc::findBlock(view(text), ed->dialect(), number)) {
                ed->gotoLine(*line);
                ed->setFocus();
            } else {
                showMessage(parent, Tr::tr("No block number %1 in the program").arg(number));
            }
        });
    add({QStringLiteral("Cam.Nc.Renumber"), Tr::tr("&Renumber Blocks…"), menu, QKeySequence(), false, true,
         Tr::tr("Renumber the blocks of the NC program (one undo step)")},
        [ed, parent] {
            if (!ed)
                return;
            if (ed->isReadOnly()) {
                showMessage(parent, Tr::tr("The NC program is read-only"));
                return;
            }
            if (refusedForClFile(ed, parent))
                return;
            RenumberDialog dialog(ed->dialect(), parent);
            if (dialog.exec() != QDialog::Accepted || !ed)
                return;
            const QByteArray text = ed->utf8Text();
            applyRewrite(ed, parent, nc::renumberBlocks(view(text), dialog.options()), false);
        });
    add({QStringLiteral("Cam.Nc.RemoveNumbers"), Tr::tr("Re&move Block Numbers"), menu, QKeySequence(), false, false,
         Tr::tr("Remove the N numbers (blocks a GOTO jumps to keep theirs)")},
        [ed, parent] {
            if (!ed)
                return;
            if (ed->isReadOnly()) {
                showMessage(parent, Tr::tr("The NC program is read-only"));
                return;
            }
            if (refusedForClFile(ed, parent))
                return;
            const QByteArray text = ed->utf8Text();
            applyRewrite(ed, parent, nc::removeBlockNumbers(view(text), ed->dialect()), true);
        });
    add({QStringLiteral("Cam.Nc.Compare"), Tr::tr("&Compare with File…"), menu, QKeySequence(), false, true,
         Tr::tr("Compare the NC program with another file side by side")},
        [ed, parent, prompter] {
            if (!ed || !parent)
                return;
            // The file first: a dialog with one side would compare the program with nothing.
            const QString path = prompter().openFileName(
                Tr::tr("Compare with File"),
                Tr::tr("NC programs (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;"
                       "CL files (*.apt *.aptsource *.cl *.cls *.dump *.trace);;All files (*)"));
            if (path.isEmpty() || !ed)
                return;
            CompareDialog* dialog = reuseOrCreate<CompareDialog>(parent, ed);
            dialog->setLanguage(ed->dialect(), ed->clFormat());
            const QString name = QFileInfo(ed->programPath()).fileName();
            dialog->setLeft(ed->text(),
                            name.isEmpty() ? Tr::tr("Current program") : Tr::tr("%1 (in the editor)").arg(name));
            if (!dialog->loadRight(path))
                showMessage(parent, Tr::tr("Cannot read %1").arg(path));
            dialog->show();
            dialog->raise();
        });
    add({QStringLiteral("Cam.Nc.ProgramInfo"), Tr::tr("Program &Information…"), menu, QKeySequence(), false, false,
         Tr::tr("Extents, path lengths and machining time of the NC program")},
        [ed, parent, machine] {
            if (!ed || !parent)
                return;
            ProgramInfoDialog* dialog = reuseOrCreate<ProgramInfoDialog>(parent, ed);
            dialog->analyze(ed->text(), ed->dialect(), ed->programPath(), machine ? machine() : nullptr,
                            ed->clFormat());
            dialog->show();
            dialog->raise();
        });
}

}  // namespace camwb::gui
