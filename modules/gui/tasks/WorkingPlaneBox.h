// An operation's working plane (3+2): flat (the workpiece's XY; drilling then turns to each
// hole's own axis), along a planar face's normal, or spatial angles A, B, C. Edits the operation's
// WorkingPlaneSpec in place and says when it changed.
#pragma once

#include "document/Job.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace camwb::gui {

class WorkingPlaneBox : public QWidget {
    Q_OBJECT
public:
    // `faceCount`: the model's faces, the range of the face field (0: no model).
    WorkingPlaneBox(document::WorkingPlaneSpec& spec, int faceCount, QWidget* parent = nullptr);

signals:
    void changed();

private:
    void showMode();

    document::WorkingPlaneSpec& m_spec;
    QComboBox* m_mode = nullptr;
    QSpinBox* m_face = nullptr;
    QDoubleSpinBox* m_angles[3] = {};
};

}  // namespace camwb::gui
