// A strip above a view that says what is wrong with what the view shows ("out of date: the
// post failed ..."), so a stale program never looks current. Hidden while there is nothing to say.
#pragma once

#include <QLabel>

namespace camwb::gui {

class Banner : public QLabel {
    Q_OBJECT
public:
    explicit Banner(const QString& objectName, QWidget* parent = nullptr);
    void setMessage(const QString& text);  // empty: hidden

    // One widget holding `banner` above `content` (for a dock or the central area).
    static QWidget* above(Banner* banner, QWidget* content, QWidget* parent);
};

}  // namespace camwb::gui
