// Pictures for the setup sheet without OpenGL, so that `camwb-cli setup-sheet` draws them
// headless: the model's display mesh in isometric view (flat-shaded triangles in painter's
// order), the stock box outline, the work zero's axes and the toolpath, with one operation's
// path highlighted. QtGui only (QImage, QPainter).
#pragma once

#include "base/Vec.h"
#include "occ/DisplayMesh.h"
#include "toolpath/ToolpathPolylines.h"

#include <QImage>
#include <QSize>

#include <optional>
#include <vector>

namespace camwb::toolpath {
class Toolpath;
}

namespace camwb::sheet {

class SheetPicture {
public:
    SheetPicture(occ::DisplayMesh mesh, std::optional<base::Box3> stock, const toolpath::Toolpath& program);

    // The part with the whole path (highlightOperation < 0), or with the given operation's path
    // (job index) drawn strong and the rest faint.
    QImage render(QSize size, int highlightOperation = -1) const;

private:
    struct Triangle {
        base::Vec3 a, b, c;
        double depth = 0;  // along the view direction: larger is nearer
        double shade = 1;
    };
    QPointF project(const base::Vec3& p, double scale, const QPointF& offset) const;

    std::vector<Triangle> m_triangles;  // far to near
    std::optional<base::Box3> m_stock;
    toolpath::ToolpathPolylines m_path;
    std::vector<int> m_segmentOperation;  // per path segment: the job operation it belongs to (-1 none)
    base::Box3 m_bounds;                  // of everything drawn
};

}  // namespace camwb::sheet
