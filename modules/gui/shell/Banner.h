// A strip above a view that says what is wrong with what the view shows ("out of date: the
// post failed ..."), so a stale program never looks current. Hidden while there is nothing to say.
#pragma once

#include <QLabel>

namespace camwb::gui {

class Banner : public QLabel {
    Q_OBJECT
public:
    explicit Banner(const QString& objectName, QWidget* parent = nullptr);
    // Empty: hidden. `details` (default: the text) is the tooltip, for what is too long to show.
    void setMessage(const QString& text, const QString& details = {});

    // One widget holding `banner` above `content` (for a dock or the central area).
    static QWidget* above(Banner* banner, QWidget* content, QWidget* parent);
};

}  // namespace camwb::gui
