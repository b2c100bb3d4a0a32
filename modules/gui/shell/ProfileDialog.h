// Parameters of a profile operation: face, depth, heights, direction, tool. Returns the edited
// operation; the caller applies it as one undoable step.
#pragma once

#include "document/Job.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;

namespace camwb::occ {
class Model;
}

namespace camwb::gui {

class ProfileDialog : public QDialog {
    Q_OBJECT
public:
    ProfileDialog(const document::Operation& operation, const document::Job& job, const occ::Model& model,
                  QWidget* parent = nullptr);
    document::Operation operation() const;

private:
    document::Operation m_operation;
    QLineEdit* m_name;
    QComboBox* m_face;
    QComboBox* m_tool;
    QComboBox* m_direction;
    QDoubleSpinBox* m_depth;
    QDoubleSpinBox* m_safe;
    QDoubleSpinBox* m_clearance;
};

}  // namespace camwb::gui
