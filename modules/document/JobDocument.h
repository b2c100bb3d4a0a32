// A job being edited: the Job, its file path and its undo stack. Every change goes through
// edit(), which records one undoable step (one user gesture), and notifies the listener.
#pragma once

#include "base/Result.h"
#include "document/Job.h"
#include "document/UndoStack.h"

#include <functional>
#include <string>

namespace camwb::document {

class JobDocument {
public:
    const Job& job() const { return m_job; }
    const std::string& path() const { return m_path; }
    UndoStack& undoStack() { return m_undo; }
    bool isModified() const { return !m_undo.isClean(); }

    // Replaces the whole job (open/new): clears the undo history.
    void reset(Job job, std::string path);
    // One undoable edit named `text`; `change` modifies a copy of the job.
    void edit(const std::string& text, const std::function<void(Job&)>& change);
    // `after` as one undoable edit named `text`, unless it is the job as it is (as the file would
    // hold it): then no step, and false. For edits built on a copy (OK of a panel, a switch of post).
    bool replace(const std::string& text, Job after);
    void undo();
    void redo();
    // Writes atomically; on success the path becomes `path` and the document is clean.
    base::Status saveAs(const std::string& path);

    // Called after every change of the job (edit, undo, redo, reset).
    void setChangedListener(std::function<void()> listener) { m_listener = std::move(listener); }

private:
    friend class JobSnapshotCommand;
    void assign(const Job& job);

    Job m_job;
    std::string m_path;
    UndoStack m_undo;
    std::function<void()> m_listener;
};

}  // namespace camwb::document
