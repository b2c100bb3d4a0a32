// Private to the job setup panel (JobSetupPanel.cpp, JobSetupStock.cpp): the X/Y/Z field
// helpers and the order of the origin choices both files use.
#pragma once

#include "base/Vec.h"
#include "document/JobSetup.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QLabel>
#include <QString>
#include <QWidget>

#include <array>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace camwb::gui::jobsetup {

inline QString qs(const std::string& s) { return QString::fromStdString(s); }

inline base::Vec3 valueOf(const std::array<QDoubleSpinBox*, 3>& fields)
{
    return {fields[0]->value(), fields[1]->value(), fields[2]->value()};
}

inline void showVec3(const std::array<QDoubleSpinBox*, 3>& fields, const base::Vec3& v)
{
    fields[0]->setValue(v.x);
    fields[1]->setValue(v.y);
    fields[2]->setValue(v.z);
}

// Columns of X, Y, Z fields under their titles, one row per axis: narrow enough for the dock.
inline QWidget* axisGrid(const std::vector<std::pair<QString, std::array<QDoubleSpinBox*, 3>>>& columns)
{
    auto* widget = new QWidget;
    auto* grid = new QGridLayout(widget);
    grid->setContentsMargins(0, 0, 0, 0);
    const char* axes[] = {"X", "Y", "Z"};
    for (int c = 0; c < static_cast<int>(columns.size()); ++c) {
        const auto& [title, fields] = columns[static_cast<std::size_t>(c)];
        if (!title.isEmpty())
            grid->addWidget(new QLabel(title), 0, c + 1);
        for (int a = 0; a < 3; ++a)
            grid->addWidget(fields[static_cast<std::size_t>(a)], a + 1, c + 1);
    }
    for (int a = 0; a < 3; ++a)
        grid->addWidget(new QLabel(QLatin1String(axes[a])), a + 1, 0);
    return widget;
}

// Origin choices after "typed": the stock points of document::stockAnchor, in this order.
inline constexpr document::StockAnchor kAnchors[] = {
    document::StockAnchor::TopFrontLeft, document::StockAnchor::BottomFrontLeft, document::StockAnchor::TopCentre,
    document::StockAnchor::Centre, document::StockAnchor::BottomCentre};
// Then the model vertex picked in the 3D view (X, Y and Z), then the face picked there (its level as Z0).
inline constexpr int kPickedVertex = 1 + static_cast<int>(std::size(kAnchors));
inline constexpr int kPickedFace = kPickedVertex + 1;

}  // namespace camwb::gui::jobsetup
