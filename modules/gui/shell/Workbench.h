// The GUI's controller: owns the job document, the loaded model and the derived toolpath and
// NC. Long work (model import, compute + post) runs on a worker thread; results come back as
// signals. No widgets here, so every action can be driven and tested without a window.
#pragma once

#include "base/Diagnostic.h"
#include "document/JobDocument.h"
#include "occ/DisplayMesh.h"
#include "occ/Model.h"
#include "post/PostProcessor.h"
#include "toolpath/Toolpath.h"

#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace camwb::gui {

class Workbench : public QObject {
    Q_OBJECT
public:
    using Severity = base::Severity;

    explicit Workbench(QObject* parent = nullptr);
    ~Workbench() override;

    document::JobDocument& document() { return m_document; }
    const document::Job& job() const { return m_document.job(); }
    const occ::Model& model() const { return m_model; }
    const occ::DisplayMesh& displayMesh() const { return m_mesh; }
    const toolpath::Toolpath& toolpath() const { return m_toolpath; }
    const QString& ncText() const { return m_nc; }
    QString ncExtension() const { return m_ncExtension; }
    bool isBusy() const { return m_busy; }

    // Opens a job: reads it now (errors reported, current job kept), then loads its model and
    // computes + posts in the background (modelChanged, toolpathChanged, ncChanged, postFinished).
    bool openJob(const QString& path);
    bool saveJob(const QString& path);
    // Loads a model in the background with progress; on success it becomes the job's model
    // (one undoable step); on error the job is left unchanged.
    void importModel(const QString& path);
    // Recomputes every operation and posts the program in the background.
    void post();
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
    void undo();
    void redo();

signals:
    void jobChanged();
    void modelChanged();
    void toolpathChanged();
    void ncChanged();
    void postFinished(bool ok);
    void modelImportFinished(bool ok);
    void busyChanged(bool busy);
    void progress(int percent, const QString& what);
    void message(camwb::gui::Workbench::Severity severity, const QString& text);

private:
    struct ComputeOutcome;
    // Recomputes (and posts) the job; reloads the model first when the job names another file.
    void startCompute();
    void finishCompute(const std::shared_ptr<ComputeOutcome>& outcome);
    void setBusy(bool busy);
    void report(Severity severity, const QString& text);

    document::JobDocument m_document;
    occ::Model m_model;
    std::string m_modelPath;  // the file m_model came from
    occ::DisplayMesh m_mesh;
    toolpath::Toolpath m_toolpath;
    QString m_nc;
    QString m_ncExtension = QStringLiteral("nc");
    bool m_busy = false;
    bool m_recomputePending = false;
    bool m_suppressRecompute = false;
};

}  // namespace camwb::gui
