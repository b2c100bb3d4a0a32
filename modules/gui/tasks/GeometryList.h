// A task panel's geometry: the faces, edges and holes the operation cuts, listed by model index
// with what they are (plane Z, length, diameter). Faces picked in the 3D view are added with one
// button (holes by their cylindrical face); edges, which the view cannot pick, by typed index.
#pragma once

#include "document/Job.h"
#include "geom/Hole.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace camwb::occ {
class Model;
}

namespace camwb::gui {

class TaskOverlay;

class GeometryList : public QWidget {
    Q_OBJECT
public:
    enum Kind { Faces = 1, Edges = 2, Holes = 4 };

    // `refs` is the operation's geometry, edited in place; `kinds` what this operation takes.
    GeometryList(document::GeometryRefs& refs, int kinds, const occ::Model& model, TaskOverlay* overlay,
                 QWidget* parent = nullptr);

    QListWidget* list() const { return m_list; }
    // Adds one reference; false (with the reason in `why`) for an unknown index or a face that is
    // no hole when a hole is asked for.
    bool add(Kind kind, int index, QString* why = nullptr);

signals:
    void changed();
    void rejected(const QString& why);

private:
    void rebuild();
    void addSelection();
    void removeSelected();
    QString describe(Kind kind, int index) const;
    std::vector<int>& indices(Kind kind);

    document::GeometryRefs& m_refs;
    int m_kinds;
    const occ::Model& m_model;
    TaskOverlay* m_overlay;
    std::vector<geom::Hole> m_holes;
    QListWidget* m_list;
    QComboBox* m_kindBox;
    QSpinBox* m_indexBox;
    QPushButton* m_addSelection;
};

}  // namespace camwb::gui
