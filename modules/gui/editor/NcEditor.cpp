#include "gui/editor/NcEditor.h"

#include "gui/editor/detail/NcFindBar.h"
#include "gui/editor/detail/NcLexer.h"

#include <Qsci/qsciscintilla.h>
#include <Qsci/qscistyle.h>

#include <QAccessible>
#include <QAccessibleWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <map>

namespace camwb::gui {

namespace {

using Base = QsciScintillaBase;

constexpr int kMarkerMargin = 1;
constexpr int kFoldMargin = 2;
// Markers and squiggle indicators per severity, indexed by nc::Severity (Note, Warning, Error).
constexpr int kFirstMarker = 8;
constexpr int kFirstIndicator = 8;
// Annotation styles per severity: fixed numbers far above the lexer's styles (QsciStyle's own
// allocation counts down from 63 and is shared by every editor in the process).
constexpr int kFirstAnnotationStyle = 200;

// QScintilla's accessibility interface turns the caret position into a character offset by
// counting from the document start on every repaint: half a second per scroll step at the end of
// a million-line program. Unless an accessibility client is listening (then screen readers get
// QScintilla's full text interface), editors get a plain widget interface. Qt creates interfaces
// for widget events even when no client listens, and caches them per object.
QAccessibleInterface* plainScintillaAccessible(const QString&, QObject* object)
{
    if (!QAccessible::isActive() && object != nullptr && object->isWidgetType() &&
        object->inherits("QsciScintillaBase"))
        return new QAccessibleWidget(static_cast<QWidget*>(object), QAccessible::EditableText);
    return nullptr;
}

int severityIndex(nc::Severity s) { return static_cast<int>(s); }

QColor severityColor(nc::Severity s)
{
    switch (s) {
    case nc::Severity::Note:
        return QColor(40, 110, 200);
    case nc::Severity::Warning:
        return QColor(220, 140, 0);
    case nc::Severity::Error:
        break;
    }
    return QColor(210, 30, 30);
}

QColor annotationPaper(nc::Severity s)
{
    switch (s) {
    case nc::Severity::Note:
        return QColor(232, 240, 252);
    case nc::Severity::Warning:
        return QColor(255, 244, 214);
    case nc::Severity::Error:
        break;
    }
    return QColor(255, 226, 226);
}

}  // namespace

struct NcEditor::Private {
    QsciScintilla* sci = nullptr;
    NcLexer* lexer = nullptr;
    NcFindBar* findBar = nullptr;
    std::vector<QsciStyle> annotationStyles;  // per severity
    QString programPath;
    int lastLine = 1;
};

NcEditor::NcEditor(QWidget* parent) : QWidget(parent), d(std::make_unique<Private>())
{
    QAccessible::installFactory(plainScintillaAccessible);  // Qt ignores repeated installs
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    d->sci = new QsciScintilla(this);
    d->sci->setObjectName(QStringLiteral("ncEditorText"));
    d->sci->setUtf8(true);
    d->lexer = new NcLexer(d->sci);
    d->sci->setLexer(d->lexer);
    d->sci->setFont(d->lexer->defaultFont(0));

    d->sci->setMarginType(0, QsciScintilla::NumberMargin);
    d->sci->setMarginLineNumbers(0, true);
    d->sci->setMarginsFont(d->lexer->defaultFont(0));
    d->sci->setMarginsBackgroundColor(QColor(240, 240, 240));
    d->sci->setMarginsForegroundColor(QColor(120, 120, 120));
    d->sci->setCaretLineVisible(true);
    d->sci->setCaretLineBackgroundColor(QColor(255, 250, 220));
    d->sci->setWrapMode(QsciScintilla::WrapNone);
    d->sci->setIndentationsUseTabs(false);
    d->sci->setTabWidth(4);
    d->sci->setEolMode(QsciScintilla::EolUnix);
    // Jumping far into a big program styles what comes before the view in idle time, in slices,
    // instead of freezing until everything up to there is styled (the view shows plain text for
    // a moment instead).
    d->sci->SendScintilla(Base::SCI_SETIDLESTYLING, static_cast<unsigned long>(Base::SC_IDLESTYLING_TOVISIBLE));
    // The horizontal scroll range follows the longest line seen, not a fixed 2000 pixels.
    d->sci->SendScintilla(Base::SCI_SETSCROLLWIDTH, 1UL);
    d->sci->SendScintilla(Base::SCI_SETSCROLLWIDTHTRACKING, 1UL);
    // The lexer sets a line state per line; nobody listens to those changes, and a million
    // notifications (Qt signals) cost more than the lexing.
    d->sci->SendScintilla(Base::SCI_SETMODEVENTMASK,
                          static_cast<unsigned long>(Base::SC_MODEVENTMASKALL & ~Base::SC_MOD_CHANGELINESTATE));

    // Diagnostics: a symbol margin with one marker per severity, squiggles under the column,
    // boxed annotations under the line.
    d->sci->setMarginType(kMarkerMargin, QsciScintilla::SymbolMargin);
    d->sci->setMarginWidth(kMarkerMargin, 16);
    d->sci->setMarginSensitivity(kMarkerMargin, false);
    int markerMask = 0;
    for (nc::Severity s : {nc::Severity::Note, nc::Severity::Warning, nc::Severity::Error}) {
        const int marker = kFirstMarker + severityIndex(s);
        d->sci->markerDefine(s == nc::Severity::Error ? QsciScintilla::Circle : QsciScintilla::RightTriangle, marker);
        d->sci->setMarkerBackgroundColor(severityColor(s), marker);
        d->sci->setMarkerForegroundColor(severityColor(s).darker(140), marker);
        markerMask |= 1 << marker;
        const int indicator = kFirstIndicator + severityIndex(s);
        d->sci->indicatorDefine(QsciScintilla::SquiggleIndicator, indicator);
        d->sci->setIndicatorForegroundColor(severityColor(s), indicator);
        QFont font = d->lexer->defaultFont(0);
        font.setItalic(true);
        d->annotationStyles.emplace_back(kFirstAnnotationStyle + severityIndex(s), QStringLiteral("diagnostic"),
                                         severityColor(s).darker(130), annotationPaper(s), font);
    }
    d->sci->setMarginMarkerMask(kMarkerMargin, markerMask);
    d->sci->setMarginMarkerMask(0, 0);
    d->sci->setAnnotationDisplay(QsciScintilla::AnnotationBoxed);
    d->sci->setFolding(QsciScintilla::BoxedTreeFoldStyle, kFoldMargin);
    d->sci->setFoldMarginColors(QColor(245, 245, 245), QColor(245, 245, 245));

    layout->addWidget(d->sci, 1);
    d->findBar = new NcFindBar(this);
    layout->addWidget(d->findBar);
    setFocusProxy(d->sci);

    auto updateMargin = [this] {
        const int digits = QString::number(std::max(1, d->sci->lines())).size();
        d->sci->setMarginWidth(0, QString(digits + 1, QLatin1Char('9')));
    };
    updateMargin();
    connect(d->sci, &QsciScintilla::linesChanged, this, updateMargin);
    connect(d->sci, &QsciScintilla::cursorPositionChanged, this, [this](int, int) { checkCursorLine(); });
    connect(d->sci, &QsciScintilla::textChanged, this, &NcEditor::textChanged);
    connect(d->sci, &QsciScintilla::modificationChanged, this, &NcEditor::modificationChanged);
}

NcEditor::~NcEditor() = default;

void NcEditor::setText(const QString& text)
{
    clearDiagnostics();
    d->sci->setText(text);
    d->sci->SendScintilla(Base::SCI_EMPTYUNDOBUFFER);
    d->sci->SendScintilla(Base::SCI_SETSAVEPOINT);
    checkCursorLine();
}

QString NcEditor::text() const { return d->sci->text(); }

QByteArray NcEditor::utf8Text() const
{
    const long length = d->sci->SendScintilla(Base::SCI_GETLENGTH);
    QByteArray bytes(static_cast<qsizetype>(length) + 1, Qt::Uninitialized);
    d->sci->SendScintilla(Base::SCI_GETTEXT, static_cast<unsigned long>(length + 1), bytes.data());
    bytes.resize(static_cast<qsizetype>(length));
    return bytes;
}

void NcEditor::replaceText(const QString& text) { replaceUtf8Text(text.toUtf8()); }

void NcEditor::replaceUtf8Text(const QByteArray& bytes)
{
    if (d->sci->isReadOnly())
        return;
    const int firstVisible = d->sci->firstVisibleLine();
    int line = 0;
    int index = 0;
    d->sci->getCursorPosition(&line, &index);
    d->sci->beginUndoAction();
    d->sci->SendScintilla(Base::SCI_TARGETWHOLEDOCUMENT);
    d->sci->SendScintilla(Base::SCI_REPLACETARGET, static_cast<unsigned long>(bytes.size()), bytes.constData());
    d->sci->endUndoAction();
    d->sci->setCursorPosition(std::min(line, std::max(0, d->sci->lines() - 1)), 0);
    d->sci->setFirstVisibleLine(firstVisible);
    checkCursorLine();
}

void NcEditor::undo()
{
    d->sci->undo();
    checkCursorLine();
}

void NcEditor::redo()
{
    d->sci->redo();
    checkCursorLine();
}

void NcEditor::setReadOnly(bool readOnly) { d->sci->setReadOnly(readOnly); }

bool NcEditor::isReadOnly() const { return d->sci->isReadOnly(); }

bool NcEditor::isModified() const { return d->sci->isModified(); }

void NcEditor::markSaved() { d->sci->SendScintilla(Base::SCI_SETSAVEPOINT); }

void NcEditor::setDialect(nc::Dialect dialect) { d->lexer->setDialect(dialect); }

nc::Dialect NcEditor::dialect() const { return d->lexer->dialect(); }

void NcEditor::setClFormat(std::optional<toolpath::ClFormat> format) { d->lexer->setClFormat(format); }

std::optional<toolpath::ClFormat> NcEditor::clFormat() const { return d->lexer->clFormat(); }

void NcEditor::setProgramPath(const QString& path) { d->programPath = path; }

QString NcEditor::programPath() const { return d->programPath; }

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

int NcEditor::firstVisibleLine() const { return d->sci->firstVisibleLine() + 1; }

void NcEditor::checkCursorLine()
{
    const int line = currentLine();
    if (line != d->lastLine) {
        d->lastLine = line;
        emit cursorLineChanged(line);
    }
}

void NcEditor::styleThrough(int line) const
{
    const long lineEnd =
        d->sci->SendScintilla(Base::SCI_GETLINEENDPOSITION, static_cast<unsigned long>(std::max(0, line - 1)));
    // For a container lexer this asks the lexer to style up to the line end (if not yet done).
    const long styledTo = d->sci->SendScintilla(Base::SCI_GETENDSTYLED);
    if (styledTo <= lineEnd)
        d->sci->SendScintilla(Base::SCI_COLOURISE, static_cast<unsigned long>(styledTo), lineEnd + 1);
}

int NcEditor::styleAt(int line, int column) const
{
    if (line < 1 || line > lineCount() || column < 1)
        return -1;
    const QString lineText = d->sci->text(line - 1).remove(QLatin1Char('\n')).remove(QLatin1Char('\r'));
    if (column > lineText.size())
        return -1;
    const long position = d->sci->positionFromLineIndex(line - 1, column - 1);
    styleThrough(line);
    return static_cast<int>(d->sci->SendScintilla(Base::SCI_GETSTYLEAT, static_cast<unsigned long>(position)));
}

bool NcEditor::isStyledThrough(int line) const
{
    const long lineEnd =
        d->sci->SendScintilla(Base::SCI_GETLINEENDPOSITION, static_cast<unsigned long>(std::max(0, line - 1)));
    return d->sci->SendScintilla(Base::SCI_GETENDSTYLED) >= lineEnd;
}

int NcEditor::foldDepth(int line) const
{
    if (line < 1 || line > lineCount())
        return -1;
    styleThrough(line);
    const long level = d->sci->SendScintilla(Base::SCI_GETFOLDLEVEL, static_cast<unsigned long>(line - 1));
    return static_cast<int>((level & Base::SC_FOLDLEVELNUMBERMASK) - Base::SC_FOLDLEVELBASE);
}

bool NcEditor::isFoldHeader(int line) const
{
    if (line < 1 || line > lineCount())
        return false;
    styleThrough(line);
    const long level = d->sci->SendScintilla(Base::SCI_GETFOLDLEVEL, static_cast<unsigned long>(line - 1));
    return (level & Base::SC_FOLDLEVELHEADERFLAG) != 0;
}

void NcEditor::setDiagnostics(const QList<NcEditorDiagnostic>& diagnostics)
{
    clearDiagnostics();
    // Per line: the worst severity and all messages, in the order given.
    std::map<int, std::pair<nc::Severity, QStringList>> byLine;
    const int lines = lineCount();
    for (const NcEditorDiagnostic& diag : diagnostics) {
        const int line = std::clamp(diag.line, 1, std::max(1, lines));
        auto& entry = byLine.try_emplace(line, diag.severity, QStringList()).first->second;
        entry.first = std::max(entry.first, diag.severity);
        const QString where = diag.column > 0 ? tr("column %1: ").arg(diag.column) : QString();
        entry.second << QStringLiteral("%1%2: %3")
                            .arg(where, QString::fromLatin1(nc::severityName(diag.severity)), diag.message);
        if (diag.column > 0) {
            // Squiggle under the word at the column (to the next blank).
            const QString text = d->sci->text(line - 1);
            int end = std::min(static_cast<int>(text.size()), diag.column - 1);
            while (end < text.size() && !text.at(end).isSpace())
                ++end;
            if (end > diag.column - 1)
                d->sci->fillIndicatorRange(line - 1, diag.column - 1, line - 1, end,
                                           kFirstIndicator + severityIndex(diag.severity));
        }
    }
    for (const auto& [line, entry] : byLine) {
        d->sci->markerAdd(line - 1, kFirstMarker + severityIndex(entry.first));
        d->sci->annotate(line - 1, entry.second.join(QLatin1Char('\n')),
                         d->annotationStyles[static_cast<std::size_t>(severityIndex(entry.first))]);
    }
}

void NcEditor::clearDiagnostics()
{
    for (int k = 0; k < 3; ++k) {
        d->sci->markerDeleteAll(kFirstMarker + k);
        d->sci->clearIndicatorRange(0, 0, std::max(0, lineCount() - 1), d->sci->lineLength(lineCount() - 1),
                                    kFirstIndicator + k);
    }
    d->sci->clearAnnotations();
}

std::optional<nc::Severity> NcEditor::diagnosticSeverityAt(int line) const
{
    if (line < 1 || line > lineCount())
        return std::nullopt;
    const unsigned mask = d->sci->markersAtLine(line - 1);
    for (nc::Severity s : {nc::Severity::Error, nc::Severity::Warning, nc::Severity::Note})
        if ((mask & (1u << (kFirstMarker + severityIndex(s)))) != 0)
            return s;
    return std::nullopt;
}

QString NcEditor::annotationAt(int line) const
{
    if (line < 1 || line > lineCount())
        return {};
    return d->sci->annotation(line - 1);
}

QList<NcEditorDiagnostic> NcEditor::diagnosticsFor(const std::vector<nc::Diagnostic>& diagnostics,
                                                   const std::string& file)
{
    QList<NcEditorDiagnostic> out;
    for (const nc::Diagnostic& diag : diagnostics)
        if (diag.file == file || diag.file.empty())
            out.append({std::max(1, diag.line), diag.column, diag.severity, QString::fromStdString(diag.message)});
    return out;
}

bool NcEditor::findText(const QString& text, bool forward, bool caseSensitive, bool wholeWord)
{
    if (text.isEmpty())
        return false;
    int line = 0;
    int index = 0;
    if (!forward && d->sci->hasSelectedText()) {
        // Search backwards from the selection's start, not from its end.
        int lineTo = 0;
        int indexTo = 0;
        d->sci->getSelection(&line, &index, &lineTo, &indexTo);
    } else {
        d->sci->getCursorPosition(&line, &index);
    }
    const bool found = d->sci->findFirst(text, false, caseSensitive, wholeWord, true, forward, line, index, true);
    checkCursorLine();
    return found;
}

void NcEditor::showFindBar() { d->findBar->activate(d->sci->selectedText()); }

}  // namespace camwb::gui
