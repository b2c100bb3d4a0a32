// The NC program editor/inspector widget: QScintilla with line numbers, a monospace font,
// highlighting and folding per dialect, diagnostics as margin markers and annotations, and a find
// bar. QScintilla stays behind a pimpl so the main window never includes it.
#pragma once

#include "gui/editor/NcStyles.h"
#include "nc/Diagnostic.h"
#include "nc/Dialect.h"
#include "toolpath/ClFormat.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

namespace camwb::gui {

// One diagnostic to show: 1-based line, 1-based column (0 = the whole line).
struct NcEditorDiagnostic {
    int line = 0;
    int column = 0;
    nc::Severity severity = nc::Severity::Error;
    QString message;
};

class NcEditor : public QWidget {
    Q_OBJECT

public:
    explicit NcEditor(QWidget* parent = nullptr);
    ~NcEditor() override;

    void setText(const QString& text);  // a new document: clears undo history, diagnostics, modified
    QString text() const;
    // The text as Scintilla holds it, without a round trip through QString (the tools' fast path).
    QByteArray utf8Text() const;
    // Replaces the whole text as one undoable step and keeps the view (cursor line, scroll).
    void replaceText(const QString& text);
    void replaceUtf8Text(const QByteArray& utf8);
    void undo();
    void redo();
    void setReadOnly(bool readOnly);
    bool isReadOnly() const;
    // Edits since setText or the last markSaved (undoing back to that point clears it again).
    bool isModified() const;
    void markSaved();

    void setDialect(nc::Dialect dialect);  // Sinumerik by default
    nc::Dialect dialect() const;
    // Set: the text is a CL file of this format (highlighted as one; block numbers are not its
    // business). The inspector sets it as it reads the program (document::clFormatToRead).
    void setClFormat(std::optional<toolpath::ClFormat> format);
    std::optional<toolpath::ClFormat> clFormat() const;
    // Where the program lives (empty: not saved): names it in the tools' dialogs and lets Program
    // info find its subprograms in the same folder.
    void setProgramPath(const QString& path);
    QString programPath() const;

    int lineCount() const;
    void gotoLine(int line);       // 1-based; clamped to the program; moves the cursor to the line start
    int currentLine() const;       // 1-based
    int firstVisibleLine() const;  // 1-based

    // The highlighter's style (an NcStyle value) at a 1-based line and 1-based column
    // (characters), or -1 outside the text. Styles that part of the text first if needed.
    int styleAt(int line, int column) const;
    // Fold depth at the start of a 1-based line (0 = top level) and whether the line opens a
    // fold; -1 / false outside the text. Styles up to the line first if needed.
    int foldDepth(int line) const;
    bool isStyledThrough(int line) const;  // without styling anything: what idle styling has done
    bool isFoldHeader(int line) const;

    // Markers in the margin and boxed annotations under the lines (worst severity per line).
    void setDiagnostics(const QList<NcEditorDiagnostic>& diagnostics);
    void clearDiagnostics();
    std::optional<nc::Severity> diagnosticSeverityAt(int line) const;
    QString annotationAt(int line) const;
    // Diagnostics of the program `file` (others belong to called programs), for setDiagnostics.
    static QList<NcEditorDiagnostic> diagnosticsFor(const std::vector<nc::Diagnostic>& diagnostics,
                                                    const std::string& file);

    // Selects the next (or previous) match from the cursor, wrapping; false when there is none.
    bool findText(const QString& text, bool forward = true, bool caseSensitive = false, bool wholeWord = false);
    void showFindBar();  // with the selected text, focused

signals:
    void cursorLineChanged(int line);  // 1-based
    void textChanged();                // any edit, setText and replaceText included
    void modificationChanged(bool modified);

private:
    struct Private;
    void checkCursorLine();
    void styleThrough(int line) const;

    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
