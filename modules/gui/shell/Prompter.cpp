#include "gui/shell/Prompter.h"

#include <QFileDialog>
#include <QMessageBox>
#include <QPushButton>

namespace camwb::gui {

DialogPrompter::DialogPrompter(QWidget* parent) : m_parent(parent) {}

Prompter::Answer DialogPrompter::ask(const Question& question)
{
    QMessageBox box(QMessageBox::Question, question.title, question.text, QMessageBox::NoButton, m_parent);
    QAbstractButton* accept = question.acceptText.isEmpty()
                                  ? box.addButton(QMessageBox::Save)
                                  : box.addButton(question.acceptText, QMessageBox::AcceptRole);
    QAbstractButton* discard = question.discardText.isEmpty()
                                   ? box.addButton(QMessageBox::Discard)
                                   : box.addButton(question.discardText, QMessageBox::DestructiveRole);
    QAbstractButton* cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(qobject_cast<QPushButton*>(accept));
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() == accept)
        return Answer::Accept;
    if (box.clickedButton() == discard)
        return Answer::Discard;
    return Answer::Cancel;
}

QString DialogPrompter::openFileName(const QString& title, const QString& filter)
{
    return QFileDialog::getOpenFileName(m_parent, title, {}, filter);
}

QString DialogPrompter::saveFileName(const QString& title, const QString& suggested, const QString& filter)
{
    return QFileDialog::getSaveFileName(m_parent, title, suggested, filter);
}

void DialogPrompter::showError(const QString& title, const QString& text)
{
    if (m_error && m_error->isVisible()) {
        // Errors that follow one another (a failed post and its consequences) share one box.
        m_error->setText(m_error->text() + QStringLiteral("\n\n") + text);
        return;
    }
    m_error = new QMessageBox(QMessageBox::Critical, title, text, QMessageBox::Close, m_parent);
    m_error->setAttribute(Qt::WA_DeleteOnClose);
    m_error->setObjectName(QStringLiteral("errorMessage"));
    m_error->setWindowModality(Qt::NonModal);  // the user reads it and goes on working
    m_error->show();
}

}  // namespace camwb::gui
