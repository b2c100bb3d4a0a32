// Syntax highlighting of Sinumerik NC programs for the NC editor. Private to gui/editor (it
// includes QScintilla). Styles only the ranges Scintilla asks for, so large programs stay fast.
#pragma once

#include "gui/editor/NcStyles.h"

#include <Qsci/qscilexercustom.h>

#include <functional>

namespace camwb::gui {

class SinumerikLexer : public QsciLexerCustom {
public:
    explicit SinumerikLexer(QObject* parent = nullptr);

    const char* language() const override;
    QString description(int style) const override;
    QColor defaultColor(int style) const override;
    QFont defaultFont(int style) const override;
    QColor defaultPaper(int style) const override;
    void styleText(int start, int end) override;

    // Splits `length` bytes that start at a line start into styled runs (run length, style).
    // Pure, for tests and for styleText.
    static void lex(const char* text, int length, const std::function<void(int, NcStyle)>& emitRun);

private:
    QFont m_font;
};

}  // namespace camwb::gui
