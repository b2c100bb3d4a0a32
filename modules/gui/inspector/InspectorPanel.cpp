#include "gui/inspector/InspectorPanel.h"

#include "gui/inspector/ModalStatePanel.h"

#include <QComboBox>
#include <QFormLayout>
#include <QListWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace camwb::gui {

InspectorPanel::InspectorPanel(QWidget* parent) :
    QWidget(parent),
    m_dialect(new QComboBox(this)),
    m_source(new QComboBox(this)),
    m_tools(new QListWidget(this)),
    m_machine(new QComboBox(this)),
    m_modal(new ModalStatePanel(this))
{
    m_dialect->setObjectName(QStringLiteral("dialectCombo"));
    m_dialect->addItem(tr("Automatic"), -1);
    m_dialect->addItem(tr("SINUMERIK"), static_cast<int>(nc::Dialect::Sinumerik));
    m_dialect->addItem(tr("Heidenhain Klartext"), static_cast<int>(nc::Dialect::Heidenhain));
    m_dialect->addItem(tr("ISO (LinuxCNC, Fanuc)"), static_cast<int>(nc::Dialect::Iso));
    m_source->setObjectName(QStringLiteral("backplotCombo"));
    m_source->addItem(tr("NC program (traced)"));
    m_source->addItem(tr("Operations' toolpath"));
    m_tools->setObjectName(QStringLiteral("toolList"));
    m_tools->setMaximumHeight(64);
    m_modal->setObjectName(QStringLiteral("modalStatePanel"));
    m_machine->setObjectName(QStringLiteral("machineCombo"));
    m_machine->setToolTip(tr("The machine the program is traced on: its limits are checked, and five-axis "
                             "NC (M128, TRAORI, B and C words) is read through its kinematics"));
    setMachines({});

    auto* form = new QFormLayout;
    form->addRow(tr("Dialect"), m_dialect);
    form->addRow(tr("3D shows"), m_source);
    form->addRow(tr("Tools"), m_tools);
    form->addRow(tr("Machine"), m_machine);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(form);
    layout->addWidget(m_modal, 1);

    connect(m_dialect, &QComboBox::currentIndexChanged, this, [this] { emit dialectChosen(dialect()); });
    connect(m_machine, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_filling)
            emit machineChosen(machineId());
    });
    connect(m_source, &QComboBox::currentIndexChanged, this, [this] { emit showNcTraceChosen(showsNcTrace()); });
    connect(m_tools, &QListWidget::itemChanged, this, [this](QListWidgetItem* item) {
        if (!m_filling)
            emit toolVisibilityChanged(item->data(Qt::UserRole).toInt(), item->checkState() == Qt::Checked);
    });
}

std::optional<nc::Dialect> InspectorPanel::dialect() const
{
    const int value = m_dialect->currentData().toInt();
    if (value < 0)
        return std::nullopt;
    return static_cast<nc::Dialect>(value);
}

void InspectorPanel::setDialect(std::optional<nc::Dialect> dialect)
{
    m_dialect->setCurrentIndex(m_dialect->findData(dialect ? static_cast<int>(*dialect) : -1));
}

void InspectorPanel::setMachines(const std::vector<std::pair<QString, QString>>& machines)
{
    const QString kept = machineId();
    m_filling = true;
    m_machine->clear();
    m_machine->addItem(tr("None: no limits checked, three axes"), QString());
    for (const auto& [id, name] : machines)
        m_machine->addItem(name == id ? id : tr("%1 (%2)").arg(name, id), id);
    m_filling = false;
    setMachineId(kept);
}

void InspectorPanel::setMachineId(const QString& id)
{
    m_filling = true;
    int index = m_machine->findData(id);
    if (index < 0 && !id.isEmpty()) {  // a job's machine from a file outside the folders
        m_machine->addItem(id, id);
        index = m_machine->count() - 1;
    }
    m_machine->setCurrentIndex(std::max(index, 0));
    m_filling = false;
}

QString InspectorPanel::machineId() const { return m_machine->currentData().toString(); }

bool InspectorPanel::showsNcTrace() const { return m_source->currentIndex() == 0; }

void InspectorPanel::setShowsNcTrace(bool show) { m_source->setCurrentIndex(show ? 0 : 1); }

void InspectorPanel::setTools(const std::vector<int>& tools, const std::vector<int>& hidden)
{
    m_filling = true;
    m_tools->clear();
    for (int tool : tools) {
        auto* item = new QListWidgetItem(tool > 0 ? tr("T%1").arg(tool) : tr("before the first tool"), m_tools);
        item->setData(Qt::UserRole, tool);
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        const bool isHidden = std::find(hidden.begin(), hidden.end(), tool) != hidden.end();
        item->setCheckState(isHidden ? Qt::Unchecked : Qt::Checked);
    }
    m_filling = false;
}

void InspectorPanel::setToolChecked(int tool, bool checked)
{
    for (int i = 0; i < m_tools->count(); ++i)
        if (m_tools->item(i)->data(Qt::UserRole).toInt() == tool)
            m_tools->item(i)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

}  // namespace camwb::gui
