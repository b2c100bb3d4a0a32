// The report/log dock's widget: messages from the Workbench with time and severity.
#pragma once

#include "gui/shell/Workbench.h"

#include <QPlainTextEdit>

namespace camwb::gui {

class ReportView : public QPlainTextEdit {
    Q_OBJECT
public:
    explicit ReportView(QWidget* parent = nullptr);
    void append(Workbench::Severity severity, const QString& text);
};

}  // namespace camwb::gui
