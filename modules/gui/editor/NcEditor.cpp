#include "gui/editor/NcEditor.h"

#include "gui/editor/detail/SinumerikLexer.h"

#include <Qsci/qsciscintilla.h>

#include <QVBoxLayout>

#include <algorithm>

namespace camwb::gui {

struct NcEditor::Private {
    QsciScintilla* sci = nullptr;
    SinumerikLexer* lexer = nullptr;
    int lastLine = 1;
};

NcEditor::NcEditor(QWidget* parent) : QWidget(parent), d(std::make_unique<Private>())
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    d->sci = new QsciScintilla(this);
    d->sci->setObjectName(QStringLiteral("ncEditorText"));
    d->sci->setUtf8(true);
    d->lexer = new SinumerikLexer(d->sci);
    d->sci->setLexer(d->lexer);
    d->sci->setFont(d->lexer->defaultFont(0));

    d->sci->setMarginType(0, QsciScintilla::NumberMargin);
    d->sci->setMarginLineNumbers(0, true);
    d->sci->setMarginsFont(d->lexer->defaultFont(0));
    d->sci->setMarginsBackgroundColor(QColor(240, 240, 240));
    d->sci->setMarginsForegroundColor(QColor(120, 120, 120));
    d->sci->setMarginWidth(1, 0);
    d->sci->setCaretLineVisible(true);
    d->sci->setCaretLineBackgroundColor(QColor(255, 250, 220));
    d->sci->setWrapMode(QsciScintilla::WrapNone);
    d->sci->setIndentationsUseTabs(false);
    d->sci->setTabWidth(4);
    d->sci->setEolMode(QsciScintilla::EolUnix);
    layout->addWidget(d->sci);
    setFocusProxy(d->sci);

    auto updateMargin = [this] {
        const int digits = QString::number(std::max(1, d->sci->lines())).size();
        d->sci->setMarginWidth(0, QString(digits + 1, QLatin1Char('9')));
    };
    updateMargin();
    connect(d->sci, &QsciScintilla::linesChanged, this, updateMargin);
    connect(d->sci, &QsciScintilla::cursorPositionChanged, this, [this](int, int) { checkCursorLine(); });
}

NcEditor::~NcEditor() = default;

void NcEditor::setText(const QString& text)
{
    d->sci->setText(text);
    checkCursorLine();
}

QString NcEditor::text() const { return d->sci->text(); }

void NcEditor::setReadOnly(bool readOnly) { d->sci->setReadOnly(readOnly); }

bool NcEditor::isReadOnly() const { return d->sci->isReadOnly(); }

int NcEditor::lineCount() const { return d->sci->lines(); }

void NcEditor::gotoLine(int line)
{
    const int target = std::clamp(line, 1, std::max(1, lineCount())) - 1;
    d->sci->setCursorPosition(target, 0);
    d->sci->ensureLineVisible(target);
    // QScintilla reports cursor moves only when it repaints; tell listeners now.
    checkCursorLine();
}

int NcEditor::currentLine() const
{
    int line = 0;
    int index = 0;
    d->sci->getCursorPosition(&line, &index);
    return line + 1;
}

void NcEditor::checkCursorLine()
{
    const int line = currentLine();
    if (line != d->lastLine) {
        d->lastLine = line;
        emit cursorLineChanged(line);
    }
}

int NcEditor::styleAt(int line, int column) const
{
    if (line < 1 || line > lineCount() || column < 1)
        return -1;
    const int lineLength =
        static_cast<int>(d->sci->text(line - 1).remove(QLatin1Char('\n')).remove(QLatin1Char('\r')).size());
    if (column > lineLength)
        return -1;
    const long position = d->sci->positionFromLineIndex(line - 1, column - 1);
    const long lineEnd =
        d->sci->SendScintilla(QsciScintillaBase::SCI_GETLINEENDPOSITION, static_cast<unsigned long>(line - 1));
    // For a container lexer this asks the lexer to style up to the line end (if not yet done).
    const long styledTo = d->sci->SendScintilla(QsciScintillaBase::SCI_GETENDSTYLED);
    if (styledTo <= lineEnd)
        d->sci->SendScintilla(QsciScintillaBase::SCI_COLOURISE, static_cast<unsigned long>(styledTo), lineEnd);
    return static_cast<int>(
        d->sci->SendScintilla(QsciScintillaBase::SCI_GETSTYLEAT, static_cast<unsigned long>(position)));
}

}  // namespace camwb::gui
