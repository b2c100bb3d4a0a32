#include "gui/editor/CompareDialog.h"

#include "gui/editor/detail/NcLexer.h"

#include <Qsci/qsciscintilla.h>

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollBar>
#include <QSplitter>
#include <QVBoxLayout>

#include <algorithm>
#include <array>

namespace camwb::gui {

namespace {

using Base = QsciScintillaBase;

// Background markers per row kind, the arrow of the current difference, the changed characters.
constexpr int kChangedMarker = 1;
constexpr int kRemovedMarker = 2;
constexpr int kAddedMarker = 3;
constexpr int kGapMarker = 4;
constexpr int kCurrentMarker = 5;
constexpr int kCharIndicator = 8;

QStringList splitLines(const QString& text)
{
    QStringList lines = text.split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.back().isEmpty())
        lines.removeLast();  // a final line end opens no line
    for (QString& line : lines)
        if (line.endsWith(QLatin1Char('\r')))
            line.chop(1);
    return lines;
}

}  // namespace

struct CompareDialog::Private {
    nc::Dialect dialect = nc::Dialect::Iso;
    std::array<QString, 2> texts;
    std::array<bool, 2> loaded{};  // a side without a program is not compared (not an empty file)
    std::array<QsciScintilla*, 2> views{};
    std::array<NcLexer*, 2> lexers{};
    std::array<QLabel*, 2> titles{};
    QCheckBox* ignoreNumbers = nullptr;
    QCheckBox* ignoreBlanks = nullptr;
    QLabel* summary = nullptr;
    QPushButton* previous = nullptr;
    QPushButton* next = nullptr;
    nc::LineDiff diff;
    int current = -1;
    bool syncing = false;
    bool dirty = true;  // texts or options changed since the last diff
};

CompareDialog::CompareDialog(nc::Dialect dialect, QWidget* parent) : QDialog(parent), d(std::make_unique<Private>())
{
    d->dialect = dialect;
    setObjectName(QStringLiteral("compareDialog"));
    setWindowTitle(tr("Compare NC Programs"));
    resize(1200, 760);
    auto* layout = new QVBoxLayout(this);

    auto* splitter = new QSplitter(Qt::Horizontal, this);
    for (int side = 0; side < 2; ++side) {
        auto* pane = new QWidget(splitter);
        auto* paneLayout = new QVBoxLayout(pane);
        paneLayout->setContentsMargins(0, 0, 0, 0);
        auto* header = new QHBoxLayout;
        auto* open = new QPushButton(side == 0 ? tr("Open &Left…") : tr("Open &Right…"), pane);
        connect(open, &QPushButton::clicked, this, [this, side] { chooseFile(side == 0); });
        d->titles[side] = new QLabel(pane);
        d->titles[side]->setTextInteractionFlags(Qt::TextSelectableByMouse);
        header->addWidget(open);
        header->addWidget(d->titles[side], 1);
        paneLayout->addLayout(header);

        auto* view = new QsciScintilla(pane);
        view->setObjectName(side == 0 ? QStringLiteral("compareLeft") : QStringLiteral("compareRight"));
        view->setUtf8(true);
        auto* lexer = new NcLexer(view);
        lexer->setDialect(dialect);
        view->setLexer(lexer);
        d->lexers[side] = lexer;
        view->setReadOnly(true);
        view->setWrapMode(QsciScintilla::WrapNone);
        view->SendScintilla(Base::SCI_SETSCROLLWIDTH, 1UL);
        view->SendScintilla(Base::SCI_SETSCROLLWIDTHTRACKING, 1UL);
        view->setCaretLineVisible(true);
        view->setCaretLineBackgroundColor(QColor(230, 236, 255));
        view->setMarginsFont(lexer->defaultFont(0));
        view->setMarginsBackgroundColor(QColor(240, 240, 240));
        view->setMarginsForegroundColor(QColor(120, 120, 120));
        // Margin 0: the program's own line numbers (gaps have none), right-aligned text.
        view->SendScintilla(Base::SCI_SETMARGINTYPEN, 0UL, static_cast<long>(Base::SC_MARGIN_RTEXT));
        view->setMarginWidth(0, QStringLiteral("999999"));
        view->setMarginType(1, QsciScintilla::SymbolMargin);
        view->setMarginWidth(1, 14);
        view->setMarginWidth(2, 0);
        view->setMarginMarkerMask(0, 0);
        view->setMarginMarkerMask(1, 1 << kCurrentMarker);
        const std::pair<int, QColor> backgrounds[] = {{kChangedMarker, QColor(255, 240, 180)},
                                                      {kRemovedMarker, QColor(255, 212, 212)},
                                                      {kAddedMarker, QColor(208, 244, 208)},
                                                      {kGapMarker, QColor(228, 228, 228)}};
        for (const auto& [marker, color] : backgrounds) {
            view->markerDefine(QsciScintilla::Background, marker);
            view->setMarkerBackgroundColor(color, marker);
        }
        view->markerDefine(QsciScintilla::RightArrow, kCurrentMarker);
        view->setMarkerBackgroundColor(QColor(30, 90, 200), kCurrentMarker);
        view->indicatorDefine(QsciScintilla::StraightBoxIndicator, kCharIndicator);
        view->setIndicatorForegroundColor(QColor(230, 120, 0, 110), kCharIndicator);
        view->SendScintilla(Base::SCI_INDICSETUNDER, static_cast<unsigned long>(kCharIndicator), 1L);
        paneLayout->addWidget(view, 1);
        d->views[side] = view;
    }
    layout->addWidget(splitter, 1);

    // Both sides have the same rows, so the same scroll positions line up.
    for (int side = 0; side < 2; ++side) {
        QsciScintilla* self = d->views[side];
        QsciScintilla* other = d->views[1 - side];
        auto sync = [this](QScrollBar* target) {
            return [this, target](int value) {
                if (d->syncing)
                    return;
                d->syncing = true;
                target->setValue(value);
                d->syncing = false;
            };
        };
        connect(self->verticalScrollBar(), &QScrollBar::valueChanged, this, sync(other->verticalScrollBar()));
        connect(self->horizontalScrollBar(), &QScrollBar::valueChanged, this, sync(other->horizontalScrollBar()));
    }

    auto* bottom = new QHBoxLayout;
    d->ignoreNumbers = new QCheckBox(tr("Ignore block &numbers"), this);
    d->ignoreNumbers->setObjectName(QStringLiteral("compareIgnoreNumbers"));
    d->ignoreBlanks = new QCheckBox(tr("Ignore &blanks"), this);
    d->ignoreBlanks->setObjectName(QStringLiteral("compareIgnoreBlanks"));
    connect(d->ignoreNumbers, &QCheckBox::toggled, this, [this] { invalidate(); });
    connect(d->ignoreBlanks, &QCheckBox::toggled, this, [this] { invalidate(); });
    d->summary = new QLabel(this);
    d->summary->setObjectName(QStringLiteral("compareSummary"));
    d->previous = new QPushButton(tr("&Previous Difference"), this);
    d->previous->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F7));
    d->next = new QPushButton(tr("Ne&xt Difference"), this);
    d->next->setShortcut(QKeySequence(Qt::Key_F7));
    connect(d->previous, &QPushButton::clicked, this, &CompareDialog::previousDifference);
    connect(d->next, &QPushButton::clicked, this, &CompareDialog::nextDifference);
    auto* close = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    bottom->addWidget(d->ignoreNumbers);
    bottom->addWidget(d->ignoreBlanks);
    bottom->addStretch(1);
    bottom->addWidget(d->summary);
    bottom->addStretch(1);
    bottom->addWidget(d->previous);
    bottom->addWidget(d->next);
    bottom->addWidget(close);
    layout->addLayout(bottom);
}

CompareDialog::~CompareDialog() = default;

void CompareDialog::setLeft(const QString& text, const QString& title)
{
    d->texts[0] = text;
    d->loaded[0] = true;
    d->titles[0]->setText(title);
    invalidate();
}

void CompareDialog::setRight(const QString& text, const QString& title)
{
    d->texts[1] = text;
    d->loaded[1] = true;
    d->titles[1]->setText(title);
    invalidate();
}

bool CompareDialog::loadLeft(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        d->titles[0]->setText(tr("Cannot read %1: %2").arg(path, file.errorString()));
        return false;
    }
    setLeft(QString::fromUtf8(file.readAll()), QFileInfo(path).fileName());
    d->titles[0]->setToolTip(path);
    return true;
}

bool CompareDialog::loadRight(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        d->titles[1]->setText(tr("Cannot read %1: %2").arg(path, file.errorString()));
        return false;
    }
    setRight(QString::fromUtf8(file.readAll()), QFileInfo(path).fileName());
    d->titles[1]->setToolTip(path);
    return true;
}

void CompareDialog::setLanguage(nc::Dialect dialect, std::optional<toolpath::ClFormat> clFormat)
{
    for (NcLexer* lexer : d->lexers) {
        lexer->setDialect(dialect);
        lexer->setClFormat(clFormat);
    }
    if (d->dialect == dialect)
        return;
    d->dialect = dialect;  // the block numbers ignored are the dialect's own
    invalidate();
}

int CompareDialog::styleAt(bool left, int row, int column) const
{
    QsciScintilla* view = d->views[left ? 0 : 1];
    if (row < 1 || row > view->lines() || column < 1)
        return -1;
    const long position = view->positionFromLineIndex(row - 1, column - 1);
    const long end = view->SendScintilla(Base::SCI_GETLINEENDPOSITION, static_cast<unsigned long>(row - 1));
    if (position >= end)
        return -1;
    const long styledTo = view->SendScintilla(Base::SCI_GETENDSTYLED);  // style up to the row's end first
    if (styledTo <= end)
        view->SendScintilla(Base::SCI_COLOURISE, static_cast<unsigned long>(styledTo), end + 1);
    return static_cast<int>(view->SendScintilla(Base::SCI_GETSTYLEAT, static_cast<unsigned long>(position)));
}

void CompareDialog::setIgnoreBlockNumbers(bool ignore) { d->ignoreNumbers->setChecked(ignore); }

void CompareDialog::setIgnoreWhitespace(bool ignore) { d->ignoreBlanks->setChecked(ignore); }

void CompareDialog::invalidate()
{
    // Setting both sides (or a side and an option) diffs once, when the result is needed.
    d->dirty = true;
    if (isVisible())
        QMetaObject::invokeMethod(
            this, [this] { ensureComputed(); }, Qt::QueuedConnection);
}

void CompareDialog::ensureComputed() const
{
    if (d->dirty)
        const_cast<CompareDialog*>(this)->recompute();
}

void CompareDialog::showEvent(QShowEvent* event)
{
    ensureComputed();
    QDialog::showEvent(event);
}

const nc::LineDiff& CompareDialog::diff() const
{
    ensureComputed();
    return d->diff;
}

int CompareDialog::differenceCount() const
{
    ensureComputed();
    return static_cast<int>(d->diff.hunks.size());
}

QString CompareDialog::summaryText() const
{
    ensureComputed();
    return d->summary->text();
}

int CompareDialog::currentDifference() const
{
    ensureComputed();
    return d->current;
}

void CompareDialog::nextDifference()
{
    ensureComputed();
    if (differenceCount() > 0)
        showDifference(std::min(d->current + 1, differenceCount() - 1));
}

void CompareDialog::previousDifference()
{
    ensureComputed();
    if (differenceCount() > 0)
        showDifference(std::max(d->current - 1, 0));
}

int CompareDialog::firstVisibleRow(bool left) const
{
    ensureComputed();
    return d->views[left ? 0 : 1]->firstVisibleLine();
}

void CompareDialog::chooseFile(bool left)
{
    const QString path = QFileDialog::getOpenFileName(
        this, left ? tr("Open Left NC Program") : tr("Open Right NC Program"), QString(),
        tr("NC programs (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    if (left)
        loadLeft(path);
    else
        loadRight(path);
}

// Until both sides hold a program, each side shows its own text and nothing is compared: a
// program against nothing is no difference to step through.
void CompareDialog::showUncompared()
{
    d->diff = {};
    d->current = -1;
    for (int side = 0; side < 2; ++side) {
        QsciScintilla* view = d->views[side];
        view->setReadOnly(false);
        view->setText(d->loaded[side] ? d->texts[side] : QString());
        view->setReadOnly(true);
        view->markerDeleteAll();
        view->SendScintilla(Base::SCI_MARGINTEXTCLEARALL);
    }
    d->previous->setEnabled(false);
    d->next->setEnabled(false);
    if (!d->loaded[0] && !d->loaded[1])
        d->summary->setText(tr("Open two programs to compare"));
    else if (!d->loaded[1])
        d->summary->setText(tr("Open a program on the right to compare"));
    else
        d->summary->setText(tr("Open a program on the left to compare"));
}

void CompareDialog::recompute()
{
    d->dirty = false;
    if (!d->loaded[0] || !d->loaded[1]) {
        showUncompared();
        return;
    }
    nc::DiffOptions options;
    options.dialect = d->dialect;
    options.ignoreBlockNumbers = d->ignoreNumbers->isChecked();
    options.ignoreWhitespace = d->ignoreBlanks->isChecked();
    const QByteArray left = d->texts[0].toUtf8();
    const QByteArray right = d->texts[1].toUtf8();
    d->diff = nc::diffLines(std::string_view(left.constData(), std::size_t(left.size())),
                            std::string_view(right.constData(), std::size_t(right.size())), options);
    d->current = -1;

    const std::array<QStringList, 2> lines{splitLines(d->texts[0]), splitLines(d->texts[1])};
    for (int side = 0; side < 2; ++side) {
        QsciScintilla* view = d->views[side];
        QStringList shown;
        shown.reserve(static_cast<qsizetype>(d->diff.rows.size()));
        for (const nc::DiffRow& row : d->diff.rows) {
            const int line = side == 0 ? row.leftLine : row.rightLine;
            shown << (line > 0 ? lines[side].value(line - 1) : QString());
        }
        view->setReadOnly(false);
        view->setText(shown.join(QLatin1Char('\n')));
        view->setReadOnly(true);
        view->markerDeleteAll();
        view->SendScintilla(Base::SCI_MARGINTEXTCLEARALL);
        const int digits = static_cast<int>(QString::number(std::max(1, int(lines[side].size()))).size());
        view->setMarginWidth(0, QString(digits + 1, QLatin1Char('9')));
        for (std::size_t r = 0; r < d->diff.rows.size(); ++r) {
            const nc::DiffRow& row = d->diff.rows[r];
            const int line = side == 0 ? row.leftLine : row.rightLine;
            const int displayLine = static_cast<int>(r);
            if (line > 0) {
                const QByteArray number = QByteArray::number(line);
                view->SendScintilla(Base::SCI_MARGINSETTEXT, static_cast<unsigned long>(displayLine),
                                    number.constData());
            }
            int marker = -1;
            if (line == 0)
                marker = kGapMarker;
            else if (row.kind == nc::DiffKind::Changed)
                marker = kChangedMarker;
            else if (row.kind == nc::DiffKind::Removed)
                marker = kRemovedMarker;
            else if (row.kind == nc::DiffKind::Added)
                marker = kAddedMarker;
            if (marker >= 0)
                view->markerAdd(displayLine, marker);
            if (row.kind == nc::DiffKind::Changed) {
                // Underlay the characters between the common prefix and suffix of the two lines.
                const QString a = lines[0].value(row.leftLine - 1);
                const QString b = lines[1].value(row.rightLine - 1);
                int prefix = 0;
                while (prefix < a.size() && prefix < b.size() && a[prefix] == b[prefix])
                    ++prefix;
                int suffix = 0;
                while (suffix < a.size() - prefix && suffix < b.size() - prefix &&
                       a[a.size() - 1 - suffix] == b[b.size() - 1 - suffix])
                    ++suffix;
                const QString& mine = side == 0 ? a : b;
                const int end = static_cast<int>(mine.size()) - suffix;
                if (end > prefix)
                    view->fillIndicatorRange(displayLine, prefix, displayLine, end, kCharIndicator);
            }
        }
    }
    const int count = differenceCount();
    d->previous->setEnabled(count > 0);
    d->next->setEnabled(count > 0);
    if (count == 0)
        d->summary->setText(tr("The programs are identical"));
    else
        d->summary->setText(tr("%n difference(s)", nullptr, count));
}

void CompareDialog::showDifference(int index)
{
    if (index < 0 || index >= differenceCount())
        return;
    d->current = index;
    const nc::DiffHunk& hunk = d->diff.hunks[static_cast<std::size_t>(index)];
    for (QsciScintilla* view : d->views) {
        view->markerDeleteAll(kCurrentMarker);
        view->markerAdd(hunk.firstRow, kCurrentMarker);
        view->setCursorPosition(hunk.firstRow, 0);
    }
    d->views[0]->setFirstVisibleLine(std::max(0, hunk.firstRow - 3));  // the other side follows
    d->views[1]->setFirstVisibleLine(std::max(0, hunk.firstRow - 3));
    d->summary->setText(tr("Difference %1 of %2").arg(index + 1).arg(differenceCount()));
}

}  // namespace camwb::gui
