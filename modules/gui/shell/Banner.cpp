#include "gui/shell/Banner.h"

#include <QVBoxLayout>

namespace camwb::gui {

Banner::Banner(const QString& objectName, QWidget* parent) : QLabel(parent)
{
    setObjectName(objectName);
    setWordWrap(true);
    setTextInteractionFlags(Qt::TextSelectableByMouse);
    setContentsMargins(8, 5, 8, 5);
    // Red on pale red: read as an error in light and dark themes alike.
    setStyleSheet(QStringLiteral("QLabel { background: #fde2e1; color: #8b0000; border-bottom: 2px solid #c62828; }"));
    hide();
}

void Banner::setMessage(const QString& text, const QString& details)
{
    setText(text);
    setToolTip(details.isEmpty() ? text : details);
    setVisible(!text.isEmpty());
}

QWidget* Banner::above(Banner* banner, QWidget* content, QWidget* parent)
{
    auto* holder = new QWidget(parent);
    auto* layout = new QVBoxLayout(holder);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(banner);
    layout->addWidget(content, 1);
    return holder;
}

}  // namespace camwb::gui
