#include "gui/tasks/GeometryList.h"

#include "gui/shell/Preferences.h"
#include "gui/view3d/TaskOverlay.h"
#include "occ/Model.h"

#include <QComboBox>
#include <QGridLayout>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>
#include <cmath>

namespace camwb::gui {

namespace {

constexpr int kKindRole = Qt::UserRole + 1;
constexpr int kIndexRole = Qt::UserRole + 2;

// An area in the display unit (the model is in mm).
QString area(double mm2)
{
    const LengthUnit unit = displayUnit();
    return QString::number(toDisplayUnit(toDisplayUnit(mm2, unit), unit), 'f', unit == LengthUnit::Inch ? 3 : 1);
}

const char* curveName(occ::EdgeInfo::Curve curve)
{
    switch (curve) {
    case occ::EdgeInfo::Curve::Line:
        return "line";
    case occ::EdgeInfo::Curve::Circle:
        return "arc";
    case occ::EdgeInfo::Curve::BSpline:
        return "B-spline";
    case occ::EdgeInfo::Curve::Other:
        break;
    }
    return "curve";
}

}  // namespace

GeometryList::GeometryList(document::GeometryRefs& refs, int kinds, const occ::Model& model, TaskOverlay* overlay,
                           QWidget* parent) :
    QWidget(parent),
    m_refs(refs),
    m_kinds(kinds),
    m_model(model),
    m_overlay(overlay),
    m_holes((kinds & Holes) != 0 ? model.holes() : std::vector<geom::Hole>{}),
    m_list(new QListWidget(this)),
    m_kindBox(new QComboBox(this)),
    m_indexBox(new QSpinBox(this)),
    m_addSelection(new QPushButton(tr("Add selected faces"), this))
{
    m_list->setObjectName(QStringLiteral("geometryList"));
    m_list->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_list->setMaximumHeight(110);
    m_addSelection->setObjectName(QStringLiteral("addSelectionButton"));
    m_addSelection->setToolTip(tr("Click faces in the 3D view (Ctrl+click for several), then add them here. "
                                  "For holes, click the hole's wall."));
    auto* remove = new QPushButton(tr("Remove"), this);
    remove->setObjectName(QStringLiteral("removeGeometryButton"));
    m_kindBox->setObjectName(QStringLiteral("geometryKindBox"));
    if ((kinds & Faces) != 0)
        m_kindBox->addItem(tr("Face"), Faces);
    if ((kinds & Edges) != 0)
        m_kindBox->addItem(tr("Edge"), Edges);
    if ((kinds & Holes) != 0)
        m_kindBox->addItem(tr("Hole (face)"), Holes);
    m_indexBox->setObjectName(QStringLiteral("geometryIndexBox"));
    m_indexBox->setRange(1, std::max({1, model.faceCount(), model.edgeCount()}));
    auto* addIndex = new QPushButton(tr("Add"), this);
    addIndex->setObjectName(QStringLiteral("addIndexButton"));

    auto* grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(m_list, 0, 0, 1, 4);
    grid->addWidget(m_addSelection, 1, 0, 1, 2);
    grid->addWidget(remove, 1, 2, 1, 2);
    grid->addWidget(m_kindBox, 2, 0);
    grid->addWidget(m_indexBox, 2, 1);
    grid->addWidget(addIndex, 2, 2, 1, 2);

    connect(m_addSelection, &QPushButton::clicked, this, &GeometryList::addSelection);
    connect(remove, &QPushButton::clicked, this, &GeometryList::removeSelected);
    connect(addIndex, &QPushButton::clicked, this, [this] {
        QString why;
        if (add(static_cast<Kind>(m_kindBox->currentData().toInt()), m_indexBox->value(), &why))
            emit changed();
        else
            emit rejected(why);
    });
    if (m_overlay != nullptr) {
        auto enable = [this] { m_addSelection->setEnabled(!m_overlay->selectedFaces().empty()); };
        connect(m_overlay, &TaskOverlay::selectionChanged, this, enable);
        enable();
    } else {
        m_addSelection->setEnabled(false);
    }
    rebuild();
}

std::vector<int>& GeometryList::indices(Kind kind)
{
    return kind == Faces ? m_refs.faces : kind == Edges ? m_refs.edges : m_refs.holes;
}

bool GeometryList::add(Kind kind, int index, QString* why)
{
    auto fail = [why](const QString& text) {
        if (why != nullptr)
            *why = text;
        return false;
    };
    if ((m_kinds & kind) == 0)
        return fail(tr("This operation takes no %1.")
                        .arg(kind == Faces   ? tr("faces")
                             : kind == Edges ? tr("edges")
                                             : tr("holes")));
    if (kind == Faces && m_model.face(index).index == 0)
        return fail(tr("The model has no face %1.").arg(index));
    if (kind == Edges && m_model.edge(index).index == 0)
        return fail(tr("The model has no edge %1.").arg(index));
    if (kind == Holes &&
        std::none_of(m_holes.begin(), m_holes.end(), [index](const geom::Hole& h) { return h.faceIndex == index; }))
        return fail(tr("Face %1 is not the wall of a vertical cylindrical hole.").arg(index));
    std::vector<int>& list = indices(kind);
    if (std::find(list.begin(), list.end(), index) != list.end())
        return fail(tr("Already in the list."));
    list.push_back(index);
    rebuild();
    return true;
}

void GeometryList::addSelection()
{
    if (m_overlay == nullptr)
        return;
    bool added = false;
    QStringList skipped;
    for (int face : m_overlay->selectedFaces()) {
        // Holes take cylindrical faces, faces take planar ones; whichever this operation takes.
        const bool isHole =
            std::any_of(m_holes.begin(), m_holes.end(), [face](const geom::Hole& h) { return h.faceIndex == face; });
        const Kind kind = (m_kinds & Holes) != 0 && isHole ? Holes : Faces;
        QString why;
        if (add(kind, face, &why))
            added = true;
        else
            skipped << tr("face %1: %2").arg(face).arg(why);
    }
    m_overlay->setSelectedFaces({});
    if (!skipped.isEmpty())
        emit rejected(skipped.join(QLatin1Char(' ')));
    if (added)
        emit changed();
}

void GeometryList::removeSelected()
{
    bool removed = false;
    for (QListWidgetItem* item : m_list->selectedItems()) {
        std::vector<int>& list = indices(static_cast<Kind>(item->data(kKindRole).toInt()));
        list.erase(std::remove(list.begin(), list.end(), item->data(kIndexRole).toInt()), list.end());
        removed = true;
    }
    if (removed) {
        rebuild();
        emit changed();
    }
}

QString GeometryList::describe(Kind kind, int index) const
{
    if (kind == Faces) {
        const occ::FaceInfo f = m_model.face(index);
        if (f.index == 0)
            return tr("Face %1 (not in the model)").arg(index);
        if (!f.planar) {
            // Curved ruled faces (swarf milling's) say what they are.
            auto ruled = m_model.swarfFace(index);
            if (ruled.ok())
                return tr("Face %1 — %2, ruled, drive edge %3, %4 %5²")
                    .arg(index)
                    .arg(QString::fromStdString(ruled->surface))
                    .arg(ruled->edge)
                    .arg(area(f.areaMm2), unitSymbol());
            return tr("Face %1 — not planar").arg(index);
        }
        if (std::abs(std::abs(f.normal.z) - 1) > 1e-9)  // inclined: Z is no level of it; its normal says where it faces
            return tr("Face %1 — planar, normal (%2, %3, %4), %5 %6²")
                .arg(index)
                .arg(f.normal.x, 0, 'f', 3)
                .arg(f.normal.y, 0, 'f', 3)
                .arg(f.normal.z, 0, 'f', 3)
                .arg(area(f.areaMm2), unitSymbol());
        return tr("Face %1 — planar, Z %2, %3 %4²")
            .arg(index)
            .arg(formatLengthNumber(f.planeZ), area(f.areaMm2), unitSymbol());
    }
    if (kind == Edges) {
        const occ::EdgeInfo e = m_model.edge(index);
        if (e.index == 0)
            return tr("Edge %1 (not in the model)").arg(index);
        return tr("Edge %1 — %2, %3 %4")
            .arg(index)
            .arg(QLatin1String(curveName(e.curve)), formatLengthNumber(e.lengthMm), unitSymbol());
    }
    for (const geom::Hole& h : m_holes)
        if (h.faceIndex == index)
            return tr("Hole %1 — Ø%2 at (%3, %4), Z %5 → %6%7")
                .arg(index)
                .arg(formatLengthNumber(h.diameterMm), formatLengthNumber(h.center.x), formatLengthNumber(h.center.y),
                     formatLengthNumber(h.topZ), formatLengthNumber(h.bottomZ))
                .arg(h.through ? tr(", through") : QString());
    return tr("Hole %1 (not a hole of the model)").arg(index);
}

void GeometryList::rebuild()
{
    m_list->clear();
    for (Kind kind : {Faces, Edges, Holes}) {
        for (int index : indices(kind)) {
            auto* item = new QListWidgetItem(describe(kind, index), m_list);
            item->setData(kKindRole, kind);
            item->setData(kIndexRole, index);
        }
    }
}

}  // namespace camwb::gui
