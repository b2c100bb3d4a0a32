#include "gui/shell/ReportView.h"

#include "base/Diagnostic.h"

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
    // A diagnostic arrives as "file:line:column: error: message", the form editors and CI parsers
    // read, and says its severity itself: a second "error: " in front of it would only repeat it.
    const char* own = severity == Workbench::Severity::Note ? nullptr : base::severityName(severity);
    if (own && text.contains(QStringLiteral(": %1: ").arg(QLatin1String(own))))
        prefix.clear();
    appendPlainText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss ")) + prefix + text);
}

}  // namespace camwb::gui
