// Tests of the GUI widgets library: ToolpathPolylines (pure), View3D with a real GL context under
// Xvfb and without one on the offscreen platform (run with --no-gl), and the NC editor.
// CAMWB_VIEW3D_SCREENSHOT=<file.png> saves what the 3D view rendered, for a look by eye.
#include "QtTestRun.h"
#include "gui/editor/NcEditor.h"
#include "gui/editor/NcStyles.h"
#include "gui/view3d/View3D.h"
#include "occ/DisplayMesh.h"
#include "toolpath/Toolpath.h"
#include "toolpath/ToolpathPolylines.h"

#include <QApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

using camwb::base::Vec3;
using camwb::gui::NcEditor;
using camwb::gui::NcStyle;
using camwb::gui::View3D;
using camwb::toolpath::PathSegmentKind;
using camwb::toolpath::ToolpathPolylines;
namespace tp = camwb::toolpath;

namespace {

// A box with 4 vertices per face (flat normals) and its 12 edges as feature edges.
camwb::occ::DisplayMesh boxMesh(Vec3 lo, Vec3 hi)
{
    camwb::occ::DisplayMesh mesh;
    const Vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                       {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    struct Face {
        int v[4];
        Vec3 n;
    };
    const Face faces[6] = {{{0, 3, 2, 1}, {0, 0, -1}}, {{4, 5, 6, 7}, {0, 0, 1}}, {{0, 1, 5, 4}, {0, -1, 0}},
                           {{1, 2, 6, 5}, {1, 0, 0}},  {{2, 3, 7, 6}, {0, 1, 0}}, {{3, 0, 4, 7}, {-1, 0, 0}}};
    int faceIndex = 1;
    for (const Face& f : faces) {
        const auto base = static_cast<std::uint32_t>(mesh.positions.size() / 3);
        for (int k : f.v) {
            mesh.positions.insert(mesh.positions.end(), {float(c[k].x), float(c[k].y), float(c[k].z)});
            mesh.normals.insert(mesh.normals.end(), {float(f.n.x), float(f.n.y), float(f.n.z)});
        }
        mesh.triangles.insert(mesh.triangles.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        mesh.triangleFace.insert(mesh.triangleFace.end(), {faceIndex, faceIndex});
        ++faceIndex;
    }
    const int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : edges)
        mesh.featureEdges.push_back({c[e[0]], c[e[1]]});
    mesh.boundsMin = lo;
    mesh.boundsMax = hi;
    return mesh;
}

// Rapid in, a three-turn helix above the box, two feed moves, rapid out.
tp::Toolpath helixPath()
{
    tp::Toolpath path;
    path.add(tp::Rapid{{18, 10, 30}});
    path.add(tp::Rapid{{18, 10, 15}});
    tp::Arc helix;
    helix.to = {18, 10, 3};
    helix.center = {10, 10, 15};
    helix.turns = 2;
    helix.feedMmPerMin = 800;
    path.add(helix);
    path.add(tp::Linear{{30, 10, 3}, 800});
    path.add(tp::Linear{{30, 28, 3}, 800});
    path.add(tp::Rapid{{30, 28, 30}});
    return path;
}

struct PixelStats {
    int grey = 0, blue = 0, green = 0, orange = 0;
    double greyCentroidY = 0, blueCentroidY = 0;
    double lumaVariance = 0;
};

PixelStats analyse(const QImage& image)
{
    PixelStats s;
    double sum = 0, sumSq = 0;
    const QImage img = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < img.height(); ++y) {
        const auto* line = reinterpret_cast<const QRgb*>(img.constScanLine(y));
        for (int x = 0; x < img.width(); ++x) {
            const int r = qRed(line[x]), g = qGreen(line[x]), b = qBlue(line[x]);
            const double luma = 0.299 * r + 0.587 * g + 0.114 * b;
            sum += luma;
            sumSq += luma * luma;
            if (std::abs(r - g) < 12 && std::abs(g - b) < 12 && std::abs(r - b) < 12 && r > 60) {
                ++s.grey;
                s.greyCentroidY += y;
            }
            if (b - r > 100 && b - g > 80) {
                ++s.blue;
                s.blueCentroidY += y;
            }
            if (g - r > 60 && g - b > 40)
                ++s.green;
            if (r - b > 100 && r - g > 40)
                ++s.orange;
        }
    }
    const double n = double(img.width()) * img.height();
    s.lumaVariance = sumSq / n - (sum / n) * (sum / n);
    if (s.grey > 0)
        s.greyCentroidY /= s.grey;
    if (s.blue > 0)
        s.blueCentroidY /= s.blue;
    return s;
}

constexpr const char* kSinumerik = "; CAM Workbench test program\n"
                                   "N10 G17 G90 G54\n"
                                   "N20 T=\"MILL10\" D1 M6\n"
                                   "N30 S8000 M3\n"
                                   "N40 G0 X10.5 Y-20 Z5\n"
                                   "N50 G1 Z-2 F500 ; plunge\n"
                                   "N60 MCALL CYCLE81(10, 0, 2, -5)\n"
                                   "N70 R1=5 IF R1>2 GOTOF ENDE\n"
                                   "N80 X=IC(5) $P_UIFR[1]\n"
                                   "N90 M30\n";

}  // namespace

class ToolpathPolylinesTest : public QObject {
    Q_OBJECT

private slots:
    void fullCircleStaysOnRadius()
    {
        const double r = 10.0, tol = 0.01;
        camwb::toolpath::ToolpathPolylines lines(tol);
        lines.rapid({{r, 0, 0}});
        tp::Arc arc;
        arc.to = {r, 0, 0};
        arc.center = {0, 0, 0};
        lines.arc(arc);
        QCOMPARE(lines.segmentCount(camwb::toolpath::PathSegmentKind::Rapid),
                 std::size_t(0));  // first move only sets the position
        const auto& pts = lines.points();
        const auto& segs = lines.segments();
        QVERIFY(segs.size() >= 36);
        QCOMPARE(segs.size(), lines.segmentCount(camwb::toolpath::PathSegmentKind::Arc));
        QCOMPARE(pts.size(), segs.size() + 1);
        double sweep = 0;
        for (const auto& s : segs) {
            const Vec3 a = pts[s.from], b = pts[s.to];
            QVERIFY(std::abs(a.length() - r) < 1e-9);
            QVERIFY(std::abs(b.length() - r) < 1e-9);
            QVERIFY(std::abs(a.z) < 1e-12);
            QVERIFY((a + b).length() / 2 >= r - tol - 1e-9);  // chord within tolerance
            sweep += std::atan2(a.cross(b).z, a.dot(b));
        }
        QVERIFY(std::abs(sweep - 2 * std::numbers::pi) < 1e-9);  // counter-clockwise, one turn
        QVERIFY(pts.back() == Vec3(r, 0, 0));
    }

    // Five-axis moves: the path joins their tips; the tool axis stands at the first of each run and
    // at every kToolAxisEvery-th move after it, a segment of its own that no path run continues from.
    void toolAxisAlongFiveAxisMoves()
    {
        camwb::toolpath::ToolpathPolylines lines;
        lines.rapid({{0, 0, 10}});
        const Vec3 axis{0.6, 0, 0.8};
        const int moves = 2 * camwb::toolpath::ToolpathPolylines::kToolAxisEvery + 1;
        for (int i = 1; i <= moves; ++i)
            lines.toolAxisMove({{double(i), 0, 10}, axis, 100});
        lines.linear({{0, 0, 10}, 100});
        QCOMPARE(lines.segmentCount(camwb::toolpath::PathSegmentKind::Feed), std::size_t(moves + 1));
        QCOMPARE(lines.segmentCount(camwb::toolpath::PathSegmentKind::ToolAxis), std::size_t(3));  // moves 1, 6 and 11
        const auto& pts = lines.points();
        Vec3 previousEnd{0, 0, 10};
        for (const camwb::toolpath::PathSegment& s : lines.segments()) {
            if (s.kind == camwb::toolpath::PathSegmentKind::ToolAxis) {
                const Vec3 d = pts[s.to] - pts[s.from];
                QVERIFY((d - axis * camwb::toolpath::ToolpathPolylines::kToolAxisLengthMm).length() < 1e-12);
                continue;
            }
            QVERIFY((pts[s.from] - previousEnd).length() < 1e-12);  // the path stays connected
            previousEnd = pts[s.to];
        }
        QVERIFY((previousEnd - Vec3{0, 0, 10}).length() < 1e-12);
    }

    void clockwiseQuarter()
    {
        camwb::toolpath::ToolpathPolylines lines(0.001);
        lines.setStartPosition({0, 5, 0});
        tp::Arc arc;
        arc.to = {5, 0, 0};
        arc.center = {0, 0, 0};
        arc.clockwise = true;
        lines.arc(arc);
        const auto& pts = lines.points();
        for (const Vec3& p : pts) {
            QVERIFY(p.x >= -1e-9 && p.y >= -1e-9);  // stays in the first quadrant (the short way round)
            QVERIFY(std::abs(p.length() - 5) < 1e-9);
        }
        QVERIFY(pts.back() == Vec3(5, 0, 0));
    }

    void helixEndsAtItsZ()
    {
        camwb::toolpath::ToolpathPolylines lines(0.01);
        lines.setStartPosition({18, 10, 15});
        tp::Arc helix;
        helix.to = {18, 10, 3};
        helix.center = {10, 10, 15};
        helix.turns = 2;
        lines.arc(helix);
        const auto& pts = lines.points();
        QVERIFY(pts.back() == Vec3(18, 10, 3));
        double sweep = 0;
        double lastZ = 15;
        for (const auto& s : lines.segments()) {
            const Vec3 a = pts[s.from] - Vec3{10, 10, 0}, b = pts[s.to] - Vec3{10, 10, 0};
            QVERIFY(std::abs(std::hypot(b.x, b.y) - 8) < 1e-9);
            QVERIFY(pts[s.to].z <= lastZ + 1e-12);  // monotonic descent
            lastZ = pts[s.to].z;
            sweep += std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
        }
        QVERIFY(std::abs(sweep - 3 * 2 * std::numbers::pi) < 1e-6);  // coincident ends = 1 turn, + 2 turns
        // Height is linear in the angle: after one of three turns, a third of the drop.
        const std::size_t third = lines.segments().size() / 3;
        QVERIFY(std::abs(pts[lines.segments()[third - 1].to].z - 11) < 1e-6);
    }

    void kindsFromToolpath()
    {
        const camwb::toolpath::ToolpathPolylines lines = camwb::toolpath::ToolpathPolylines::fromToolpath(helixPath());
        QCOMPARE(lines.segmentCount(camwb::toolpath::PathSegmentKind::Rapid),
                 std::size_t(2));  // first rapid only positions
        QCOMPARE(lines.segmentCount(camwb::toolpath::PathSegmentKind::Feed), std::size_t(2));
        QVERIFY(lines.segmentCount(camwb::toolpath::PathSegmentKind::Arc) > 100);
        QVERIFY(lines.points().back() == Vec3(30, 28, 30));
    }

    void cycleDrawsEachHole()
    {
        camwb::toolpath::ToolpathPolylines lines;
        lines.setStartPosition({0, 0, 50});
        tp::Cycle cycle;
        cycle.clearanceZ = 10;
        cycle.retractZ = 2;
        cycle.bottomZ = -5;
        cycle.holes = {{10, 10, 0}, {20, 10, 0}};
        lines.cycle(cycle);
        QCOMPARE(lines.segmentCount(camwb::toolpath::PathSegmentKind::Feed), std::size_t(2));
        QVERIFY(lines.points().back() == Vec3(20, 10, 10));
        // Pecks draw as posts without native cycles write them: down, out to R, back in, deeper.
        camwb::toolpath::ToolpathPolylines pecks;
        pecks.setStartPosition({10, 10, 10});
        cycle.kind = tp::CycleKind::Peck;
        cycle.peckMm = 2;
        cycle.holes = {{10, 10, 0}};
        pecks.cycle(cycle);
        QCOMPARE(pecks.segmentCount(camwb::toolpath::PathSegmentKind::Feed), std::size_t(3));  // to -2, -4 and -5
        QVERIFY(pecks.points().back() == Vec3(10, 10, 10));
    }
};

class NcEditorTest : public QObject {
    Q_OBJECT

private slots:
    void highlightsSinumerik()
    {
        NcEditor editor;
        editor.setText(QString::fromLatin1(kSinumerik));
        QCOMPARE(editor.text(), QString::fromLatin1(kSinumerik));
        QCOMPARE(editor.lineCount(), 11);
        auto style = [&](int line, int column) { return static_cast<NcStyle>(editor.styleAt(line, column)); };
        QCOMPARE(style(1, 1), NcStyle::Comment);
        QCOMPARE(style(1, 20), NcStyle::Comment);
        QCOMPARE(style(2, 1), NcStyle::BlockNumber);
        QCOMPARE(style(2, 3), NcStyle::BlockNumber);
        QCOMPARE(style(2, 5), NcStyle::GWord);           // G17
        QCOMPARE(style(3, 5), NcStyle::FeedSpeedTool);   // T=
        QCOMPARE(style(3, 7), NcStyle::String);          // "MILL10"
        QCOMPARE(style(3, 16), NcStyle::FeedSpeedTool);  // D1
        QCOMPARE(style(3, 19), NcStyle::MWord);          // M6
        QCOMPARE(style(4, 5), NcStyle::FeedSpeedTool);   // S8000
        QCOMPARE(style(4, 11), NcStyle::MWord);          // M3
        QCOMPARE(style(5, 8), NcStyle::AxisWord);        // X10.5
        QCOMPARE(style(5, 12), NcStyle::AxisWord);       // the 5 of X10.5
        QCOMPARE(style(5, 15), NcStyle::AxisWord);       // the - of Y-20
        QCOMPARE(style(6, 5), NcStyle::GWord);           // G1
        QCOMPARE(style(6, 8), NcStyle::AxisWord);        // Z-2
        QCOMPARE(style(6, 12), NcStyle::FeedSpeedTool);  // F500
        QCOMPARE(style(6, 17), NcStyle::Comment);        // ; plunge
        QCOMPARE(style(7, 5), NcStyle::Keyword);         // MCALL
        QCOMPARE(style(7, 11), NcStyle::Keyword);        // CYCLE81
        QCOMPARE(style(7, 19), NcStyle::Number);         // 10
        QCOMPARE(style(8, 5), NcStyle::Parameter);       // R1
        QCOMPARE(style(8, 8), NcStyle::Number);          // 5
        QCOMPARE(style(8, 10), NcStyle::Keyword);        // IF
        QCOMPARE(style(8, 19), NcStyle::Keyword);        // GOTOF
        QCOMPARE(style(9, 7), NcStyle::Keyword);         // IC
        QCOMPARE(style(9, 14), NcStyle::Parameter);      // $P_UIFR
        QCOMPARE(style(10, 5), NcStyle::MWord);          // M30
        QCOMPARE(editor.styleAt(10, 40), -1);
        QCOMPARE(editor.styleAt(99, 1), -1);
    }

    void gotoLineRoundTrip()
    {
        NcEditor editor;
        editor.setText(QString::fromLatin1(kSinumerik));
        QSignalSpy spy(&editor, &NcEditor::cursorLineChanged);
        editor.gotoLine(5);
        QCOMPARE(editor.currentLine(), 5);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.at(0).at(0).toInt(), 5);
        editor.gotoLine(1000);
        QCOMPARE(editor.currentLine(), editor.lineCount());
        editor.gotoLine(1);
        QCOMPARE(editor.currentLine(), 1);
        editor.setReadOnly(true);
        QVERIFY(editor.isReadOnly());
    }

    void largeProgramStylesOnDemand()
    {
        QString program;
        for (int i = 1; i <= 200000; ++i)
            program +=
                QStringLiteral("N%1 G1 X%2 Y%3 F1200 ; move\n").arg(i * 10).arg(i * 0.001, 0, 'f', 3).arg(i % 97);
        NcEditor editor;
        editor.setText(program);
        QCOMPARE(editor.lineCount(), 200001);
        QCOMPARE(static_cast<NcStyle>(editor.styleAt(150000, 1)), NcStyle::BlockNumber);
        editor.gotoLine(199999);
        QCOMPARE(editor.currentLine(), 199999);
    }
};

class View3DTest : public QObject {
    Q_OBJECT

private slots:
    void rendersModelAndToolpath()
    {
        QString reason;
        QVERIFY2(View3D::openGlAvailable(&reason), qPrintable(reason));
        View3D view;
        QVERIFY(view.hasOpenGl());
        QVERIFY(view.findChild<QLabel*>(QStringLiteral("noOpenGlMessage")) == nullptr);
        view.resize(800, 600);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));

        view.setModel(boxMesh({0, 0, -10}, {20, 20, 0}));
        view.setToolpath(helixPath());
        QVERIFY(view.hasModelActor());
        QVERIFY(view.hasToolpathActor());
        QVERIFY(view.toolpathSegmentCount() > 100);
        view.setViewPreset(View3D::Preset::Isometric);
        QTest::qWait(50);

        const QImage image = view.grabImage();
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 800 && image.height() >= 600);
        if (const QByteArray path = qgetenv("CAMWB_VIEW3D_SCREENSHOT"); !path.isEmpty())
            image.save(QString::fromLocal8Bit(path));
        const PixelStats s = analyse(image);
        const int area = image.width() * image.height();
        QVERIFY2(s.lumaVariance > 100, qPrintable(QString::number(s.lumaVariance)));
        QVERIFY2(s.grey > area / 50, qPrintable(QStringLiteral("grey %1").arg(s.grey)));  // the shaded box
        // Colours as CAMotics and SinuTrain draw them: arcs blue, feed green, rapids red.
        QVERIFY2(s.blue > 200, qPrintable(QStringLiteral("blue %1").arg(s.blue)));    // the helix
        QVERIFY2(s.green > 20, qPrintable(QStringLiteral("green %1").arg(s.green)));  // feed moves
        QVERIFY2(s.orange > 20, qPrintable(QStringLiteral("red %1").arg(s.orange)));  // rapids
        // Z up: the helix above the box is drawn above it (the image is not upside down).
        QVERIFY(s.blueCentroidY < s.greyCentroidY);

        view.setViewPreset(View3D::Preset::Top);
        const PixelStats top = analyse(view.grabImage());
        QVERIFY(top.grey > area / 50);

        view.clearToolpath();
        QVERIFY(!view.hasToolpathActor());
        QCOMPARE(view.toolpathSegmentCount(), 0);
        view.clearModel();
        QVERIFY(!view.hasModelActor());
        const PixelStats empty = analyse(view.grabImage());
        // The helix was most of the blue; only the orientation marker's Z axis is left.
        QVERIFY2(empty.blue < s.blue / 4, qPrintable(QStringLiteral("%1 of %2").arg(empty.blue).arg(s.blue)));
    }

    void mouseOrbitChangesTheImage()
    {
        View3D view;
        view.resize(400, 300);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setModel(boxMesh({0, 0, -10}, {20, 20, 0}));
        const QImage before = view.grabImage();
        QWidget* gl = view.findChild<QWidget*>(QStringLiteral("view3dGl"));
        QVERIFY(gl != nullptr);
        QTest::mousePress(gl, Qt::LeftButton, {}, QPoint(200, 150));
        QTest::mouseMove(gl, QPoint(260, 170));
        QTest::mouseRelease(gl, Qt::LeftButton, {}, QPoint(260, 170));
        const QImage after = view.grabImage();
        QVERIFY(before != after);
    }

    void disabledByEnvironment()
    {
        qputenv("CAMWB_NO_OPENGL", "1");
        QString reason;
        const bool available = View3D::openGlAvailable(&reason);
        qunsetenv("CAMWB_NO_OPENGL");
        QVERIFY(!available);
        QVERIFY(reason.contains(QLatin1String("CAMWB_NO_OPENGL")));
    }
};

class View3DNoGlTest : public QObject {
    Q_OBJECT

private slots:
    void showsMessageAndKeepsData()
    {
        QString reason;
        QVERIFY(!View3D::openGlAvailable(&reason));
        QVERIFY(!reason.isEmpty());
        View3D view;
        QVERIFY(!view.hasOpenGl());
        view.resize(400, 300);
        view.show();
        auto* label = view.findChild<QLabel*>(QStringLiteral("noOpenGlMessage"));
        QVERIFY(label != nullptr);
        QVERIFY(label->isVisible());
        QVERIFY(label->text().startsWith(QLatin1String("3D view unavailable: ")));
        view.setModel(boxMesh({0, 0, -10}, {20, 20, 0}));
        view.setToolpath(helixPath());
        view.setViewPreset(View3D::Preset::Front);
        view.fitAll();
        QVERIFY(view.hasModelActor());
        QVERIFY(view.hasToolpathActor());
        QVERIFY(view.toolpathSegmentCount() > 100);
        QVERIFY(view.grabImage().isNull());
        view.clearModel();
        view.clearToolpath();
        QVERIFY(!view.hasModelActor());
    }
};

int main(int argc, char** argv)
{
    std::vector<char*> args;
    bool noGl = false;
    for (int i = 0; i < argc; ++i) {
        if (std::strcmp(argv[i], "--no-gl") == 0)
            noGl = true;
        else
            args.push_back(argv[i]);
    }
    int count = static_cast<int>(args.size());
    View3D::setDefaultSurfaceFormat();
    QApplication app(count, args.data());
    QtTestRun run(count, args.data());
    View3DNoGlTest noGlTest;
    ToolpathPolylinesTest polylines;
    View3DTest view;
    run.run(&polylines);
    if (noGl) {
        run.run(&noGlTest);
        run.notOnThisPlatform("View3DTest", "the Xvfb registration runs it");
    } else {
        run.run(&view);
        run.notOnThisPlatform("View3DNoGlTest", "the offscreen registration (--no-gl) runs it");
    }
    NcEditorTest editor;
    run.run(&editor);
    return run.finish();
}

#include "WidgetsTest.moc"
