// The Workbench's post choice per job: its property values and a change of post, each one
// undoable step. A change of post keeps only the values the new post takes (post::switchPost) and
// says which it dropped, so a job never carries a value the new post would refuse at run time.
#include "document/JobFile.h"
#include "document/JobPipeline.h"
#include "gui/shell/Workbench.h"
#include "kinematics/Machine.h"
#include "post/PostRegistry.h"
#include "post/PostSwitch.h"

namespace camwb::gui {

namespace {

QString q(const std::string& text) { return QString::fromStdString(text); }

// The declarations of post `id` (the job's post folders), or the load error.
base::Result<post::PostInfo> loadPostInfo(const std::string& id)
{
    document::Job probe;
    probe.postId = id;
    auto loaded = document::loadJobPost(probe, post::defaultPostDirs());
    if (!loaded)
        return loaded.error();
    return loaded->info();
}

}  // namespace

void Workbench::setPostProperties(const std::map<std::string, std::string>& values)
{
    if (values == job().postProperties)
        return;  // no empty undo step
    m_document.edit("Post properties", [&](document::Job& j) { j.postProperties = values; });
}

bool Workbench::setPost(const std::string& postId, const std::optional<std::string>& machineId,
                        const std::optional<std::map<std::string, std::string>>& values)
{
    document::Job edited = job();
    std::vector<QString> notes;
    if (!switchPostIn(edited, postId, machineId, values, notes))
        return false;
    if (!m_document.replace("Post", std::move(edited)))
        return true;  // no empty undo step
    for (const QString& note : notes)
        report(Severity::Warning, note);
    return true;
}

bool Workbench::switchPostIn(document::Job& edited, const std::string& postId,
                             const std::optional<std::string>& machineId,
                             const std::optional<std::map<std::string, std::string>>& values,
                             std::vector<QString>& notes)
{
    auto target = loadPostInfo(postId);
    if (!target) {
        fail(tr("Post"), tr("The post %1 cannot be used: %2").arg(q(postId), q(target.error().toString())));
        return false;
    }
    const post::PostInfo& to = target.value();
    // A current post that no longer loads has no definitions to compare types with: the new post decides.
    post::PostInfo from;
    from.id = edited.postId;
    if (auto current = loadPostInfo(edited.postId))
        from = std::move(current).value();

    const post::PostSwitch moved = post::switchPost(edited.postProperties, from, to);
    edited.postId = postId;
    edited.postProperties = values ? *values : moved.kept;
    for (const post::DroppedProperty& dropped : moved.dropped)
        if (!values || !values->count(dropped.name))
            notes.push_back(tr("Post %1 does not keep property %2 = %3: %4")
                                .arg(q(postId), q(dropped.name), q(dropped.value), q(dropped.reason)));
    for (document::Operation& operation : edited.operations) {
        const post::PostSwitch own = post::switchPost(operation.postProperties, from, to, true);
        operation.postProperties = own.kept;
        for (const post::DroppedProperty& dropped : own.dropped)
            notes.push_back(tr("Operation %1 loses its property %2 = %3: %4")
                                .arg(q(operation.name()), q(dropped.name), q(dropped.value), q(dropped.reason)));
    }
    if (machineId) {
        edited.machineId = *machineId;
    } else if (!edited.machineId.empty()) {
        // The job's machine stays unless the new post cannot drive it (the run would be refused).
        auto machine = kinematics::findMachine(edited.machineId, kinematics::defaultMachineDirs());
        if (machine && !post::servesMachine(to, machine.value())) {
            notes.push_back(
                tr("Post %1 does not drive machine %2: the job now uses the post's default machine%3")
                    .arg(q(postId), q(edited.machineId),
                         to.defaultMachine.empty() ? QString() : QStringLiteral(" ") + q(to.defaultMachine)));
            edited.machineId.clear();
        }
    }
    return true;
}

}  // namespace camwb::gui
