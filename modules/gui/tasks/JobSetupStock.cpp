// The job setup panel's stock group (JobSetupPanel.h): a box or a cylinder from the model's bounds
// with offsets or of an explicit size, or a blank (a cast or forged part) from a mesh or STEP file.
#include "gui/tasks/JobSetupPanel.h"

#include "document/JobSetup.h"
#include "document/StockBlank.h"
#include "gui/shell/Preferences.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/detail/JobSetupFields.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

#include <cmath>

namespace camwb::gui {

using namespace jobsetup;
using Shape = document::Stock::Shape;

namespace {

// The shape combo's rows.
constexpr int kBoxRow = 0, kCylinderRow = 1, kBlankRow = 2;

// A coordinate as the summary shows it: a blank's meshed bounds give -1.8e-15 for 0.
double shown(double mm) { return std::abs(mm) < 5e-7 ? 0.0 : mm; }
// A length of the summary in the display unit, as short as it is exact to a micrometre.
QString inUnit(double mm) { return QString::number(toDisplayUnit(shown(mm), displayUnit()), 'g', 6); }

int rowOf(Shape shape) { return shape == Shape::Cylinder ? kCylinderRow : shape == Shape::Blank ? kBlankRow : kBoxRow; }

}  // namespace

QWidget* JobSetupPanel::buildStock()
{
    auto* widget = new QWidget;
    auto* form = new QFormLayout(widget);
    m_stockShape = new QComboBox;
    m_stockShape->setObjectName(QStringLiteral("stockShape"));
    m_stockShape->addItem(tr("Box"));
    m_stockShape->addItem(tr("Cylinder (along Z)"));
    m_stockShape->addItem(tr("Blank from file…"));
    m_stockShape->setItemData(kBlankRow,
                              tr("A cast or forged blank: a STEP, IGES, BREP or STL file in the model's coordinates"),
                              Qt::ToolTipRole);
    form->addRow(tr("Shape"), m_stockShape);
    m_stockSize = new QComboBox;
    m_stockSize->setObjectName(QStringLiteral("stockSize"));
    m_stockSize->addItem(tr("Model bounds + offsets"));
    m_stockSize->addItem(tr("Explicit size"));
    form->addRow(tr("Size"), m_stockSize);

    m_blankRow = new QWidget;
    auto* blankLayout = new QHBoxLayout(m_blankRow);
    blankLayout->setContentsMargins(0, 0, 0, 0);
    m_blankLabel = new QLabel;
    m_blankLabel->setObjectName(QStringLiteral("blankLabel"));
    m_blankLabel->setWordWrap(true);
    auto* choose = new QPushButton(tr("Choose…"));
    choose->setObjectName(QStringLiteral("blankButton"));
    choose->setToolTip(tr("Choose the blank's file"));
    blankLayout->addWidget(m_blankLabel, 1);
    blankLayout->addWidget(choose);
    form->addRow(tr("Blank"), m_blankRow);
    m_blankError = warningLabel("blankError");
    form->addRow(m_blankError);

    m_below = vec3Fields("stockBelow", 0, 1000);
    m_above = vec3Fields("stockAbove", 0, 1000);
    m_offsetRows = axisGrid({{tr("Below min"), m_below}, {tr("Above max"), m_above}});
    form->addRow(m_offsetRows);
    m_min = vec3Fields("stockMin", -10000, 10000);
    m_max = vec3Fields("stockMax", -10000, 10000);
    m_explicitRows = axisGrid({{tr("Min"), m_min}, {tr("Max"), m_max}});
    form->addRow(m_explicitRows);
    m_stockSummary = new QLabel;
    m_stockSummary->setObjectName(QStringLiteral("stockSummary"));
    m_stockSummary->setWordWrap(true);
    form->addRow(m_stockSummary);
    m_stockError = warningLabel("stockError");
    form->addRow(m_stockError);

    connect(choose, &QPushButton::clicked, this, &JobSetupPanel::chooseBlankFile);
    connect(m_stockShape, &QComboBox::currentIndexChanged, this, [this](int row) {
        // A blank needs its file first: choosing the row asks for it (the panel's fields stay
        // as they were when none is chosen).
        if (!m_showing && row == kBlankRow && m_setup.stock.shape != Shape::Blank) {
            chooseBlankFile();
            return;
        }
        stockEdited();
    });
    connect(m_stockSize, &QComboBox::currentIndexChanged, this, &JobSetupPanel::stockEdited);
    for (const Vec3Fields* fields : {&m_below, &m_above, &m_min, &m_max})
        for (QDoubleSpinBox* spin : *fields)
            connect(spin, &QDoubleSpinBox::valueChanged, this, &JobSetupPanel::stockEdited);
    return widget;
}

bool JobSetupPanel::modelBounds(base::Vec3& min, base::Vec3& max) const
{
    const occ::Model& model = m_workbench.model();
    if (model.empty())
        return false;
    min = model.boundsMin() + m_workbench.modelOrigin();
    max = model.boundsMax() + m_workbench.modelOrigin();
    return true;
}

void JobSetupPanel::resolveStock()
{
    base::Vec3 min, max;
    if (modelBounds(min, max))
        m_setup.stock.resolve(min - m_setup.origin, max - m_setup.origin);
}

void JobSetupPanel::stockEdited()
{
    if (m_showing)
        return;
    document::Stock& stock = m_setup.stock;
    const int row = m_stockShape->currentIndex();
    if (row == kBlankRow)
        return;  // a blank's size is its file's (setBlankFile)
    stock.shape = row == kCylinderRow ? Shape::Cylinder : Shape::Box;
    stock.blankPath.clear();
    m_blankError->hide();
    if (m_stockSize->currentIndex() == 0) {
        stock.fromModel = document::StockFromModel{valueOf(m_below), valueOf(m_above)};
        resolveStock();
    } else {
        stock.fromModel.reset();
        stock.min = valueOf(m_min);
        stock.max = valueOf(m_max);
        if (stock.shape == Shape::Cylinder) {
            // Round: the diameter is the x size, about the y centre.
            const double cy = (stock.min.y + stock.max.y) / 2, r = (stock.max.x - stock.min.x) / 2;
            stock.min.y = cy - r;
            stock.max.y = cy + r;
        }
    }
    stockMoved();
}

// An origin on a stock point follows the stock.
void JobSetupPanel::stockMoved()
{
    if (const int anchor = m_originAnchor->currentIndex(); anchor > 0 && anchor < kPickedVertex)
        moveOrigin(document::stockAnchor(m_setup.stock, kAnchors[anchor - 1]));
    showValues();
}

void JobSetupPanel::chooseBlankFile()
{
    const QString start =
        m_setup.stock.blankPath.empty() ? QFileInfo(qs(m_setup.modelPath)).absolutePath() : qs(m_setup.stock.blankPath);
    const QString path = QFileDialog::getOpenFileName(this, tr("Blank from file"), start,
                                                      tr("Models (*.step *.stp *.iges *.igs *.brep *.brp *.stl)"));
    if (path.isEmpty() || !setBlankFile(path))
        showValues();  // the shape shown goes back to the stock's
}

bool JobSetupPanel::setBlankFile(const QString& path)
{
    document::Job probe = m_setup;
    probe.stock.shape = Shape::Blank;
    probe.stock.blankPath = QFileInfo(path).absoluteFilePath().toStdString();
    probe.stock.fromModel.reset();
    QApplication::setOverrideCursor(Qt::WaitCursor);
    auto blank = document::loadStockBlank(probe, m_workbench.document().path());
    QApplication::restoreOverrideCursor();
    if (!blank) {
        m_blankError->setText(tr("The blank cannot be used: %1").arg(qs(blank.error().toString())));
        m_blankError->show();
        return false;
    }
    m_blankError->hide();
    document::resolveStockBlank(probe.stock, blank.value());
    m_setup.stock = probe.stock;
    stockMoved();
    return true;
}

void JobSetupPanel::showStock()
{
    const document::Stock& stock = m_setup.stock;
    const bool fromModel = stock.fromModel.has_value();
    const bool blank = stock.shape == Shape::Blank;
    m_stockShape->setCurrentIndex(rowOf(stock.shape));
    m_stockSize->setCurrentIndex(fromModel ? 0 : 1);
    if (fromModel) {
        showVec3(m_below, stock.fromModel->below);
        showVec3(m_above, stock.fromModel->above);
    }
    showVec3(m_min, stock.min);
    showVec3(m_max, stock.max);
    m_stockSize->setEnabled(!blank);
    // The row with its "Blank" label: hiding the field alone would leave the label standing.
    if (auto* form = qobject_cast<QFormLayout*>(m_blankRow->parentWidget()->layout()))
        form->setRowVisible(m_blankRow, blank);
    m_blankLabel->setText(QFileInfo(qs(stock.blankPath)).fileName());
    m_blankLabel->setToolTip(qs(stock.blankPath));
    m_offsetRows->setVisible(fromModel && !blank);
    m_explicitRows->setVisible(!fromModel && !blank);
    const base::Vec3 size = stock.max - stock.min;
    if (stock.shape == Shape::Cylinder)
        m_stockSummary->setText(
            tr("Ø%1 × %2 %5, from Z %3 to %4")
                .arg(inUnit(size.x), inUnit(size.z), inUnit(stock.min.z), inUnit(stock.max.z), unitSymbol()));
    else
        m_stockSummary->setText((blank ? tr("Blank in a box of %1 × %2 × %3 %7, from (%4, %5, %6)")
                                       : tr("%1 × %2 × %3 %7, from (%4, %5, %6)"))
                                    .arg(inUnit(size.x), inUnit(size.y), inUnit(size.z), inUnit(stock.min.x),
                                         inUnit(stock.min.y), inUnit(stock.min.z), unitSymbol()));
    // What OK refuses (the job file would not load with it), said while it is typed.
    const std::optional<std::string> problem = document::stockProblem(stock);
    m_stockError->setText(problem ? tr("The stock cannot be used: %1").arg(qs(*problem)) : QString());
    m_stockError->setVisible(problem.has_value());
}

}  // namespace camwb::gui
