#include "gui/shell/PreferencesDialog.h"

#include "gui/shell/Prompter.h"
#include "kinematics/Machine.h"
#include "post/PostRegistry.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace camwb::gui {

namespace {

QComboBox* combo(QWidget* parent, const char* name)
{
    auto* box = new QComboBox(parent);
    box->setObjectName(QLatin1String(name));
    return box;
}

// Selects the entry whose data is `value`; a value the lists no longer have (a post removed
// since) is kept as an entry of its own, so OK does not change it behind the user's back.
void select(QComboBox* box, const QVariant& value)
{
    int index = box->findData(value);
    if (index < 0) {
        box->addItem(QObject::tr("%1 (not found)").arg(value.toString()), value);
        index = box->count() - 1;
    }
    box->setCurrentIndex(index);
}

}  // namespace

PreferencesDialog::PreferencesDialog(const Preferences& current, Prompter& prompter, QWidget* parent) :
    QDialog(parent),
    m_initial(current),
    m_prompter(prompter),
    m_units(combo(this, "units")),
    m_post(combo(this, "defaultPost")),
    m_machine(combo(this, "defaultMachine")),
    m_toolLibrary(new QLineEdit(this)),
    m_language(combo(this, "language")),
    m_autosave(new QSpinBox(this)),
    m_restartNotice(new QLabel(tr("The language changes when CAM Workbench is started again."), this))
{
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    setMinimumWidth(520);  // room for a tool library path

    m_units->addItem(tr("Millimetres (mm)"), static_cast<int>(LengthUnit::Millimetre));
    m_units->addItem(tr("Inches (in)"), static_cast<int>(LengthUnit::Inch));
    m_units->setToolTip(tr("How lengths are shown. Jobs and NC programs keep their own units."));
    select(m_units, static_cast<int>(current.units));
    fillPosts();
    select(m_post, current.defaultPostId);
    fillMachines();
    select(m_machine, current.defaultMachineId);
    m_toolLibrary->setObjectName(QStringLiteral("toolLibrary"));
    m_toolLibrary->setText(current.toolLibraryPath);
    m_toolLibrary->setPlaceholderText(tr("The library in the user's data folder"));
    m_language->addItem(tr("System"), static_cast<int>(Language::System));
    m_language->addItem(QStringLiteral("English"), static_cast<int>(Language::English));  // each in its own language
    m_language->addItem(QStringLiteral("Čeština"), static_cast<int>(Language::Czech));
    select(m_language, static_cast<int>(current.language));
    m_autosave->setObjectName(QStringLiteral("autosaveSeconds"));
    m_autosave->setRange(5, 3600);
    m_autosave->setSuffix(tr(" s"));
    m_autosave->setValue(current.autosaveSeconds);
    m_autosave->setToolTip(tr("How often unsaved changes are written to a side file for recovery after a crash."));
    m_restartNotice->setObjectName(QStringLiteral("restartNotice"));
    m_restartNotice->setVisible(false);
    connect(m_language, &QComboBox::currentIndexChanged, this,
            [this] { m_restartNotice->setVisible(preferences().language != m_initial.language); });

    auto* form = new QFormLayout;
    form->addRow(tr("&Display units:"), m_units);
    form->addRow(tr("Default &post:"), m_post);
    form->addRow(tr("Default &machine:"), m_machine);
    form->addRow(tr("&Tool library:"), toolLibraryRow());
    form->addRow(tr("&Language:"), m_language);
    form->addRow(tr("&Autosave every:"), m_autosave);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_restartNotice);
    layout->addStretch();
    layout->addWidget(buttons);
}

QWidget* PreferencesDialog::toolLibraryRow()
{
    auto* row = new QWidget(this);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* browse = new QPushButton(tr("&Browse…"), row);
    browse->setObjectName(QStringLiteral("browseToolLibrary"));
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString path = m_prompter.openFileName(tr("Tool library"), tr("Tool libraries (*.json);;All files (*)"));
        if (!path.isEmpty())
            m_toolLibrary->setText(path);
    });
    layout->addWidget(m_toolLibrary, 1);
    layout->addWidget(browse);
    return row;
}

void PreferencesDialog::fillPosts()
{
    m_post->addItem(tr("(the built-in default)"), QString());
    for (const post::PostEntry& entry : post::listPosts(post::defaultPostDirs()))
        m_post->addItem(QString::fromStdString(entry.id), QString::fromStdString(entry.id));
}

void PreferencesDialog::fillMachines()
{
    m_machine->addItem(tr("(the post's default machine)"), QString());
    for (const base::DataFile& file : kinematics::listMachineFiles())
        m_machine->addItem(QString::fromStdString(file.id), QString::fromStdString(file.id));
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.units = static_cast<LengthUnit>(m_units->currentData().toInt());
    p.defaultPostId = m_post->currentData().toString();
    p.defaultMachineId = m_machine->currentData().toString();
    p.toolLibraryPath = m_toolLibrary->text().trimmed();
    p.language = static_cast<Language>(m_language->currentData().toInt());
    p.autosaveSeconds = m_autosave->value();
    return p;
}

}  // namespace camwb::gui
