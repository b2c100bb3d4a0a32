// The modal state of the NC block under the editor's cursor, as the inspector derives it from the
// interpreted records: tool, feed, spindle, coolant, work offset, compensation, positions before
// and after, the move. Only shows what it is given; NcTrace computes it.
#pragma once

#include <QWidget>

class QLabel;
class QFormLayout;

namespace camwb::document {
struct LineState;
struct NcTrace;
}  // namespace camwb::document

namespace camwb::gui {

class ModalStatePanel : public QWidget {
    Q_OBJECT
public:
    explicit ModalStatePanel(QWidget* parent = nullptr);

    // `where` names a record from a called program ("SUB.SPF:12"), empty for the main program.
    void showState(const document::LineState& state, const document::NcTrace& trace);
    void showMessage(const QString& text);  // no trace yet, tracing, ...

    // The value shown for a row ("plane", "units", "distance", "compensation", "tool", "feed",
    // "spindle", "coolant", "workOffset", "before", "after", "move", "block", "toolAxis",
    // "rotaryAxes"), for tests.
    QString value(const QString& row) const;

private:
    QLabel* addRow(const QString& key, const QString& label);

    QFormLayout* m_form;
    QLabel* m_message;
};

}  // namespace camwb::gui
