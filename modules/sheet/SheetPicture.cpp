#include "sheet/SheetPicture.h"

#include "toolpath/Toolpath.h"

#include <QPainter>
#include <QPainterPath>
#include <QPen>

#include <algorithm>
#include <array>
#include <cmath>

namespace camwb::sheet {

namespace {

// Isometric view from the front right, above: towards the camera, right and up on the screen.
const base::Vec3 kToCamera{1 / std::sqrt(3.0), -1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
const base::Vec3 kRight{1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0};
const base::Vec3 kUp{-1 / std::sqrt(6.0), 1 / std::sqrt(6.0), 2 / std::sqrt(6.0)};
// The light comes from over the viewer's left shoulder, so that the three visible sides differ.
const base::Vec3 kLight{0.2, -0.5, 0.84};

const QColor kModel(150, 170, 190);
const QColor kStock(230, 130, 0);
const QColor kFeed(0, 70, 200);
const QColor kRapid(210, 0, 0);
const QColor kFaint(120, 120, 120, 70);

}  // namespace

SheetPicture::SheetPicture(occ::DisplayMesh mesh, std::optional<base::Box3> stock, const toolpath::Toolpath& program) :
    m_stock(std::move(stock)),
    m_path(toolpath::ToolpathPolylines::fromToolpath(program, 0.05))
{
    const auto vertex = [&](std::uint32_t i) {
        return base::Vec3{mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
    };
    for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
        Triangle tri{vertex(mesh.triangles[t]), vertex(mesh.triangles[t + 1]), vertex(mesh.triangles[t + 2])};
        const base::Vec3 n = (tri.b - tri.a).cross(tri.c - tri.a);
        const double length = n.length();
        if (length <= 0)
            continue;
        tri.depth = (tri.a + tri.b + tri.c).dot(kToCamera) / 3;
        tri.shade = 0.45 + 0.55 * std::fabs(n.dot(kLight)) / length;
        m_triangles.push_back(tri);
        for (const base::Vec3& p : {tri.a, tri.b, tri.c})
            m_bounds.add(p);
    }
    std::stable_sort(m_triangles.begin(), m_triangles.end(),
                     [](const Triangle& l, const Triangle& r) { return l.depth < r.depth; });
    if (m_stock) {
        m_bounds.add(m_stock->min);
        m_bounds.add(m_stock->max);
    }
    for (const base::Vec3& p : m_path.points())
        m_bounds.add(p);
    m_bounds.add({0, 0, 0});  // the work zero's axes
    for (const toolpath::PathSegment& segment : m_path.segments())
        m_segmentOperation.push_back(segment.record < program.size() ? program.source(segment.record).operationIndex
                                                                     : -1);
}

QPointF SheetPicture::project(const base::Vec3& p, double scale, const QPointF& offset) const
{
    return {offset.x() + scale * p.dot(kRight), offset.y() - scale * p.dot(kUp)};
}

QImage SheetPicture::render(QSize size, int highlightOperation) const
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    if (m_bounds.empty)
        return image;
    // Fit the projected bounds into the picture with a margin.
    double left = 1e300, right = -1e300, top = -1e300, bottom = 1e300;
    for (const base::Vec3& corner : base::boxCorners(m_bounds.min, m_bounds.max)) {
        left = std::min(left, corner.dot(kRight));
        right = std::max(right, corner.dot(kRight));
        top = std::max(top, corner.dot(kUp));
        bottom = std::min(bottom, corner.dot(kUp));
    }
    const double margin = 16;
    const double scale = std::min((size.width() - 2 * margin) / std::max(right - left, 1e-6),
                                  (size.height() - 2 * margin) / std::max(top - bottom, 1e-6));
    const QPointF offset(size.width() / 2.0 - scale * (left + right) / 2,
                         size.height() / 2.0 + scale * (top + bottom) / 2);
    const auto at = [&](const base::Vec3& p) { return project(p, scale, offset); };

    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    for (const Triangle& tri : m_triangles) {
        const QColor colour =
            QColor::fromRgbF(kModel.redF() * tri.shade, kModel.greenF() * tri.shade, kModel.blueF() * tri.shade);
        painter.setPen(QPen(colour, 0.5));
        painter.setBrush(colour);
        const std::array<QPointF, 3> points{at(tri.a), at(tri.b), at(tri.c)};
        painter.drawPolygon(points.data(), 3);
    }
    if (m_stock) {
        painter.setPen(QPen(kStock, 1.5, Qt::DashLine));
        const base::Vec3 lo = m_stock->min, hi = m_stock->max;
        const std::array<base::Vec3, 4> bottomRing{
            {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}}};
        for (std::size_t i = 0; i < 4; ++i) {
            const base::Vec3 a = bottomRing[i], b = bottomRing[(i + 1) % 4];
            painter.drawLine(at(a), at(b));
            painter.drawLine(at({a.x, a.y, hi.z}), at({b.x, b.y, hi.z}));
            painter.drawLine(at(a), at({a.x, a.y, hi.z}));
        }
    }
    // The path: the highlighted operation last, over the faint rest.
    const auto& points = m_path.points();
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t s = 0; s < m_path.segments().size(); ++s) {
            const toolpath::PathSegment& segment = m_path.segments()[s];
            if (segment.kind == toolpath::PathSegmentKind::ToolAxis)
                continue;
            const bool mine = highlightOperation < 0 || m_segmentOperation[s] == highlightOperation;
            if (mine != (pass == 1))
                continue;
            const bool rapid = segment.kind == toolpath::PathSegmentKind::Rapid;
            QPen pen(!mine ? kFaint : rapid ? kRapid : kFeed, mine && highlightOperation >= 0 ? 1.6 : 1.0);
            if (rapid)
                pen.setStyle(Qt::DashLine);
            painter.setPen(pen);
            painter.drawLine(at(points[segment.from]), at(points[segment.to]));
        }
    }
    // The work zero: X red, Y green, Z blue, a tenth of the picture's size.
    const double axis = 0.1 * std::max(right - left, top - bottom);
    const std::array<std::pair<base::Vec3, QColor>, 3> axes{
        {{{axis, 0, 0}, Qt::red}, {{0, axis, 0}, QColor(0, 150, 0)}, {{0, 0, axis}, Qt::blue}}};
    const char* const names[] = {"X", "Y", "Z"};
    for (std::size_t i = 0; i < axes.size(); ++i) {
        painter.setPen(QPen(axes[i].second, 2.5));
        painter.drawLine(at({0, 0, 0}), at(axes[i].first));
        painter.drawText(at(axes[i].first) + QPointF(3, -3), QString::fromLatin1(names[i]));
    }
    return image;
}

}  // namespace camwb::sheet
