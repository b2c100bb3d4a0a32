#include "gui/editor/RenumberDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>
#include <QVBoxLayout>

namespace camwb::gui {

RenumberDialog::RenumberDialog(nc::Dialect dialect, QWidget* parent) : QDialog(parent), m_dialect(dialect)
{
    setObjectName(QStringLiteral("renumberDialog"));
    setWindowTitle(tr("Renumber Blocks"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    m_start = new QSpinBox(this);
    m_start->setObjectName(QStringLiteral("renumberStart"));
    m_start->setRange(0, 999'999'999);
    m_step = new QSpinBox(this);
    m_step->setObjectName(QStringLiteral("renumberStep"));
    m_step->setRange(1, 100'000);
    form->addRow(tr("&Start at:"), m_start);
    form->addRow(tr("S&tep:"), m_step);
    layout->addLayout(form);
    m_commentLines = new QCheckBox(tr("Number &comment-only lines"), this);
    m_commentLines->setObjectName(QStringLiteral("renumberCommentLines"));
    m_emptyLines = new QCheckBox(tr("Number &empty lines"), this);
    m_emptyLines->setObjectName(QStringLiteral("renumberEmptyLines"));
    m_keepExisting = new QCheckBox(tr("&Keep existing numbers, number only blocks without one"), this);
    m_keepExisting->setObjectName(QStringLiteral("renumberKeepExisting"));
    m_onlyNumbered = new QCheckBox(tr("Renumber &only blocks that have a number"), this);
    m_onlyNumbered->setObjectName(QStringLiteral("renumberOnlyNumbered"));
    for (QCheckBox* box : {m_commentLines, m_emptyLines, m_keepExisting, m_onlyNumbered})
        layout->addWidget(box);
    // The two are opposites: keeping every number while touching only numbered blocks does nothing.
    connect(m_keepExisting, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            m_onlyNumbered->setChecked(false);
    });
    connect(m_onlyNumbered, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            m_keepExisting->setChecked(false);
    });
    auto* note = new QLabel(this);
    note->setWordWrap(true);
    if (dialect == nc::Dialect::Heidenhain) {
        note->setText(tr("Heidenhain Klartext blocks are always numbered 0, 1, 2, … on every line "
                         "(continuation lines excepted)."));
        for (QWidget* w : std::initializer_list<QWidget*>{m_start, m_step, m_commentLines, m_emptyLines, m_keepExisting,
                                                          m_onlyNumbered})
            w->setEnabled(false);
    } else {
        note->setText(tr("Jump targets (GOTOF N100, GOTO 100) follow their blocks. Labels, comments and "
                         "strings are left as they are."));
    }
    layout->addWidget(note);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);

    nc::RenumberOptions defaults;
    if (dialect == nc::Dialect::Heidenhain) {
        defaults.start = 0;
        defaults.step = 1;
    }
    setOptions(defaults);
}

void RenumberDialog::setOptions(const nc::RenumberOptions& options)
{
    m_start->setValue(static_cast<int>(std::min<long long>(options.start, m_start->maximum())));
    m_step->setValue(static_cast<int>(std::min<long long>(options.step, m_step->maximum())));
    m_commentLines->setChecked(options.numberCommentLines);
    m_emptyLines->setChecked(options.numberEmptyLines);
    m_keepExisting->setChecked(!options.replaceExisting);
    m_onlyNumbered->setChecked(options.onlyNumbered);
}

nc::RenumberOptions RenumberDialog::options() const
{
    nc::RenumberOptions options;
    options.dialect = m_dialect;
    options.start = m_start->value();
    options.step = m_step->value();
    options.numberCommentLines = m_commentLines->isChecked();
    options.numberEmptyLines = m_emptyLines->isChecked();
    options.replaceExisting = !m_keepExisting->isChecked();
    options.onlyNumbered = m_onlyNumbered->isChecked();
    return options;
}

}  // namespace camwb::gui
