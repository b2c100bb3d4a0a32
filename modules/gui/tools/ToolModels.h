// Table models of the tool library dialog: the library's tools (one row per tool, geometry in
// columns, edited in place) and one tool's cutting data (one row per material). Both edit the
// vector they are given, owned by the dialog, and say when they changed it.
#pragma once

#include "ops/OpCommon.h"

#include <QAbstractTableModel>
#include <QPointer>

#include <vector>

namespace camwb::gui {

class ToolTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Number,
        Name,
        Kind,
        Diameter,
        CornerRadius,
        FluteLength,
        Length,
        Flutes,
        PointAngle,
        Holder,
        ColumnCount
    };

    explicit ToolTableModel(std::vector<ops::ToolController>* tools, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

    // The vector was replaced or rows added/removed outside the model.
    void reload();

signals:
    void edited();

private:
    std::vector<ops::ToolController>* m_tools;
};

class Workbench;

// The job's tools with their speeds and feeds, which the user may edit after computing them
// (each edit one undo step through the workbench); follows the job.
class JobToolsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Number, Name, Diameter, Flutes, Rpm, CuttingFeed, PlungeFeed, RampFeed, Materials, ColumnCount };

    explicit JobToolsModel(Workbench& workbench, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

private:
    // The window may destroy the workbench before this dialog's model: then the model is empty.
    const Workbench* workbench() const { return m_workbench.data(); }
    QPointer<Workbench> m_workbench;
};

class CuttingDataModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Material, Vc, Fz, Plunge, Ramp, ColumnCount };

    explicit CuttingDataModel(QObject* parent = nullptr);
    // The cutting data shown: that of `tool` (nullptr: none).
    void setTool(ops::ToolController* tool);
    void addRow();
    void removeRow(int row);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;

signals:
    void edited();

private:
    ops::ToolController* m_tool = nullptr;
};

}  // namespace camwb::gui
