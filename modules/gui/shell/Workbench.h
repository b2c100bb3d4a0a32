// The GUI's controller: owns the job document, the loaded model and the derived toolpath and
// NC. Long work (model import, compute + post) runs on a worker thread; results come back as
// signals. No widgets here, so every action can be driven and tested without a window.
#pragma once

#include "base/Diagnostic.h"
#include "document/JobDocument.h"
#include "nc/ToolTable.h"
#include "occ/DisplayMesh.h"
#include "occ/Model.h"
#include "post/PostProcessor.h"
#include "sim/TriangleMesh.h"
#include "toolpath/Toolpath.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace camwb::gui {

class Prompter;

class Workbench : public QObject {
    Q_OBJECT
public:
    using Severity = base::Severity;

    explicit Workbench(QObject* parent = nullptr);
    ~Workbench() override;

    document::JobDocument& document() { return m_document; }
    const document::Job& job() const { return m_document.job(); }
    const occ::Model& model() const { return m_model; }
    // The job origin model() is moved by (it is in work coordinates; its file's coordinates are
    // model() + modelOrigin()).
    const base::Vec3& modelOrigin() const { return m_modelOrigin; }
    const occ::DisplayMesh& displayMesh() const { return m_mesh; }
    // A blank stock's solid in work coordinates (document::loadStockBlank), as last loaded; null
    // for the other stock shapes or while it is not (yet) read.
    std::shared_ptr<const sim::TriangleMesh> stockBlank() const { return m_stockBlank; }
    const toolpath::Toolpath& toolpath() const { return m_toolpath; }
    const QString& ncText() const { return m_nc; }
    QString ncExtension() const { return m_ncExtension; }
    bool isBusy() const { return m_busy; }

    // Asks the questions (import over operations) and shows the errors that stop what the user
    // asked for. Not owned; without one, nothing is dropped and errors go to the report only.
    void setPrompter(Prompter* prompter) { m_prompter = prompter; }

    // The NC program (ncText) is current when the last compute + post of the job as it is now
    // succeeded. Otherwise programProblem() says why (a failed post, a model that cannot be
    // read) and ncText() is the last good program (or empty): out of date, not to be saved.
    bool isProgramCurrent() const { return m_programProblem.isEmpty(); }
    const QString& programProblem() const { return m_programProblem; }
    // The machine the last posted program was checked against (the job's, else its post's
    // default); nullptr when there is none. The NC inspector checks the program against it too.
    std::shared_ptr<const kinematics::Machine> machine() const { return m_machine; }
    // The job's tools as the last posted program was made with them: what its T and D words mean.
    std::shared_ptr<const nc::ToolTable> toolTable() const { return m_tools; }
    // The post the last program was posted with (its properties and their defaults); nullptr
    // before the first post.
    std::shared_ptr<const post::PostInfo> postInfo() const { return m_postInfo; }
    // Why operation `index` cannot be made as the job stands (empty when it can or is untried).
    QString operationProblem(int index) const;
    // Why the job's model is not loaded (empty when it is, or the job has none).
    const QString& modelProblem() const { return m_modelProblem; }

    // Opens a job: reads it now (errors reported, current job kept), drops everything derived from
    // the previous job (model, toolpath, NC), then loads its model and computes + posts in the
    // background (modelChanged, toolpathChanged, ncChanged, postFinished).
    bool openJob(const QString& path);
    // Replaces the job as openJob does with one already read: `path` is where it saves (empty for
    // a new, untitled job); the undo history starts empty.
    void setJob(document::Job job, const QString& path);
    bool saveJob(const QString& path);
    // Loads a model in the background with progress. The operations are kept: their references
    // are looked up on the new model (document/ReferenceRemap.h); when some are not found the
    // prompter is asked whether to keep the operations without them, delete those operations, or
    // cancel. Then the new model becomes the job's model in one undoable step. On error or cancel
    // the job is left unchanged.
    void importModel(const QString& path);
    // Recomputes every operation and posts the program in the background; a failure is shown.
    void post();
    // Whether there is a current program to save; when not, says why (shown) and answers false:
    // out of date, none, or being recomputed (the program is of the job before the last edit).
    bool ncSavable();
    // Refused (false, the reason shown) unless ncSavable().
    bool saveNc(const QString& path);

    // Adds an operation of `kind` made from the selected faces or the model's defaults
    // (gui/shell/NewOperation.h), with a default tool controller when the job has no suited
    // tool; one undoable step. False (and a message) when the model offers nothing to cut.
    bool addOperation(document::OperationKind kind, const std::vector<int>& selectedFaces = {});
    // Adds `operation` (and `newTool` first, when given) as one undoable step.
    void addOperation(const document::Operation& operation, const std::optional<ops::ToolController>& newTool = {});
    // Replaces the operation as one undoable step ("Edit <name>"); unchanged operations add none.
    void updateOperation(int index, const document::Operation& operation);
    void removeOperation(int index);
    // The job's post property values (text by name: the non-default ones) as one undoable step
    // ("Post properties"); the same values add none. Defined in WorkbenchPost.cpp.
    void setPostProperties(const std::map<std::string, std::string>& values);
    // The job's post (and machine, when given) as one undoable step ("Post"): the property values
    // the new post takes are kept (post::switchPost, operations' own values too), the dropped ones
    // are reported by name; `values`, when given, replace the kept ones. A machine the new post
    // does not drive gives way to its default (reported). False, reported, when it cannot load.
    bool setPost(const std::string& postId, const std::optional<std::string>& machineId = {},
                 const std::optional<std::map<std::string, std::string>>& values = {});
    // The job tree's edits, one undoable step each; out-of-range indices and no-ops add none.
    // Moves operation `from` to position `to` (the order is the program's order; tool changes
    // follow it when the job is computed).
    void moveOperation(int from, int to);
    void setOperationEnabled(int index, bool enabled);
    // Inserts a copy ("<name> (copy)") right after the operation.
    void duplicateOperation(int index);
    void renameOperation(int index, const QString& name);
    // Seconds operation `index` takes on the machine (planned motion) in the last program; < 0
    // when unknown (not computed, disabled, failed).
    double operationSeconds(int index) const;
    // Copies tools (from a tool library) into the job as one undoable step; a number the job has
    // already gets the next free one, and the report says so. These four: gui/tools/WorkbenchTools.cpp.
    void addTools(const std::vector<ops::ToolController>& tools);
    // Sets the job's tools' speeds and feeds (tool `number`, 0: all with cutting data for the
    // job's material) from their cutting data, clamped to machine(); one undoable step. False,
    // the job unchanged and the reason shown, when nothing could be computed.
    bool computeFeeds(int number = 0);
    // Replaces the job's tool at `index` (speeds and feeds edited by hand); one undoable step,
    // none when nothing changed.
    void updateTool(int index, const ops::ToolController& tool);
    // The stock material the cutting data is chosen by; one undoable step.
    void setMaterial(const std::string& material);
    // The job setup panel's OK: the stock, work origin and offset, machine, post, post properties and output of
    // `setup` become the job's as one undoable step ("Job setup"); a "from model" stock is resolved
    // against the loaded model in the new origin's coordinates, and the operations' height
    // overrides move with the origin (document::moveOrigin); another post keeps the property
    // values it takes (as setPost). Unchanged setups add no step. False (shown) when the post
    // cannot be loaded: nothing changes.
    bool setJobSetup(const document::Job& setup);
    void undo();
    void redo();

signals:
    void jobChanged();
    void modelChanged();
    void stockBlankChanged();
    void toolpathChanged();
    void ncChanged();
    void postFinished(bool ok);
    void modelImportFinished(bool ok);
    // isProgramCurrent(), programProblem(), operationProblem() or modelProblem() changed.
    void programStateChanged();
    void busyChanged(bool busy);
    void progress(int percent, const QString& what);
    // The workbench is being destroyed: background work started for it (a setup sheet) stops
    // now. It then waits for its workers, which must not outlive the application.
    void closing();
    void message(camwb::gui::Workbench::Severity severity, const QString& text);

private:
    struct ComputeOutcome;
    // Recomputes (and posts) the job; reloads the model first when the job names another file.
    void startCompute();
    void finishCompute(const std::shared_ptr<ComputeOutcome>& outcome);
    void applyProblems(const ComputeOutcome& outcome);
    // setPost's rule on `edited` (a copy of the job): its post becomes `postId`, keeping the property
    // values the new post takes (dropped ones added to `notes`) and a machine it drives. False
    // (shown) when the post cannot be loaded. Defined in WorkbenchPost.cpp.
    bool switchPostIn(document::Job& edited, const std::string& postId, const std::optional<std::string>& machineId,
                      const std::optional<std::map<std::string, std::string>>& values, std::vector<QString>& notes);
    void finishImport(const std::string& file, const std::shared_ptr<ComputeOutcome>& outcome);
    void clearDerived();
    void setBusy(bool busy);
    void report(Severity severity, const QString& text);
    // An error that stops what the user asked for: in the report and shown by the prompter.
    void fail(const QString& title, const QString& text);

    document::JobDocument m_document;
    occ::Model m_model;
    std::string m_modelPath;   // the file m_model came from
    base::Vec3 m_modelOrigin;  // the job origin m_model is moved by (m_model is in work coordinates)
    occ::DisplayMesh m_mesh;
    std::shared_ptr<const sim::TriangleMesh> m_stockBlank;
    std::string m_stockBlankKey;  // the blank file and origin m_stockBlank was read for
    toolpath::Toolpath m_toolpath;
    QString m_nc;
    QString m_ncExtension = QStringLiteral("nc");
    QString m_programProblem;
    std::shared_ptr<const kinematics::Machine> m_machine;
    std::shared_ptr<const nc::ToolTable> m_tools;
    std::shared_ptr<const post::PostInfo> m_postInfo;
    QString m_modelProblem;
    std::vector<QString> m_operationProblems;  // by operation index, from the last compute
    std::vector<double> m_operationSeconds;    // by operation index, from the last compute
    Prompter* m_prompter = nullptr;
    bool m_busy = false;
    bool m_recomputePending = false;
    bool m_suppressRecompute = false;
    bool m_showComputeFailure = false;  // the running compute was asked for (open, post): show its error
    bool m_checkStoredStock = false;    // the first compute after opening: the stored stock box is checked
    int m_generation = 0;               // a compute started for an earlier job is not applied
    // Set as the workbench is destroyed: its background work stops at the next step it checks.
    std::shared_ptr<std::atomic<bool>> m_closing = std::make_shared<std::atomic<bool>>(false);
};

}  // namespace camwb::gui
