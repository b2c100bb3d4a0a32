// The four heights of an operation (clearance, safe, start, final), each "auto" (derived from the
// model and stock when computed; the field shows the derived value of the last preview) or set by
// the user (stored in the job as an override).
#pragma once

#include "document/Job.h"
#include "ops/OpCommon.h"

#include <QWidget>

#include <array>

class QCheckBox;
class QDoubleSpinBox;

namespace camwb::gui {

class HeightsBox : public QWidget {
    Q_OBJECT
public:
    HeightsBox(document::HeightOverrides& overrides, QWidget* parent = nullptr);

    // Shows derived values in the fields that are "auto" (and remembers them for unchecking).
    void setDerived(const ops::Heights& heights);

signals:
    void changed();

private:
    struct Row {
        std::optional<double> document::HeightOverrides::*override;
        double ops::Heights::*derived;
        QCheckBox* automatic = nullptr;
        QDoubleSpinBox* value = nullptr;
    };
    document::HeightOverrides& m_overrides;
    std::array<Row, 4> m_rows;
};

}  // namespace camwb::gui
