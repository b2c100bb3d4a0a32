#include "gui/editor/detail/NcFindBar.h"

#include "gui/editor/NcEditor.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QToolButton>

namespace camwb::gui {

NcFindBar::NcFindBar(NcEditor* editor) : QWidget(editor), m_editor(editor)
{
    setObjectName(QStringLiteral("ncFindBar"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addWidget(new QLabel(tr("Find:"), this));
    m_text = new QLineEdit(this);
    m_text->setObjectName(QStringLiteral("ncFindText"));
    m_text->setClearButtonEnabled(true);
    m_text->installEventFilter(this);
    layout->addWidget(m_text, 1);
    auto* previous = new QToolButton(this);
    previous->setText(tr("Previous"));
    previous->setArrowType(Qt::UpArrow);
    previous->setToolTip(tr("Find the previous match (Shift+Enter)"));
    auto* next = new QToolButton(this);
    next->setText(tr("Next"));
    next->setArrowType(Qt::DownArrow);
    next->setToolTip(tr("Find the next match (Enter)"));
    layout->addWidget(previous);
    layout->addWidget(next);
    m_matchCase = new QCheckBox(tr("Match case"), this);
    m_wholeWord = new QCheckBox(tr("Whole words"), this);
    layout->addWidget(m_matchCase);
    layout->addWidget(m_wholeWord);
    m_status = new QLabel(this);
    m_status->setMinimumWidth(90);
    layout->addWidget(m_status);
    auto* close = new QToolButton(this);
    close->setText(QStringLiteral("✕"));
    close->setToolTip(tr("Close the find bar (Escape)"));
    layout->addWidget(close);

    connect(previous, &QToolButton::clicked, this, [this] { find(false); });
    connect(next, &QToolButton::clicked, this, [this] { find(true); });
    connect(m_text, &QLineEdit::returnPressed, this, [this] { find(true); });
    connect(m_text, &QLineEdit::textChanged, this, [this] { m_status->clear(); });
    connect(close, &QToolButton::clicked, this, [this] {
        hide();
        m_editor->setFocus();
    });
    hide();
}

void NcFindBar::activate(const QString& initialText)
{
    if (!initialText.isEmpty() && !initialText.contains(QLatin1Char('\n')))
        m_text->setText(initialText);
    show();
    m_text->setFocus();
    m_text->selectAll();
}

bool NcFindBar::find(bool forward)
{
    if (m_text->text().isEmpty())
        return false;
    const bool found = m_editor->findText(m_text->text(), forward, m_matchCase->isChecked(), m_wholeWord->isChecked());
    m_status->setText(found ? QString() : tr("Not found"));
    return found;
}

bool NcFindBar::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_text && event->type() == QEvent::KeyPress) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Escape) {
            hide();
            m_editor->setFocus();
            return true;
        }
        if ((key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) && (key->modifiers() & Qt::ShiftModifier)) {
            find(false);
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

}  // namespace camwb::gui
