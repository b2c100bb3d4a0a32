#include "gui/shell/Prompter.h"

#include <QFileDialog>
#include <QMessageBox>

namespace camwb::gui {

SaveChoice DialogPrompter::askSaveChanges(QWidget* parent, const QString& title, const QString& text)
{
    const auto answer = QMessageBox::warning(
        parent, title, text, QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return SaveChoice::Save;
    if (answer == QMessageBox::Discard)
        return SaveChoice::Discard;
    return SaveChoice::Cancel;  // Escape and closing the box too
}

bool DialogPrompter::confirm(QWidget* parent, const QString& title, const QString& text)
{
    return QMessageBox::question(parent, title, text, QMessageBox::Ok | QMessageBox::Cancel, QMessageBox::Cancel) ==
           QMessageBox::Ok;
}

QString DialogPrompter::openFileName(QWidget* parent, const QString& caption, const QString& suggested,
                                     const QString& filter)
{
    return QFileDialog::getOpenFileName(parent, caption, suggested, filter);
}

QString DialogPrompter::saveFileName(QWidget* parent, const QString& caption, const QString& suggested,
                                     const QString& filter)
{
    return QFileDialog::getSaveFileName(parent, caption, suggested, filter);
}

}  // namespace camwb::gui
