// The post settings dialog: which posts are offered for the job's machine, what a change of post
// keeps of the values in the form (post::switchPost, shown before OK), and one undo step on OK.
#include "gui/tasks/PostSettingsPanel.h"

#include "document/JobPipeline.h"
#include "gui/actions/ActionRegistry.h"
#include "gui/shell/Workbench.h"
#include "gui/tasks/PostPropertiesForm.h"
#include "post/PostProcessor.h"
#include "post/PostRegistry.h"
#include "post/PostSwitch.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

namespace camwb::gui {

namespace {

QString q(const std::string& text) { return QString::fromStdString(text); }

}  // namespace

PostSettingsPanel::PostSettingsPanel(Workbench& workbench, QWidget* parent) : QDialog(parent), m_workbench(workbench)
{
    setWindowTitle(tr("Post and Properties"));
    setObjectName(QStringLiteral("postSettingsPanel"));
    const document::Job& job = workbench.job();
    for (const post::PostEntry& entry : post::listPosts(post::defaultPostDirs()))
        if (auto loaded = post::PostProcessor::load(entry.path))
            m_all.push_back(loaded->info());
    const post::PostInfo* current = info(q(job.postId));
    const std::string machineId = !job.machineId.empty() ? job.machineId : current ? current->defaultMachine : "";
    if (!machineId.empty())
        if (auto found = kinematics::findMachine(machineId, kinematics::defaultMachineDirs()))
            m_jobMachine = std::move(found).value();

    auto* layout = new QVBoxLayout(this);
    auto* top = new QFormLayout;
    m_machineNote = new QLabel(this);
    m_machineNote->setObjectName(QStringLiteral("machineNote"));
    top->addRow(tr("Machine:"), m_machineNote);
    m_posts = new QComboBox(this);
    m_posts->setObjectName(QStringLiteral("postCombo"));
    top->addRow(tr("&Post:"), m_posts);
    m_showAll = new QCheckBox(tr("Show &all posts, not only those for the job's machine"), this);
    m_showAll->setObjectName(QStringLiteral("showAllPosts"));
    m_showAll->setEnabled(m_jobMachine.has_value());
    top->addRow(QString(), m_showAll);
    layout->addLayout(top);

    m_dropped = new QLabel(this);
    m_dropped->setObjectName(QStringLiteral("droppedNote"));
    m_dropped->setWordWrap(true);
    m_dropped->hide();
    layout->addWidget(m_dropped);

    m_form = new PostPropertiesForm;
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_form);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    layout->addWidget(scroll, 1);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &PostSettingsPanel::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &PostSettingsPanel::reject);
    layout->addWidget(buttons);

    if (current) {
        m_form->setPost(*current, job.postProperties);
        showMachine(*current);
    } else {
        m_dropped->setText(tr("The job's post %1 cannot be loaded: choose another.").arg(q(job.postId)));
        m_dropped->show();
    }
    fillPosts(q(job.postId));
    connect(m_posts, &QComboBox::currentIndexChanged, this, &PostSettingsPanel::postChosen);
    connect(m_showAll, &QCheckBox::toggled, this, [this] { fillPosts(m_posts->currentData().toString()); });
    resize(680, 700);
}

const post::PostInfo* PostSettingsPanel::info(const QString& id) const
{
    for (const post::PostInfo& candidate : m_all)
        if (q(candidate.id) == id)
            return &candidate;
    return nullptr;
}

QStringList PostSettingsPanel::offeredPosts() const
{
    QStringList ids;
    for (int i = 0; i < m_posts->count(); ++i)
        ids << m_posts->itemData(i).toString();
    return ids;
}

// The posts that serve the job's machine (all with "Show all posts"), and `keep` in any case, so
// that the combo never changes the chosen post by itself.
void PostSettingsPanel::fillPosts(const QString& keep)
{
    const QSignalBlocker quiet(m_posts);
    m_posts->clear();
    for (const post::PostInfo& candidate : m_all) {
        const bool serves = !m_jobMachine || post::servesMachine(candidate, *m_jobMachine);
        if (!serves && !m_showAll->isChecked() && q(candidate.id) != keep)
            continue;
        QString text = q(candidate.id) + QStringLiteral(" — ") + q(candidate.description);
        if (!serves)
            text += tr(" (not for this machine)");
        m_posts->addItem(text, q(candidate.id));
    }
    m_posts->setCurrentIndex(m_posts->findData(keep));
}

bool PostSettingsPanel::choosePost(const QString& id)
{
    if (!info(id))
        return false;
    if (m_posts->findData(id) < 0)
        m_showAll->setChecked(true);
    m_posts->setCurrentIndex(m_posts->findData(id));
    return m_posts->currentData().toString() == id;
}

// The form follows the chosen post with the values it can keep; the note names those it cannot.
void PostSettingsPanel::postChosen()
{
    const post::PostInfo* chosen = info(m_posts->currentData().toString());
    if (!chosen)
        return;
    const post::PostSwitch moved = post::switchPost(m_form->values(), m_form->post(), *chosen);
    m_form->setPost(*chosen, moved.kept);
    QStringList lines;
    for (const post::DroppedProperty& dropped : moved.dropped)
        lines << tr("%1 = %2 is dropped: %3").arg(q(dropped.name), q(dropped.value), q(dropped.reason));
    m_dropped->setText(lines.join(QLatin1Char('\n')));
    m_dropped->setVisible(!lines.isEmpty());
    showMachine(*chosen);
}

// The machine the job is posted for with `chosen`: its own, unless the post cannot drive it (then,
// as with no machine of its own, the post's default; Workbench::setPost does the same).
void PostSettingsPanel::showMachine(const post::PostInfo& chosen)
{
    const std::string& own = m_workbench.job().machineId;
    const bool keeps = !own.empty() && (!m_jobMachine || post::servesMachine(chosen, *m_jobMachine));
    const QString machine = keeps ? q(own) : q(chosen.defaultMachine);
    QString text = machine.isEmpty() ? tr("none (the post's machine limits are not checked)") : machine;
    if (keeps && m_jobMachine)
        text += tr(" (control %1)").arg(q(m_jobMachine->control));
    else if (!machine.isEmpty())
        text += tr(" (the post's default machine)");
    m_machineNote->setText(text);
}

void PostSettingsPanel::accept()
{
    const QString id = m_posts->currentData().toString();
    if (id.isEmpty())
        return;
    if (id.toStdString() == m_workbench.job().postId)
        m_workbench.setPostProperties(m_form->values());
    else if (!m_workbench.setPost(id.toStdString(), std::nullopt, m_form->values()))
        return;  // the reason is shown; the dialog stays open
    QDialog::accept();
}

namespace {

class Tr {
    Q_DECLARE_TR_FUNCTIONS(PostSettingsActions)
};

}  // namespace

void registerPostSettingsActions(ActionRegistry& registry, Workbench* workbench, QWidget* parent)
{
    QAction* action = registry.add({"Cam.Job.PostSettings",
                                    Tr::tr("Post && &Properties…"),
                                    Tr::tr("&Job"),
                                    {},
                                    false,
                                    false,
                                    Tr::tr("Choose the job's post and set its properties")});
    QObject::connect(action, &QAction::triggered, parent, [workbench, parent] {
        auto* panel = new PostSettingsPanel(*workbench, parent);
        panel->setAttribute(Qt::WA_DeleteOnClose);
        panel->open();
    });
}

}  // namespace camwb::gui
