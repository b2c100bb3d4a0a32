// The NC editor's find bar (Ctrl+F): a line edit with previous/next, match case and whole word,
// under the text. Enter finds the next match, Shift+Enter the previous one, Escape closes.
#pragma once

#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;

namespace camwb::gui {

class NcEditor;

class NcFindBar : public QWidget {
    Q_OBJECT

public:
    explicit NcFindBar(NcEditor* editor);

    void activate(const QString& initialText);  // shows, fills, focuses
    bool find(bool forward);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    NcEditor* m_editor;
    QLineEdit* m_text;
    QCheckBox* m_matchCase;
    QCheckBox* m_wholeWord;
    QLabel* m_status;
};

}  // namespace camwb::gui
