// A chart of one analysed quantity against time, with the playback's time as a red line: a VTK
// chart (vtkChartXY) in the project's own Qt6 OpenGL bridge. A click on the chart asks the
// playback to go to that time. Without OpenGL it shows a message instead, like the 3D view.
#pragma once

#include <QString>
#include <QWidget>

#include <memory>
#include <vector>

namespace camwb::gui {

class SimChart : public QWidget {
    Q_OBJECT
public:
    explicit SimChart(QWidget* parent = nullptr);
    ~SimChart() override;

    bool hasChart() const;  // false without OpenGL
    // The series (equal lengths; long ones are thinned to their extremes per pixel column); an
    // empty one clears the chart.
    void setSeries(const std::vector<double>& timeSeconds, const std::vector<double>& values, const QString& title);
    int plottedPoints() const;
    // The value axis from `low` to `high` (the user's limits); low >= high: the series' own range.
    void setValueLimits(double low, double high);
    void setCursorTime(double seconds);
    double cursorTime() const;

signals:
    void timeClicked(double seconds);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Private;
    std::unique_ptr<Private> d;
};

}  // namespace camwb::gui
