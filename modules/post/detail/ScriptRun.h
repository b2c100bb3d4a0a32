// Private: one post run in its own QJSEngine. Installs the kernel services, evaluates the post
// script, reads its declarations (metadata, capabilities, properties, block templates), and calls
// its handlers under the watchdog. Playing the CL records is ScriptSink's job (ScriptSink.cpp).
#pragma once

#include "base/Result.h"
#include "post/FiveAxisPlan.h"
#include "post/PostProcessor.h"
#include "post/ProgramSummary.h"
#include "post/detail/BlockTemplates.h"
#include "post/detail/ScriptBindings.h"
#include "post/detail/ScriptWatchdog.h"

#include <QJSEngine>
#include <QJSValue>

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace camwb::post {

enum class Handler {
    Open,
    Section,
    ToolChange,
    Spindle,
    Coolant,
    FeedMode,
    WorkOffset,
    Rapid,
    Linear,
    Circular,
    Linear5D,
    Cycle,
    CyclePoint,
    CycleEnd,
    Comment,
    CutterComp,
    Dwell,
    SectionEnd,
    Stop,
    PassThrough,
    WorkingPlane,
    Close,
    FiveAxisBegin,
    FiveAxisEnd,
    Count
};
const char* handlerName(Handler handler);
// "1 arc", "3 arcs": a count with its noun, for the run's warnings.
std::string counted(int count, const char* one, const char* many);

// post.fiveAxis: how the kernel writes five-axis moves on a machine with a five-axis chain.
struct FiveAxisDeclaration {
    bool machineCoordinates = false;        // "machine": linear axes about the chain's origin (no TCPM); "tip"
    FiveAxisFeed feed = FiveAxisFeed::Tip;  // "tip", "combined" (machine output), "inverse"
    FiveAxisOptions options;
    // output/feed given as functions: asked at each five-axis section (an operation may set the
    // post properties they read), answering what the fields above say.
    QJSValue chooseOutput, chooseFeed;
};

class ScriptRun {
public:
    ScriptRun(std::string postFile, const PostContext& context, std::chrono::milliseconds budget);
    ~ScriptRun();

    // What getProperty() answers and what `machine` is while the script runs; set before evaluate().
    void setProperties(const std::map<std::string, PropertyValue>& values);
    // An operation's own property values for its section (SectionBegin::postProperties; empty:
    // none): each must be declared perOperation and valid, else the run fails naming the record.
    bool setSectionProperties(const std::vector<std::pair<std::string, std::string>>& values);
    void setMachine(const kinematics::Machine& machine);
    // `job` in the script: {name, stock: {min, max} or null}.
    void setJob(const JobFacts& job);
    // What machiningSeconds() computes (once, when the script first asks).
    void setMachiningTime(std::function<double()> estimate) { m_kernel->setMachiningTime(std::move(estimate)); }

    // Evaluates the post source and reads its declarations into `info` and the block templates.
    base::Status evaluate(const std::string& source, PostInfo& info);
    // Plays the toolpath through the post (onOpen ... onClose); the text goes to writer().
    base::Status play(const toolpath::Toolpath& toolpath, const ProgramSummary& summary);

    OutputWriter& writer() { return m_kernel->mainWriter(); }
    // The companion files the post wrote (openFile/closeFile), in the order it opened them.
    std::vector<CompanionWriter>& companions() { return m_kernel->companions(); }
    std::vector<base::Diagnostic>& messages() { return m_kernel->messages(); }

private:
    friend class ScriptSink;
    friend class FiveAxisWriter;

    // Calls `handler` when the post has it; false when the script failed (m_failure holds why).
    bool call(Handler handler, const QJSValueList& args);
    // What a post function (no arguments) answers, as text; nullopt when it failed (m_failure
    // holds why, naming `what` and the record).
    std::optional<std::string> answer(const QJSValue& function, const std::string& what);
    bool has(Handler handler) const { return m_handlers[static_cast<int>(handler)].isCallable(); }
    base::Error scriptError(const QJSValue& thrown, const std::string& where);
    void fail(const std::string& message);  // a kernel error about the current record
    std::string where() const;              // "CL record 12 Arc", or "" outside the records
    base::Status readDeclarations(const std::string& source, PostInfo& info);
    base::Status readFiveAxis(const std::string& source);
    QJSValue scriptValue(const PropertyValue& value);

    std::string m_postFile;
    std::string m_postId;
    QJSEngine m_engine;
    std::unique_ptr<ScriptKernel> m_kernel;  // C++ ownership; destroyed before the engine
    ScriptWatchdog m_watchdog;
    QJSValue m_post;
    QJSValue m_trampoline;
    std::array<QJSValue, static_cast<int>(Handler::Count)> m_handlers;
    BlockTemplates m_templates;
    PostCapabilities m_capabilities;
    std::optional<kinematics::Machine> m_machine;
    FiveAxisDeclaration m_fiveAxis;  // post.fiveAxis
    std::vector<PropertyDef> m_propertyDefs;
    long long m_recordIndex = -1;  // record being played, for messages
    const char* m_recordName = "";
    std::optional<base::Error> m_failure;
};

}  // namespace camwb::post
