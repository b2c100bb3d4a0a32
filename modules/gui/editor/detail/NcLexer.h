// Syntax highlighting and folding of NC programs for the NC editor, one lexer for the three
// dialects. Private to gui/editor (it includes QScintilla). Styles only the ranges Scintilla asks
// for, with one SETSTYLINGEX call per range, so large programs stay fast.
#pragma once

#include "gui/editor/NcStyles.h"
#include "nc/Dialect.h"

#include <Qsci/qscilexercustom.h>

namespace camwb::gui {

class NcLexer : public QsciLexerCustom {
public:
    explicit NcLexer(QObject* parent = nullptr);

    // Restyles the whole text (lazily: Scintilla asks again for what it shows).
    void setDialect(nc::Dialect dialect);
    nc::Dialect dialect() const { return m_dialect; }

    const char* language() const override;
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    QColor defaultPaper(int style) const override;
    void styleText(int start, int end) override;

private:
    nc::Dialect m_dialect = nc::Dialect::Sinumerik;
    QFont m_font;
    std::vector<char> m_styles;  // reused between calls
};

}  // namespace camwb::gui
