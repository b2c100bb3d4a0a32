#include "gui/sim/SimChart.h"

#include "gui/view3d/View3D.h"
#include "gui/view3d/VtkOpenGLWidget.h"

#include <QLabel>
#include <QMouseEvent>
#include <QVBoxLayout>

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>

namespace camwb::gui {

namespace {

// Points plotted at most: the extremes of this many columns each.
constexpr std::size_t kColumns = 1500;

vtkSmartPointer<vtkTable> table(const char* x, const char* y)
{
    auto t = vtkSmartPointer<vtkTable>::New();
    for (const char* name : {x, y}) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(name);
        t->AddColumn(column);
    }
    return t;
}

}  // namespace

struct SimChart::Private {
    VtkOpenGLWidget* gl = nullptr;
    vtkNew<vtkRenderer> renderer;
    vtkNew<vtkContextActor> actor;
    vtkNew<vtkChartXY> chart;
    vtkSmartPointer<vtkTable> series = table("t", "value");
    vtkSmartPointer<vtkTable> cursor = table("t", "cursor");
    double low = 0, high = 1;
    double cursorTime = 0;
    int points = 0;

    void render()
    {
        if (gl != nullptr)
            gl->update();
    }
    void placeCursor();
};

SimChart::SimChart(QWidget* parent) : QWidget(parent), d(std::make_unique<Private>())
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    setMinimumHeight(140);
    QString reason;
    if (!View3D::openGlAvailable(&reason)) {
        auto* message = new QLabel(tr("Chart unavailable: %1").arg(reason), this);
        message->setObjectName(QStringLiteral("noChartMessage"));
        message->setAlignment(Qt::AlignCenter);
        message->setWordWrap(true);
        layout->addWidget(message);
        return;
    }
    d->gl = new VtkOpenGLWidget(this);
    d->gl->setObjectName(QStringLiteral("simChartGl"));
    d->gl->installEventFilter(this);
    layout->addWidget(d->gl);
    d->renderer->SetBackground(1, 1, 1);
    d->gl->renderWindow()->AddRenderer(d->renderer);
    d->actor->GetScene()->AddItem(d->chart);
    d->actor->GetScene()->SetRenderer(d->renderer);
    d->renderer->AddActor(d->actor);
    d->chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("t (s)");
    d->chart->SetShowLegend(false);
}

SimChart::~SimChart()
{
    delete d->gl;  // VTK's graphics released while the context exists
}

bool SimChart::hasChart() const { return d->gl != nullptr; }

void SimChart::setSeries(const std::vector<double>& timeSeconds, const std::vector<double>& values,
                         const QString& title)
{
    d->chart->ClearPlots();
    d->points = 0;
    const std::size_t n = std::min(timeSeconds.size(), values.size());
    if (n < 2) {
        d->render();
        return;
    }
    // Per column the first, lowest and highest values in time order: spikes survive thinning.
    auto* t = vtkDoubleArray::SafeDownCast(d->series->GetColumn(0));
    auto* v = vtkDoubleArray::SafeDownCast(d->series->GetColumn(1));
    t->Reset();
    v->Reset();
    const std::size_t step = std::max<std::size_t>(1, n / kColumns);
    d->low = values[0];
    d->high = values[0];
    for (std::size_t begin = 0; begin < n; begin += step) {
        const std::size_t end = std::min(n, begin + step);
        const auto [lo, hi] = std::minmax_element(values.begin() + begin, values.begin() + end);
        for (auto it : {lo, hi}) {
            const std::size_t i = static_cast<std::size_t>(it - values.begin());
            t->InsertNextValue(timeSeconds[i]);
            v->InsertNextValue(values[i]);
        }
        d->low = std::min(d->low, *lo);
        d->high = std::max(d->high, *hi);
    }
    d->series->Modified();
    d->points = static_cast<int>(t->GetNumberOfTuples());
    vtkPlot* line = d->chart->AddPlot(vtkChart::LINE);
    line->SetInputData(d->series, 0, 1);
    line->SetColor(20, 80, 200, 255);
    line->SetWidth(1.5f);
    const QByteArray titleUtf8 = title.toUtf8();
    d->chart->GetAxis(vtkAxis::LEFT)->SetTitle(titleUtf8.constData());
    vtkPlot* cursor = d->chart->AddPlot(vtkChart::LINE);
    cursor->SetInputData(d->cursor, 0, 1);
    cursor->SetColor(220, 0, 0, 255);
    cursor->SetWidth(2.0f);
    d->placeCursor();
    d->chart->RecalculateBounds();
    d->render();
}

int SimChart::plottedPoints() const { return d->points; }

void SimChart::setValueLimits(double low, double high)
{
    vtkAxis* axis = d->chart->GetAxis(vtkAxis::LEFT);
    if (low < high) {
        axis->SetBehavior(vtkAxis::FIXED);
        axis->SetRange(low, high);
    } else {
        axis->SetBehavior(vtkAxis::AUTO);
        d->chart->RecalculateBounds();
    }
    d->render();
}

void SimChart::Private::placeCursor()
{
    auto* t = vtkDoubleArray::SafeDownCast(cursor->GetColumn(0));
    auto* v = vtkDoubleArray::SafeDownCast(cursor->GetColumn(1));
    t->Reset();
    v->Reset();
    for (double y : {low, high}) {
        t->InsertNextValue(cursorTime);
        v->InsertNextValue(y);
    }
    cursor->Modified();
}

void SimChart::setCursorTime(double seconds)
{
    d->cursorTime = seconds;
    if (d->points == 0)
        return;
    d->placeCursor();
    d->render();
}

double SimChart::cursorTime() const { return d->cursorTime; }

// A click picks a time; the rest of the mouse stays with the chart (no camera to turn here).
bool SimChart::eventFilter(QObject* watched, QEvent* event)
{
    if (d->gl == nullptr || watched != d->gl)
        return QWidget::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* mouse = static_cast<QMouseEvent*>(event);
        vtkAxis* axis = d->chart->GetAxis(vtkAxis::BOTTOM);
        const double x = mouse->position().x() * d->gl->devicePixelRatioF();
        const float* p1 = axis->GetPoint1();
        const float* p2 = axis->GetPoint2();
        if (mouse->button() == Qt::LeftButton && d->points > 0 && p2[0] > p1[0])
            emit timeClicked(axis->GetMinimum() +
                             (x - p1[0]) / (p2[0] - p1[0]) * (axis->GetMaximum() - axis->GetMinimum()));
        return true;
    }
    case QEvent::MouseButtonRelease:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::MouseButtonDblClick:
        return true;
    default:
        return QWidget::eventFilter(watched, event);
    }
}

}  // namespace camwb::gui
