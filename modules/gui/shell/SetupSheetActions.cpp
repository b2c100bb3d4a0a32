#include "gui/shell/SetupSheetActions.h"

#include "document/SetupSheet.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Prompter.h"
#include "gui/shell/Workbench.h"
#include "post/PostRegistry.h"
#include "sheet/SheetFiles.h"
#include "sheet/SheetPicture.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace camwb::gui {

namespace {

// Translation context of the strings below (lupdate reads Q_DECLARE_TR_FUNCTIONS).
class Tr {
    Q_DECLARE_TR_FUNCTIONS(SetupSheetActions)
};

// Writes the sheet to `html` and the PDF beside it; the error's text, or an empty string.
QString writeSheet(Workbench& workbench, const QString& html, const QImage& grabbed)
{
    const document::Job& job = workbench.job();
    std::string jobPath = workbench.document().path();
    if (jobPath.empty())
        jobPath = (job.name.empty() ? std::string("job") : job.name) + ".camwb";
    document::SheetOptions options;
    options.postDirs = post::defaultPostDirs();
    auto sheet = document::collectSetupSheet(job, jobPath, workbench.model(), workbench.toolpath(), options);
    if (!sheet)
        return QString::fromStdString(sheet.error().toString());
    const sheet::SheetPicture pictures(workbench.model().mesh(), job.stock.box(), workbench.toolpath());
    sheet::SheetOutput output;
    output.htmlPath = html.toStdString();
    const QFileInfo info(html);
    output.pdfPath = info.dir().filePath(info.completeBaseName() + QStringLiteral(".pdf")).toStdString();
    if (!grabbed.isNull())
        output.partPicture =
            grabbed.scaled(sheet::kPartWidth, sheet::kPartHeight, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    if (const base::Status written = sheet::writeSetupSheet(sheet.value(), pictures, output); !written)
        return QString::fromStdString(written.error().toString());
    return {};
}

}  // namespace

void registerSetupSheetActions(ActionRegistry& registry, const QString& menu, Workbench* workbench,
                               std::function<Prompter&()> prompter, std::function<QImage()> grab)
{
    QAction* action = registry.add({"Cam.Job.SetupSheet",
                                    Tr::tr("Setup &Sheet…"),
                                    menu,
                                    {},
                                    false,
                                    false,
                                    Tr::tr("Write the setup sheet of the job for the operator: HTML and PDF")});
    QObject::connect(action, &QAction::triggered, workbench, [workbench, prompter, grab] {
        // The sheet shows the program as posted: not one that is out of date or being computed.
        if (!workbench->ncSavable())
            return;
        const QString base = QFileInfo(QString::fromStdString(workbench->document().path())).completeBaseName();
        const QString html = prompter().saveFileName(
            Tr::tr("Save setup sheet"), (base.isEmpty() ? QStringLiteral("job") : base) + QStringLiteral("-sheet.html"),
            Tr::tr("Setup sheets (*.html);;All files (*)"));
        if (html.isEmpty())
            return;
        QApplication::setOverrideCursor(Qt::WaitCursor);
        const QString error = writeSheet(*workbench, html, grab());
        QApplication::restoreOverrideCursor();
        if (!error.isEmpty())
            prompter().showError(Tr::tr("Setup sheet"), Tr::tr("The setup sheet was not written: %1").arg(error));
        else
            emit workbench->message(Workbench::Severity::Note, Tr::tr("Setup sheet written: %1").arg(html));
    });
}

}  // namespace camwb::gui
