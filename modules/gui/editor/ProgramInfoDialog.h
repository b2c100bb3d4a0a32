// Program information (Cam.Nc.ProgramInfo): interprets the editor's program in its dialect in the
// background (the GUI stays responsive on a million lines) and shows extents per axis for rapids,
// cutting and both, rapid and feed lengths, the cycle time with the machine's accelerations
// (sim::planMotion) beside the simple distance/feed estimate, and the same per tool.
#pragma once

#include "nc/Dialect.h"
#include "toolpath/ClFormat.h"
#include "toolpath/ProgramStats.h"

#include <memory>
#include <optional>

#include <QDialog>

#include <memory>

class QDoubleSpinBox;
class QLabel;
class QTextBrowser;
class QThread;

namespace camwb::kinematics {
struct Machine;
}

namespace camwb::gui {

// A time as the program information shows it: "12.5 s", "4:07", "1:02:03" (also the job tree's).
QString formatDuration(double seconds);

class ProgramInfoDialog : public QDialog {
    Q_OBJECT

public:
    explicit ProgramInfoDialog(QWidget* parent = nullptr);
    ~ProgramInfoDialog() override;  // waits for a running analysis

    // Starts interpreting `text` off the GUI thread; `fileName` names it in diagnostics and finds
    // its subprograms (in its folder) when it is a path. With a `machine`, the simple estimate
    // assumes its rapid rate (as the post's header estimate does) and the cycle time is planned on
    // its axes; without one, on the default limits (kinematics/Machine.h), which the dialog says.
    // With a `clFormat` the text is read as that CL file (as the editor holds it), not as NC.
    void analyze(const QString& text, nc::Dialect dialect, const QString& fileName = {},
                 std::shared_ptr<const kinematics::Machine> machine = nullptr,
                 std::optional<toolpath::ClFormat> clFormat = std::nullopt);
    bool isBusy() const;
    bool hasStats() const;
    const toolpath::ProgramStats& stats() const;  // valid when hasStats()
    double plannedSeconds() const;                // the cycle time with accelerations; valid when hasStats()
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
