// Syntax highlighting and folding of NC programs for the NC editor, one lexer for the three
// dialects and the CL files the editor opens (APT, FreeCAD dump, trace; these do not fold).
// Private to gui/editor (it includes QScintilla). Styles only the ranges Scintilla asks for, with
// one SETSTYLINGEX call per range, so large programs stay fast.
#pragma once

#include "gui/editor/NcStyles.h"
#include "nc/Dialect.h"
#include "toolpath/ClFormat.h"

#include <Qsci/qscilexercustom.h>

#include <optional>

namespace camwb::gui {

class NcLexer : public QsciLexerCustom {
public:
    explicit NcLexer(QObject* parent = nullptr);

    // Restyles the whole text (lazily: Scintilla asks again for what it shows).
    void setDialect(nc::Dialect dialect);
    nc::Dialect dialect() const { return m_dialect; }
    // Set: the text is a CL file of this format and is highlighted as one, whatever the dialect.
    void setClFormat(std::optional<toolpath::ClFormat> format);
    std::optional<toolpath::ClFormat> clFormat() const { return m_clFormat; }

    const char* language() const override;
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    QColor defaultPaper(int style) const override;
    void styleText(int start, int end) override;

private:
    void restyle();

    nc::Dialect m_dialect = nc::Dialect::Sinumerik;
    std::optional<toolpath::ClFormat> m_clFormat;
    QFont m_font;
    std::vector<char> m_styles;  // reused between calls
};

}  // namespace camwb::gui
