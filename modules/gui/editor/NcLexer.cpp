#include "gui/editor/detail/NcLexer.h"

#include "gui/editor/detail/DialectLexers.h"

#include <Qsci/qsciscintilla.h>

#include <QCoreApplication>
#include <QFontDatabase>

namespace camwb::gui {

namespace {

using lexchar::upper;

bool foldRelevant(NcStyle style)
{
    return style == NcStyle::Keyword || style == NcStyle::MWord || style == NcStyle::Number || style == NcStyle::String;
}

}  // namespace

NcLexer::NcLexer(QObject* parent) : QsciLexerCustom(parent), m_font(QFontDatabase::systemFont(QFontDatabase::FixedFont))
{
    setDefaultFont(m_font);
    setDefaultPaper(Qt::white);
    setDefaultColor(Qt::black);
}

void NcLexer::setDialect(nc::Dialect dialect)
{
    if (dialect == m_dialect)
        return;
    m_dialect = dialect;
    restyle();
}

void NcLexer::setClFormat(std::optional<toolpath::ClFormat> format)
{
    if (format == m_clFormat)
        return;
    m_clFormat = format;
    restyle();
}

void NcLexer::restyle()
{
    if (QsciScintilla* sci = editor()) {
        // Styles, line states and fold levels of the old dialect are stale. Moving the styled
        // watermark to the top restyles lazily, only what is shown (a full recolour would lex a
        // million-line program at once).
        sci->SendScintilla(QsciScintillaBase::SCI_STARTSTYLING, 0UL, 0L);
        sci->viewport()->update();
    }
}

const char* NcLexer::language() const
{
    if (m_clFormat)
        return toolpath::clFormatName(*m_clFormat);
    switch (m_dialect) {
    case nc::Dialect::Sinumerik:
        return "Sinumerik";
    case nc::Dialect::Heidenhain:
        return "Heidenhain";
    case nc::Dialect::Iso:
        break;
    }
    return "ISO";
}

QString NcLexer::description(int style) const
{
    // QScintilla enumerates styles until the description is empty.
    switch (static_cast<NcStyle>(style)) {
    case NcStyle::Default:
        return QCoreApplication::translate("NcLexer", "Default");
    case NcStyle::Comment:
        return QCoreApplication::translate("NcLexer", "Comment");
    case NcStyle::BlockNumber:
        return QCoreApplication::translate("NcLexer", "Block number");
    case NcStyle::GWord:
        return QCoreApplication::translate("NcLexer", "G word");
    case NcStyle::MWord:
        return QCoreApplication::translate("NcLexer", "M word");
    case NcStyle::AxisWord:
        return QCoreApplication::translate("NcLexer", "Axis word");
    case NcStyle::FeedSpeedTool:
        return QCoreApplication::translate("NcLexer", "Feed, speed, tool");
    case NcStyle::Keyword:
        return QCoreApplication::translate("NcLexer", "Keyword or cycle");
    case NcStyle::Number:
        return QCoreApplication::translate("NcLexer", "Number");
    case NcStyle::String:
        return QCoreApplication::translate("NcLexer", "String");
    case NcStyle::Parameter:
        return QCoreApplication::translate("NcLexer", "Parameter");
    case NcStyle::Count:
        break;
    }
    return {};
}

QColor NcLexer::defaultColor(int style) const
{
    switch (static_cast<NcStyle>(style)) {
    case NcStyle::Comment:
        return QColor(96, 128, 96);
    case NcStyle::BlockNumber:
        return QColor(128, 128, 150);
    case NcStyle::GWord:
        return QColor(0, 70, 200);
    case NcStyle::MWord:
        return QColor(170, 0, 140);
    case NcStyle::AxisWord:
        return QColor(150, 40, 20);
    case NcStyle::FeedSpeedTool:
        return QColor(190, 100, 0);
    case NcStyle::Keyword:
        return QColor(110, 30, 170);
    case NcStyle::Number:
        return QColor(0, 120, 120);
    case NcStyle::String:
        return QColor(130, 90, 0);
    case NcStyle::Parameter:
        return QColor(0, 110, 170);
    default:
        return QColor(20, 20, 20);
    }
}

QFont NcLexer::defaultFont(int style) const
{
    QFont font = m_font;
    switch (static_cast<NcStyle>(style)) {
    case NcStyle::Comment:
        font.setItalic(true);
        break;
    case NcStyle::GWord:
    case NcStyle::Keyword:
        font.setBold(true);
        break;
    default:
        break;
    }
    return font;
}

QColor NcLexer::defaultPaper(int) const { return Qt::white; }

void NcLexer::styleText(int start, int end)
{
    QsciScintilla* sci = editor();
    if (sci == nullptr || end <= start)
        return;
    using Base = QsciScintillaBase;
    // Always restart at a line start and finish at one: block numbers, continuation and fold
    // state are per line.
    const long firstLine = sci->SendScintilla(Base::SCI_LINEFROMPOSITION, static_cast<unsigned long>(start));
    const long lastLine = sci->SendScintilla(Base::SCI_LINEFROMPOSITION, static_cast<unsigned long>(end - 1));
    start = static_cast<int>(sci->SendScintilla(Base::SCI_POSITIONFROMLINE, static_cast<unsigned long>(firstLine)));
    end = static_cast<int>(sci->SendScintilla(Base::SCI_POSITIONFROMLINE, static_cast<unsigned long>(lastLine + 1)));
    if (end < start)  // past the last line
        end = static_cast<int>(sci->SendScintilla(Base::SCI_GETLENGTH));
    const int length = end - start;
    if (length <= 0)
        return;

    FoldState state;
    if (firstLine > 0)
        state = FoldState::unpack(
            static_cast<int>(sci->SendScintilla(Base::SCI_GETLINESTATE, static_cast<unsigned long>(firstLine - 1))));

    // A direct pointer into Scintilla's buffer (moves the gap once), no copy.
    const auto* text = reinterpret_cast<const char*>(
        sci->SendScintilla(Base::SCI_GETRANGEPOINTER, static_cast<unsigned long>(start), static_cast<long>(length)));
    if (text == nullptr)
        return;
    m_styles.resize(static_cast<std::size_t>(length));
    if (m_clFormat)
        lexClFormat(*m_clFormat, text, length, state.continues, m_styles.data());
    else
        lexDialect(m_dialect, text, length, state.continues, m_styles.data());
    sci->SendScintilla(Base::SCI_STARTSTYLING, static_cast<unsigned long>(start), 0L);
    sci->SendScintilla(Base::SCI_SETSTYLINGEX, static_cast<unsigned long>(length), m_styles.data());

    // Fold levels and line states, line by line from the styles just made.
    std::vector<FoldToken> tokens;
    int lineBegin = 0;
    long line = firstLine;
    while (lineBegin < length) {
        int lineEnd = lineBegin;
        while (lineEnd < length && text[lineEnd] != '\n' && text[lineEnd] != '\r')
            ++lineEnd;
        tokens.clear();
        for (int k = lineBegin; k < lineEnd;) {
            const auto style = static_cast<NcStyle>(m_styles[static_cast<std::size_t>(k)]);
            int e = k + 1;
            while (e < lineEnd && m_styles[static_cast<std::size_t>(e)] == m_styles[static_cast<std::size_t>(k)])
                ++e;
            if (foldRelevant(style) && (style != NcStyle::Keyword || text[k] != '%')) {
                FoldToken token{std::string(text + k, text + e), style};
                for (char& c : token.text)
                    c = upper(c);
                tokens.push_back(std::move(token));
            }
            k = e;
        }
        int tail = lineEnd - 1;
        while (tail >= lineBegin && (text[tail] == ' ' || text[tail] == '\t'))
            --tail;
        int level = Base::SC_FOLDLEVELBASE;  // depth 0, no header
        if (m_clFormat) {
            // A CL file does not fold; an APT line ending in '$' (not in a "$$" comment) continues.
            state.continues = *m_clFormat == toolpath::ClFormat::Apt && tail >= lineBegin && text[tail] == '$' &&
                              m_styles[static_cast<std::size_t>(tail)] != static_cast<char>(NcStyle::Comment);
        } else {
            const bool tilde = m_dialect == nc::Dialect::Heidenhain && tail >= lineBegin && text[tail] == '~';
            level = foldLevel(m_dialect, tokens, tilde, state);
        }
        if (sci->SendScintilla(Base::SCI_GETFOLDLEVEL, static_cast<unsigned long>(line)) != level)
            sci->SendScintilla(Base::SCI_SETFOLDLEVEL, static_cast<unsigned long>(line), static_cast<long>(level));
        const int packed = state.pack();
        if (sci->SendScintilla(Base::SCI_GETLINESTATE, static_cast<unsigned long>(line)) != packed)
            sci->SendScintilla(Base::SCI_SETLINESTATE, static_cast<unsigned long>(line), static_cast<long>(packed));
        if (lineEnd < length && text[lineEnd] == '\r')
            ++lineEnd;
        if (lineEnd < length && text[lineEnd] == '\n')
            ++lineEnd;
        lineBegin = lineEnd;
        ++line;
    }
}

}  // namespace camwb::gui
