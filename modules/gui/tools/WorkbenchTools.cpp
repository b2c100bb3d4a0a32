// The Workbench's tools from a tool library: adding them to the job, the job's stock material,
// computing their speeds and feeds from their cutting data and editing them by hand, each one
// undoable step. The kernel does the work (document/ToolLibrary.h, document/CuttingData.h).
#include "document/CuttingData.h"
#include "document/ToolLibrary.h"
#include "gui/shell/Workbench.h"
#include "kinematics/Machine.h"

namespace camwb::gui {

namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

}  // namespace

void Workbench::addTools(const std::vector<ops::ToolController>& tools)
{
    if (tools.empty())
        return;
    std::vector<std::string> notes;
    const std::string text = tools.size() == 1 ? "Add tool " + tools.front().tool.name : "Add tools";
    m_document.edit(text, [&](document::Job& j) { notes = document::addToolsToJob(j, tools); });
    for (const std::string& note : notes)
        report(Severity::Warning, qs(note));
}

bool Workbench::computeFeeds(int number)
{
    document::Job edited = job();
    auto notes = document::computeJobFeeds(edited, number, m_machine.get());
    if (!notes) {
        fail(tr("Compute feeds and speeds"), qs(notes.error().message));
        return false;
    }
    m_document.edit("Compute feeds and speeds", [&](document::Job& j) { j = edited; });
    for (const std::string& note : notes.value())
        report(Severity::Warning, qs(note));
    return true;
}

void Workbench::updateTool(int index, const ops::ToolController& tool)
{
    if (index < 0 || index >= static_cast<int>(job().tools.size()))
        return;
    document::Job edited = job();
    edited.tools[index] = tool;
    m_document.replace("Edit tool " + tool.tool.name, std::move(edited));
}

void Workbench::setMaterial(const std::string& material)
{
    if (material != job().material)
        m_document.edit("Set material " + material, [&](document::Job& j) { j.material = material; });
}

}  // namespace camwb::gui
