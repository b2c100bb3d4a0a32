// The NC program editor/inspector widget: QScintilla with line numbers, a monospace font and
// Sinumerik highlighting. QScintilla stays behind a pimpl so the main window never includes it.
#pragma once

#include "gui/editor/NcStyles.h"

#include <QString>
#include <QWidget>

#include <memory>

namespace camwb::gui {

class NcEditor : public QWidget {
    Q_OBJECT

public:
    explicit NcEditor(QWidget* parent = nullptr);
    ~NcEditor() override;

    void setText(const QString& text);
    QString text() const;
    void setReadOnly(bool readOnly);
    bool isReadOnly() const;

    int lineCount() const;
    void gotoLine(int line);  // 1-based; clamped to the program; moves the cursor to the line start
    int currentLine() const;  // 1-based

    // The highlighter's style (an NcStyle value) at a 1-based line and 1-based column
    // (characters), or -1 outside the text. Styles that part of the text first if needed.
    int styleAt(int line, int column) const;

signals:
    void cursorLineChanged(int line);  // 1-based

private:
    struct Private;
    void checkCursorLine();

    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
