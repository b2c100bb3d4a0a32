#include "document/JobDocument.h"

#include "document/JobFile.h"

namespace camwb::document {

// Jobs are small, so a command stores the job before and after: simple and always exact.
class JobSnapshotCommand : public UndoCommand {
public:
    JobSnapshotCommand(JobDocument& document, std::string text, Job before, Job after) :
        m_document(document),
        m_text(std::move(text)),
        m_before(std::move(before)),
        m_after(std::move(after))
    {
    }
    void redo() override { m_document.assign(m_after); }
    void undo() override { m_document.assign(m_before); }
    std::string text() const override { return m_text; }

private:
    JobDocument& m_document;
    std::string m_text;
    Job m_before;
    Job m_after;
};

void JobDocument::reset(Job job, std::string path)
{
    m_path = std::move(path);
    m_undo.clear();
    assign(job);
}

void JobDocument::edit(const std::string& text, const std::function<void(Job&)>& change)
{
    Job after = m_job;
    change(after);
    m_undo.push(std::make_unique<JobSnapshotCommand>(*this, text, m_job, std::move(after)));
}

bool JobDocument::replace(const std::string& text, Job after)
{
    if (serializeJob(after) == serializeJob(m_job))
        return false;
    m_undo.push(std::make_unique<JobSnapshotCommand>(*this, text, m_job, std::move(after)));
    return true;
}

void JobDocument::undo() { m_undo.undo(); }
void JobDocument::redo() { m_undo.redo(); }

base::Status JobDocument::saveAs(const std::string& path)
{
    if (base::Status saved = saveJob(m_job, path); !saved)
        return saved;
    m_path = path;
    m_undo.setClean();
    if (m_listener)
        m_listener();
    return {};
}

void JobDocument::assign(const Job& job)
{
    m_job = job;
    if (m_listener)
        m_listener();
}

}  // namespace camwb::document
