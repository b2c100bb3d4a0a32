// Compare two NC programs side by side (Cam.Nc.Compare), as CIMCO's file compare does: aligned
// rows with gaps, changed / removed / added lines marked, the changed characters underlined,
// synchronised scrolling, next / previous difference, and options to ignore block numbers and
// blanks (a renumbered program then compares equal). QScintilla stays private.
#pragma once

#include "nc/Dialect.h"
#include "nc/tools/LineDiff.h"
#include "toolpath/ClFormat.h"

#include <QDialog>

#include <memory>
#include <optional>

namespace camwb::gui {

class CompareDialog : public QDialog {
    Q_OBJECT

public:
    explicit CompareDialog(nc::Dialect dialect, QWidget* parent = nullptr);
    ~CompareDialog() override;

    // How both sides are highlighted and their block numbers told: the editor's program's dialect,
    // or the CL format it was read as. A reused dialog takes the program it compares now.
    void setLanguage(nc::Dialect dialect, std::optional<toolpath::ClFormat> clFormat);

    // A side is compared once it holds a program (an empty file is a program); until both do, the
    // dialog shows the sides as they are, with no differences.
    void setLeft(const QString& text, const QString& title);
    void setRight(const QString& text, const QString& title);
    bool loadLeft(const QString& path);  // false (and a message in the title) when unreadable
    bool loadRight(const QString& path);
    void setIgnoreBlockNumbers(bool ignore);
    void setIgnoreWhitespace(bool ignore);

    const nc::LineDiff& diff() const;
    int differenceCount() const;
    QString summaryText() const;    // "2 difference(s)", "Open a program on the right to compare", …
    int currentDifference() const;  // index into diff().hunks, -1 before the first
    void nextDifference();
    void previousDifference();
    int firstVisibleRow(bool left) const;  // 0-based display row, for the synced scrolling
    // The highlighter's style (an NcStyle value) at a 1-based display row and column, as
    // NcEditor::styleAt; -1 outside the text. For tests.
    int styleAt(bool left, int row, int column) const;

protected:
    void showEvent(QShowEvent* event) override;

private:
    struct Private;
    void invalidate();
    void ensureComputed() const;
    void recompute();
    void showUncompared();
    void showDifference(int index);
    void chooseFile(bool left);

    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
