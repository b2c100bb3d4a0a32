// The options of Renumber blocks (Cam.Nc.Renumber): start, step, which lines get numbers and what
// happens to existing ones. Heidenhain programs are always numbered 0, 1, 2, ...: the options are
// shown disabled there, with the reason.
#pragma once

#include "nc/Dialect.h"
#include "nc/tools/BlockNumbers.h"

#include <QDialog>

class QCheckBox;
class QSpinBox;

namespace camwb::gui {

class RenumberDialog : public QDialog {
    Q_OBJECT

public:
    explicit RenumberDialog(nc::Dialect dialect, QWidget* parent = nullptr);

    void setOptions(const nc::RenumberOptions& options);
    nc::RenumberOptions options() const;

private:
    nc::Dialect m_dialect;
    QSpinBox* m_start;
    QSpinBox* m_step;
    QCheckBox* m_commentLines;
    QCheckBox* m_emptyLines;
    QCheckBox* m_keepExisting;
    QCheckBox* m_onlyNumbered;
};

}  // namespace camwb::gui
