// The Simulator dock: the playback's buttons (the registry's Cam.Sim.* actions), the speed, a
// read-out of time, line and move with the cycle time, progress and Cancel while a simulation is
// built, a banner when the program changed after simulating, and the results: the path coloured
// by an analysed quantity (auto or user limits), the stock's deviation limit with the largest
// gouge and leftover, the chart, and a measured trace's import (its column layout asked in a small
// dialog) and summary. It only shows and forwards: SimPlayer does the work.
#pragma once

#include "sim/MeasuredTrace.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSlider;
class QSpinBox;
class QToolBar;

namespace camwb::gui {

class ActionRegistry;
class Banner;
class Prompter;
class SimChart;
class SimPlayer;

class SimDock : public QWidget {
    Q_OBJECT
public:
    SimDock(SimPlayer* player, QWidget* parent = nullptr);

    SimChart* chart() const { return m_chart; }
    // The dock's buttons are the registry's actions (call after registerSimulatorActions).
    void addActions(const ActionRegistry& registry);
    int lineToJumpTo() const;
    // The stock's cell size for the next simulation (finer: truer deviations, more to draw).
    double resolutionMm() const;
    // Cam.Sim.ImportMeasured: asks `prompter` for the CSV, then for its columns and units (a
    // dialog prefilled with the last ones, at first sim::TraceColumns' defaults), and imports it;
    // an error goes to `prompter` and leaves the dock as it was.
    void importMeasured(Prompter& prompter);
    // Slider position -> playback speed (machine time per wall time), 0.1x .. 1000x.
    static double speedOfSlider(int value);

private:
    QWidget* makeResults();
    void updateReadout();
    void updateQuantities();
    void applyQuantity();
    void updateDeviation();
    void updateMeasured();
    void updateBanner();

    SimPlayer* m_player;
    QToolBar* m_buttons;
    QSlider* m_speed;
    QLabel* m_speedLabel;
    QSpinBox* m_line;
    QLabel* m_readout;
    QLabel* m_cycle;
    QProgressBar* m_progress;
    QPushButton* m_cancel;
    Banner* m_banner;
    QComboBox* m_quantity;
    QCheckBox* m_autoLimits;
    QDoubleSpinBox* m_low;
    QDoubleSpinBox* m_high;
    QDoubleSpinBox* m_deviationLimit;
    QDoubleSpinBox* m_resolution;
    QCheckBox* m_showTool;
    QLabel* m_results;
    QLabel* m_measured;
    SimChart* m_chart;
    sim::TraceColumns m_measuredColumns;  // the layout the last import used
    double m_measuredZOffsetMm = 0;
};

}  // namespace camwb::gui
