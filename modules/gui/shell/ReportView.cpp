#include "gui/shell/ReportView.h"

#include <QTime>

namespace camwb::gui {

ReportView::ReportView(QWidget* parent) : QPlainTextEdit(parent)
{
    setObjectName(QStringLiteral("reportView"));
    setReadOnly(true);
    setMaximumBlockCount(5000);
}

void ReportView::append(Workbench::Severity severity, const QString& text)
{
    QString prefix;
    switch (severity) {
    case Workbench::Severity::Warning:
        prefix = tr("warning: ");
        break;
    case Workbench::Severity::Error:
        prefix = tr("error: ");
        break;
    case Workbench::Severity::Note:
        break;
    }
    appendPlainText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss ")) + prefix + text);
}

}  // namespace camwb::gui
