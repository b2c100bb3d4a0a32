// Program information (Cam.Nc.ProgramInfo): interprets the editor's program in its dialect in the
// background (the GUI stays responsive on a million lines) and shows extents per axis for rapids,
// cutting and both, rapid and feed lengths, a machining time estimate and the same per tool.
#pragma once

#include "nc/Dialect.h"
#include "toolpath/ProgramStats.h"

#include <QDialog>

#include <memory>

class QDoubleSpinBox;
class QLabel;
class QTextBrowser;
class QThread;

namespace camwb::gui {

class ProgramInfoDialog : public QDialog {
    Q_OBJECT

public:
    explicit ProgramInfoDialog(QWidget* parent = nullptr);
    ~ProgramInfoDialog() override;  // waits for a running analysis

    // Starts interpreting `text` off the GUI thread; `fileName` names it in diagnostics and finds
    // its subprograms (in its folder) when it is a path. machineRapidMmPerMin > 0: the machine's
    // rapid rate, which the estimate then assumes (as the post's header estimate does).
    void analyze(const QString& text, nc::Dialect dialect, const QString& fileName = {},
                 double machineRapidMmPerMin = 0);
    bool isBusy() const;
    bool hasStats() const;
    const toolpath::ProgramStats& stats() const;  // valid when hasStats()
    int errorCount() const;
    QString reportText() const;  // what the dialog shows, as plain text

signals:
    void analysisFinished();

private:
    struct Result;
    void finish(std::shared_ptr<Result> result);
    void render();

    QTextBrowser* m_view;
    QDoubleSpinBox* m_rapid;
    QLabel* m_status;
    QThread* m_thread = nullptr;
    std::shared_ptr<Result> m_result;
};

}  // namespace camwb::gui
