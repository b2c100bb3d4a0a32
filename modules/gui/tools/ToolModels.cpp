#include "gui/tools/ToolModels.h"

#include "gui/shell/Preferences.h"
#include "gui/shell/Workbench.h"

#include <cmath>

namespace camwb::gui {

namespace {

// A number typed into a cell: refused (false) unless it is a number >= `minimum`.
bool toNumber(const QVariant& value, double minimum, double& out)
{
    bool ok = false;
    const double number = value.toString().toDouble(&ok);
    if (!ok || number < minimum)
        return false;
    out = number;
    return true;
}

// Lengths and feeds (mm, mm/min, mm/tooth) in the display unit, rounded as every length shows.
QVariant shown(double mm)
{
    const LengthUnit unit = displayUnit();
    const double scale = std::pow(10.0, lengthDecimals(unit));
    return std::round(toDisplayUnit(mm, unit) * scale) / scale;
}

// A length or feed typed in the display unit into `mm`: refused (false) unless a number >=
// `minimum` (mm). Typing back what is shown keeps the exact value (no rounding through inches).
bool fromShown(const QVariant& value, double minimum, double& mm)
{
    bool ok = false;
    const double number = value.toString().toDouble(&ok);
    if (!ok)
        return false;
    if (number == shown(mm).toDouble())
        return true;
    const double typed = fromDisplayUnit(number, displayUnit());
    if (typed < minimum)
        return false;
    mm = typed;
    return true;
}

}  // namespace

ToolTableModel::ToolTableModel(std::vector<ops::ToolController>* tools, QObject* parent) :
    QAbstractTableModel(parent),
    m_tools(tools)
{
}

int ToolTableModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(m_tools->size());
}

int ToolTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant ToolTableModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || (role != Qt::DisplayRole && role != Qt::EditRole))
        return {};
    const toolpath::Tool& t = (*m_tools)[index.row()].tool;
    switch (index.column()) {
    case Number:
        return t.number;
    case Name:
        return QString::fromStdString(t.name);
    case Kind:
        return QString::fromStdString(t.kind);
    case Diameter:
        return shown(t.diameterMm);
    case CornerRadius:
        return shown(t.cornerRadiusMm);
    case FluteLength:
        return shown(t.fluteLengthMm);
    case Length:
        return shown(t.lengthMm);
    case Flutes:
        return t.flutes;
    case PointAngle:
        return t.pointAngleDeg;
    case Holder:
        return QString::fromStdString(t.holder);
    default:
        return {};
    }
}

QVariant ToolTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Number:
        return tr("T");
    case Name:
        return tr("Name");
    case Kind:
        return tr("Kind");
    case Diameter:
        return tr("D (%1)").arg(unitSymbol());
    case CornerRadius:
        return tr("R (%1)").arg(unitSymbol());
    case FluteLength:
        return tr("Flute (%1)").arg(unitSymbol());
    case Length:
        return tr("Length (%1)").arg(unitSymbol());
    case Flutes:
        return tr("Flutes");
    case PointAngle:
        return tr("Point (°)");
    case Holder:
        return tr("Holder");
    default:
        return {};
    }
}

Qt::ItemFlags ToolTableModel::flags(const QModelIndex& index) const
{
    return QAbstractTableModel::flags(index) | Qt::ItemIsEditable;
}

bool ToolTableModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || role != Qt::EditRole)
        return false;
    toolpath::Tool& t = (*m_tools)[index.row()].tool;
    double number = 0;
    const QString text = value.toString().trimmed();
    static const QStringList kinds = {QStringLiteral("flat"), QStringLiteral("ball"), QStringLiteral("bull"),
                                      QStringLiteral("drill"), QStringLiteral("chamfer")};
    switch (index.column()) {
    case Number:
        if (!toNumber(value, 1, number))
            return false;
        t.number = static_cast<int>(number);
        break;
    case Name:
        if (text.isEmpty())
            return false;
        t.name = text.toStdString();
        break;
    case Kind:
        if (!kinds.contains(text))
            return false;
        t.kind = text.toStdString();
        break;
    case Diameter:
        number = t.diameterMm;
        if (!fromShown(value, 0, number) || number <= 0)
            return false;
        t.diameterMm = number;
        break;
    case CornerRadius:
        if (!fromShown(value, 0, t.cornerRadiusMm))
            return false;
        break;
    case FluteLength:
        if (!fromShown(value, 0, t.fluteLengthMm))
            return false;
        break;
    case Length:
        if (!fromShown(value, 0, t.lengthMm))
            return false;
        break;
    case Flutes:
        if (!toNumber(value, 1, number))
            return false;
        t.flutes = static_cast<int>(number);
        break;
    case PointAngle:
        if (!toNumber(value, 0, t.pointAngleDeg))
            return false;
        break;
    case Holder:
        t.holder = text.toStdString();
        break;
    default:
        return false;
    }
    emit dataChanged(index, index);
    emit edited();
    return true;
}

void ToolTableModel::reload()
{
    beginResetModel();
    endResetModel();
}

JobToolsModel::JobToolsModel(Workbench& workbench, QObject* parent) :
    QAbstractTableModel(parent),
    m_workbench(&workbench)
{
    auto reset = [this] {
        beginResetModel();
        endResetModel();
    };
    connect(&workbench, &Workbench::jobChanged, this, reset);
    connect(&workbench, &QObject::destroyed, this, reset);
}

int JobToolsModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() || !workbench() ? 0 : static_cast<int>(workbench()->job().tools.size());
}

int JobToolsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant JobToolsModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || !workbench() || (role != Qt::DisplayRole && role != Qt::EditRole))
        return {};
    const ops::ToolController& tc = workbench()->job().tools[index.row()];
    switch (index.column()) {
    case Number:
        return tc.tool.number;
    case Name:
        return QString::fromStdString(tc.tool.name);
    case Diameter:
        return shown(tc.tool.diameterMm);
    case Flutes:
        return tc.tool.flutes;
    case Rpm:
        return tc.spindleRpm;
    case CuttingFeed:
        return shown(tc.cuttingFeedMmPerMin);
    case PlungeFeed:
        return shown(tc.plungeFeedMmPerMin);
    case RampFeed:
        return shown(tc.rampFeedMmPerMin);
    case Materials: {
        QStringList materials;
        for (const ops::CuttingData& c : tc.cuttingData)
            materials << QString::fromStdString(c.material);
        return materials.join(QStringLiteral(", "));
    }
    default:
        return {};
    }
}

QVariant JobToolsModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Number:
        return tr("T");
    case Name:
        return tr("Name");
    case Diameter:
        return tr("D (%1)").arg(unitSymbol());
    case Flutes:
        return tr("Flutes");
    case Rpm:
        return tr("Spindle (rpm)");
    case CuttingFeed:
        return tr("Feed (%1/min)").arg(unitSymbol());
    case PlungeFeed:
        return tr("Plunge (%1/min)").arg(unitSymbol());
    case RampFeed:
        return tr("Ramp (%1/min)").arg(unitSymbol());
    case Materials:
        return tr("Cutting data for");
    default:
        return {};
    }
}

Qt::ItemFlags JobToolsModel::flags(const QModelIndex& index) const
{
    const bool editable = index.column() >= Rpm && index.column() <= RampFeed;
    return QAbstractTableModel::flags(index) | (editable ? Qt::ItemIsEditable : Qt::NoItemFlags);
}

bool JobToolsModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || !m_workbench || role != Qt::EditRole)
        return false;
    ops::ToolController tc = m_workbench->job().tools[index.row()];
    double* field = index.column() == Rpm           ? &tc.spindleRpm
                    : index.column() == CuttingFeed ? &tc.cuttingFeedMmPerMin
                    : index.column() == PlungeFeed  ? &tc.plungeFeedMmPerMin
                    : index.column() == RampFeed    ? &tc.rampFeedMmPerMin
                                                    : nullptr;
    if (!field || !(field == &tc.spindleRpm ? toNumber(value, 0, *field) : fromShown(value, 0, *field)))
        return false;
    m_workbench->updateTool(index.row(), tc);  // the job's change resets the model
    return true;
}

CuttingDataModel::CuttingDataModel(QObject* parent) : QAbstractTableModel(parent) {}

void CuttingDataModel::setTool(ops::ToolController* tool)
{
    beginResetModel();
    m_tool = tool;
    endResetModel();
}

void CuttingDataModel::addRow()
{
    if (!m_tool)
        return;
    const int row = rowCount();
    beginInsertRows({}, row, row);
    m_tool->cuttingData.push_back({tr("aluminium").toStdString(), 200, 0.05, 0, 0});
    endInsertRows();
    emit edited();
}

void CuttingDataModel::removeRow(int row)
{
    if (!m_tool || row < 0 || row >= rowCount())
        return;
    beginRemoveRows({}, row, row);
    m_tool->cuttingData.erase(m_tool->cuttingData.begin() + row);
    endRemoveRows();
    emit edited();
}

int CuttingDataModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() || !m_tool ? 0 : static_cast<int>(m_tool->cuttingData.size());
}

int CuttingDataModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant CuttingDataModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || !m_tool || (role != Qt::DisplayRole && role != Qt::EditRole))
        return {};
    const ops::CuttingData& c = m_tool->cuttingData[index.row()];
    switch (index.column()) {
    case Material:
        return QString::fromStdString(c.material);
    case Vc:
        return c.vcMPerMin;
    case Fz:
        return toDisplayUnit(c.fzMm, displayUnit());  // not rounded: hundredths of a mm are its size
    case Plunge:
        return c.plungeFraction;
    case Ramp:
        return c.rampFraction;
    default:
        return {};
    }
}

QVariant CuttingDataModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case Material:
        return tr("Material");
    case Vc:
        return tr("vc (m/min)");
    case Fz:
        return tr("fz (%1/tooth)").arg(unitSymbol());
    case Plunge:
        return tr("Plunge (× feed)");
    case Ramp:
        return tr("Ramp (× feed)");
    default:
        return {};
    }
}

Qt::ItemFlags CuttingDataModel::flags(const QModelIndex& index) const
{
    return QAbstractTableModel::flags(index) | Qt::ItemIsEditable;
}

bool CuttingDataModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || !m_tool || role != Qt::EditRole)
        return false;
    ops::CuttingData& c = m_tool->cuttingData[index.row()];
    bool ok = true;
    switch (index.column()) {
    case Material: {
        const QString text = value.toString().trimmed();
        ok = !text.isEmpty();
        if (ok)
            c.material = text.toStdString();
        break;
    }
    case Vc:
        ok = toNumber(value, 0, c.vcMPerMin);
        break;
    case Fz: {
        double fz = 0;
        ok = toNumber(value, 0, fz);
        if (ok)
            c.fzMm = fromDisplayUnit(fz, displayUnit());
        break;
    }
    case Plunge:
        ok = toNumber(value, 0, c.plungeFraction);
        break;
    case Ramp:
        ok = toNumber(value, 0, c.rampFraction);
        break;
    default:
        ok = false;
    }
    if (!ok)
        return false;
    emit dataChanged(index, index);
    emit edited();
    return true;
}

}  // namespace camwb::gui
