// camwb-cli sim: simulates a job or an NC program headless: the cycle time from the machine's
// limits, the stock cut with the job's or the given tools, every check with file and line, the
// remaining material against the model, and optionally the cut stock as STL, the sampled motion
// as CSV and everything as a JSON report.
#include "Cli.h"

#include "SimMeasured.h"
#include "base/AtomicFile.h"
#include "base/NumberFormat.h"
#include "document/NcTrace.h"
#include "document/Simulate.h"
#include "document/StockBlank.h"
#include "document/TurningSetup.h"
#include "nc/ToolTable.h"
#include "occ/Model.h"
#include "sim/MotionPlan.h"
#include "sim/MotionSamples.h"
#include "sim/Simulation.h"
#include "sim/TurningCheck.h"
#include "sim/TurningProfile.h"
#include "toolpath/ClText.h"
#include "toolpath/ProgramStats.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

namespace camwb::cli {

namespace {

struct SimOptions {
    std::string input;
    std::string machineId;
    double resolutionMm = 0;  // 0: the default for the input's size
    double toleranceMm = 0.02;
    double sampleMs = 3;
    std::string report;  // JSON; "-" = stdout
    std::string stl;
    std::string traceCsv;
    std::string model;                   // NC: the part to compare with
    std::string stock;                   // NC: a box "x0,y0,z0,x1,y1,z1" or a mesh/STEP file
    std::optional<base::Box3> stockBox;  // --stock as a box, checked with the other options
    std::string toolTable;               // NC: the tools' sizes
    // Turning: the revolved stock and the part's (offset) contour in XZ, and the insert's width.
    std::string stockProfile;
    std::string designProfile;
    double insertWidthMm = 0;
    // A trace the control recorded (TNCscope CSV), and how far its Z is above the tool tip.
    std::string measured;
    double measuredZOffsetMm = 0;
    bool analysis = false;          // seed 003's analysis of the simulated motion
    std::vector<std::string> sets;  // --set: a job's operation parameters for this run
};

std::optional<double> positive(const std::string& text)
{
    const std::optional<double> value = toolpath::parseNumber(text);  // no "inf" or "nan"
    if (!value || !(*value > 0))
        return std::nullopt;
    return value;
}

std::string parseSimOptions(const std::vector<std::string>& args, SimOptions& options)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        static const std::set<std::string> kTakesValue{
            "--machine",       "--resolution",     "--report",       "--stl",       "--trace-csv",
            "--model",         "--stock",          "--tolerance",    "--sample-ms", "--tool-table",
            "--stock-profile", "--design-profile", "--insert-width", "--measured",  "--measured-z-offset"};
        const bool takesValue = kTakesValue.count(arg) > 0;
        if (std::string error; takeSetOption(args, i, options.sets, error)) {
            if (!error.empty())
                return error;
            continue;
        }
        if (arg == "--analysis") {
            options.analysis = true;
            continue;
        }
        if (!takesValue) {
            if (!arg.empty() && arg[0] == '-')
                return "unknown option '" + arg + "'";
            if (!options.input.empty())
                return "sim takes one input, got '" + options.input + "' and '" + arg + "'";
            options.input = arg;
            continue;
        }
        if (i + 1 >= args.size())
            return arg + " needs a value";
        const std::string& value = args[++i];
        if (arg == "--resolution" || arg == "--tolerance" || arg == "--sample-ms" || arg == "--insert-width") {
            const std::optional<double> number = positive(value);
            if (!number)
                return arg + " needs a positive number, not '" + value + "'";
            (arg == "--resolution"  ? options.resolutionMm
             : arg == "--tolerance" ? options.toleranceMm
             : arg == "--sample-ms" ? options.sampleMs
                                    : options.insertWidthMm) = *number;
        } else if (arg == "--measured") {
            options.measured = value;
        } else if (arg == "--measured-z-offset") {
            const std::optional<double> number = toolpath::parseNumber(value);
            if (!number)
                return arg + " needs a number, not '" + value + "'";
            options.measuredZOffsetMm = *number;
        } else if (arg == "--stock-profile") {
            options.stockProfile = value;
        } else if (arg == "--design-profile") {
            options.designProfile = value;
        } else if (arg == "--machine") {
            options.machineId = value;
        } else if (arg == "--report") {
            options.report = value;
        } else if (arg == "--stl") {
            options.stl = value;
        } else if (arg == "--trace-csv") {
            options.traceCsv = value;
        } else if (arg == "--model") {
            options.model = value;
        } else if (arg == "--tool-table") {
            options.toolTable = value;
        } else {
            options.stock = value;
        }
    }
    if (options.input.empty())
        return "sim needs a job (.camwb) or an NC program";
    const bool job = std::filesystem::path(options.input).extension() == ".camwb";
    if (!job && !options.sets.empty())
        return "--set changes a job's operation; " + options.input + " is not a job";
    if (!options.stl.empty() && !job && options.stock.empty() && options.model.empty())
        return "--stl needs a stock: a job's, or --stock or --model for an NC program";
    if (options.stock.find(',') != std::string::npos) {  // a box, not a file: checked before anything is read
        std::string error;
        options.stockBox = parseStockBox(options.stock, error);
        if (!options.stockBox)
            return error;
    }
    const bool turning = !options.stockProfile.empty();
    if (!turning && (!options.designProfile.empty() || options.insertWidthMm > 0))
        return "--design-profile and --insert-width need --stock-profile (a turning simulation)";
    if (turning && (!options.stock.empty() || !options.model.empty()))
        return "--stock-profile simulates turning: --stock and --model are for milling";
    if (turning && options.insertWidthMm <= 0)
        return "--stock-profile needs --insert-width (the grooving insert's width, mm)";
    return {};
}

// Everything the report needs, from a job or from an NC program.
struct Input {
    toolpath::Toolpath program;
    std::vector<bool> recordsInError;
    std::optional<document::Job> job;
    std::optional<std::vector<std::string>> programFiles;  // an NC program's: what its records' sources name
    std::optional<kinematics::Machine> machine;
    sim::TriangleMesh design;
    std::optional<base::Box3> stockBox;
    sim::TriangleMesh stockMesh;
    std::vector<base::Diagnostic> diagnostics;  // reading the program
};

document::RecordPlace placeOf(const Input& input, const std::string& path, std::int64_t record)
{
    if (input.programFiles)
        return document::placeOfRecord(*input.programFiles, input.program, record);
    return document::placeOfRecord(*input.job, path, input.program, record);
}

std::optional<Input> loadJobInput(const SimOptions& options)
{
    std::optional<ComputedJob> computed = computeJobFile(options.input, options.sets);
    if (!computed)
        return std::nullopt;
    Input input;
    // A lathe job has no model: its stock and contour are the turning setup's (turningInput).
    if (computed->model && !computed->model->empty()) {
        input.design = document::designMesh(*computed->model);
        // The job's stock as the solid it is: a box, a cylinder, or the blank's mesh.
        sim::StockSpec stock = document::jobStockSpec(computed->job, *computed->model, computed->stockBlank, 0);
        input.stockBox = stock.box;
        input.stockMesh = std::move(stock.blank);
    }
    if (options.machineId.empty()) {
        auto machine = document::jobMachine(computed->job);
        if (!machine) {
            fail(machine.error().toString());
            return std::nullopt;
        }
        input.machine = std::move(machine).value();
    }
    input.diagnostics = computed->report.warnings;
    input.program = std::move(computed->program);
    input.job = std::move(computed->job);
    return input;
}

// --tool-table, read; nullopt (said on stderr) when it cannot be.
std::optional<nc::ToolTable> readToolTableOption(const SimOptions& options)
{
    auto table = nc::readToolTable(options.toolTable);
    if (!table) {
        fail(table.error().toString());
        return std::nullopt;
    }
    return std::move(table).value();
}

// An NC program, or a CL file (APT, FreeCAD dump, trace) by its extension, as the inspector reads
// them (document::traceNc): a CL file's tools come with it, or from --tool-table as for NC.
std::optional<Input> loadNcInput(const SimOptions& options, const kinematics::Machine* machine)
{
    auto text = base::readPlainTextFile(options.input);
    if (!text) {
        fail(text.error().toString());
        return std::nullopt;
    }
    Input input;
    document::NcTraceRequest request;
    request.text = std::move(text).value();
    request.path = options.input;
    if (machine)
        request.machine = std::make_shared<const kinematics::Machine>(*machine);
    request.checkLimits = false;  // sim::simulate checks them, as errors with the other checks
    if (!options.toolTable.empty()) {
        std::optional<nc::ToolTable> table = readToolTableOption(options);
        if (!table)
            return std::nullopt;
        request.tools = std::make_shared<const nc::ToolTable>(std::move(*table));
    }
    document::NcTrace trace = document::traceNc(request);
    input.program = std::move(trace.program);  // not copied: a long program's records are megabytes
    if (request.tools)
        document::sizeTools(input.program, document::toolsOf(*request.tools));
    input.programFiles = std::move(trace.result.files);
    input.recordsInError = std::move(trace.recordsInError);
    input.diagnostics = std::move(trace.result.diagnostics);
    return input;
}

// --model and --stock: meshes through occ (STEP, IGES, BREP, STL), or a box.
bool loadModelAndStock(const SimOptions& options, Input& input)
{
    if (!options.model.empty()) {
        auto model = occ::Model::load(options.model);
        if (!model) {
            fail(model.error().toString());
            return false;
        }
        input.design = document::designMesh(model.value());
    }
    if (options.stock.empty()) {
        if (!input.stockBox && input.stockMesh.empty() && !input.design.empty())
            input.stockBox = input.design.bounds();  // neither a job's stock nor --stock: the model's box
        return true;
    }
    if (options.stockBox) {
        input.stockBox = options.stockBox;
        return true;
    }
    auto blank = occ::Model::load(options.stock);
    if (!blank) {
        fail(blank.error().toString());
        return false;
    }
    input.stockMesh = document::designMesh(blank.value());
    input.stockBox.reset();
    return true;
}

// What the turning check runs on: --stock-profile (with --design-profile, --insert-width), else
// a job's groove operations (document::turningSetup); none for milling.
struct TurningInput {
    sim::TurningRegion stock, design;
    sim::Insert insert;
};

base::Result<std::optional<TurningInput>> turningInput(const SimOptions& options, const Input& input)
{
    if (options.stockProfile.empty()) {
        if (!input.job)
            return std::optional<TurningInput>();
        std::optional<document::TurningSetup> setup = document::turningSetup(*input.job);
        if (!setup)
            return std::optional<TurningInput>();
        return std::optional<TurningInput>(TurningInput{setup->stock, setup->design, setup->insert});
    }
    TurningInput turning;
    auto stock = sim::stockProfileFromArgument(options.stockProfile);
    if (!stock)
        return stock.error();
    turning.stock = std::move(stock).value();
    if (!options.designProfile.empty()) {
        auto read = sim::stockProfileFromArgument(options.designProfile);
        if (!read)
            return read.error();
        turning.design = std::move(read).value();
    }
    turning.insert.widthMm = options.insertWidthMm;
    return std::optional<TurningInput>(std::move(turning));
}

std::string mm(double value) { return base::formatFixed(value, 3); }

nlohmann::json point(const base::Vec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

int simCommand(const std::vector<std::string>& args)
{
    SimOptions options;
    if (const std::string error = parseSimOptions(args, options); !error.empty())
        return usageError(error);
    const bool isJob = std::filesystem::path(options.input).extension() == ".camwb";
    if (isJob && (!options.model.empty() || !options.stock.empty() || !options.toolTable.empty()))
        return usageError("--model, --stock and --tool-table are for an NC program; a job brings its own");

    auto chosen = machineOption(options.machineId);
    if (!chosen)
        return fail(chosen.error().toString());
    const std::optional<kinematics::Machine> machine = std::move(chosen).value();
    std::optional<Input> input = isJob ? loadJobInput(options) : loadNcInput(options, machine ? &*machine : nullptr);
    if (!input || !loadModelAndStock(options, *input))
        return kExitError;
    if (machine)
        input->machine = machine;
    auto turning = turningInput(options, *input);
    if (!turning)
        return fail(turning.error().toString());
    std::optional<sim::TurningReport> turned;
    if (turning.value()) {
        TurningInput& t = *turning.value();
        input->program = sim::inTurningPlane(input->program);
        sim::TurningOptions turningOptions;
        turningOptions.insert = t.insert;
        turned = sim::checkTurning(input->program, std::move(t.stock), std::move(t.design), turningOptions);
    }

    // The stock and the cut.
    std::optional<sim::StockSpec> spec;
    const base::Box3 stockBounds = input->stockBox ? *input->stockBox : input->stockMesh.bounds();
    if (input->stockBox || !input->stockMesh.empty()) {
        spec.emplace();
        spec->box = input->stockBox;
        spec->blank = input->stockMesh;
        spec->resolutionMm =
            options.resolutionMm > 0 ? options.resolutionMm : document::defaultStockResolution(stockBounds);
        spec->design = input->design;
        spec->gougeToleranceMm = options.toleranceMm;
    }
    const kinematics::Machine planMachine = input->machine ? *input->machine : kinematics::defaultLimitsMachine();
    sim::SimulationSetup setup;
    setup.machine = input->machine ? &*input->machine : nullptr;
    setup.stockSpec = spec ? &*spec : nullptr;
    setup.planOn = &planMachine;  // planned while the stock is cut
    sim::SimulationResult result = sim::simulate(input->program, setup, input->recordsInError);
    if (!result.stockError.empty())
        return fail(result.stockError);  // says what to change (--resolution, or the stock)
    if (turned) {
        result.checks.insert(result.checks.begin(), turned->findings.begin(), turned->findings.end());
        result.deviation.maxGougeMm = turned->maxGougeMm;
        result.deviation.gougeAt = {turned->maxGougeAt.y, 0, turned->maxGougeAt.x};
    }
    printDiagnostics(input->diagnostics);
    // Where each check is (file, line, operation), worked out once for the printout and the report.
    std::vector<document::RecordPlace> checkPlaces;
    checkPlaces.reserve(result.checks.size());
    for (const sim::Check& check : result.checks)
        checkPlaces.push_back(placeOf(*input, options.input, check.record));

    // Time.
    const sim::MotionPlan plan = std::move(*result.plan);
    toolpath::StatsOptions statsOptions;
    statsOptions.rapidMmPerMin = kinematics::estimateRapidMmPerMin(input->machine ? &*input->machine : nullptr);
    statsOptions.recordsInError = input->recordsInError.empty() ? nullptr : &input->recordsInError;
    const sim::CycleTimes times =
        sim::cycleTimes(result.moves, plan, toolpath::programStats(input->program, statsOptions));

    // What it found, as compilers report.
    std::vector<base::Diagnostic> found;
    for (std::size_t i = 0; i < result.checks.size(); ++i) {
        const sim::Check& check = result.checks[i];
        if (check.kind == sim::CheckKind::AirCutting)
            continue;  // in the report and the counts; too many to print
        const document::RecordPlace& place = checkPlaces[i];
        std::string message = check.message;
        if (!place.operation.empty())
            message = place.operation + ": " + message;
        found.push_back({check.severity, place.file, place.line, 0, message});
    }
    printDiagnostics(found);
    std::cout << "cycle time " << base::formatFixed(times.planned.totalSeconds(), 1) << " s on "
              << (input->machine ? input->machine->id : std::string("default limits (no machine given)"))
              << " (distance/feed estimate " << base::formatFixed(times.simpleSeconds, 1) << " s), "
              << result.moves.moves.size() << " moves\n";
    if (turned)
        std::cout << "turning stock: removed " << base::formatFixed(turned->removedMm2, 2) << " mm2 of the profile, "
                  << turned->rapidsInStock << " rapids through stock, " << turned->gouges << " gouges (deepest "
                  << mm(turned->maxGougeMm) << " mm), left over above the design "
                  << base::formatFixed(turned->leftoverMm2, 3) << " mm2 (thickest " << mm(turned->maxLeftoverMm)
                  << " mm at X " << mm(turned->maxLeftoverAt.y) << " Z " << mm(turned->maxLeftoverAt.x) << ")\n";
    if (result.cut) {
        std::cout << "stock " << (result.tilts ? "tri-dexel" : "height field") << " at "
                  << mm(result.stock->resolutionMm()) << " mm: removed " << base::formatFixed(result.removedMm3, 1)
                  << " mm3, feed in air " << base::formatFixed(result.airCuttingMm, 1) << " mm\n";
        if (!input->design.empty())
            std::cout << "largest gouge " << mm(result.deviation.maxGougeMm) << " mm, largest leftover over the part "
                      << mm(result.deviation.maxLeftoverMm) << " mm, material beside the part up to "
                      << mm(result.deviation.maxOutsideMm) << " mm thick\n";
    }

    // Seed 003's analysis of the planned motion needs its samples at once: bounded, so that a
    // program of many hours asks for a coarser step instead of all the memory.
    std::optional<nlohmann::json> analysis;
    if (options.analysis) {
        constexpr double kMaxSamples = 5e6;
        const double samples = plan.totalSeconds / (options.sampleMs / 1000);
        if (samples > kMaxSamples)
            return fail("--analysis: " + base::formatFixed(plan.totalSeconds, 0) + " s at " +
                        base::formatFixed(options.sampleMs, 1) +
                        " ms is over 5 million samples; give a larger --sample-ms");
        sim::SampleOptions sampling;
        sampling.stepSeconds = options.sampleMs / 1000;
        sim::Trace trace;
        for (const sim::MotionSample& s : sim::sampleMotion(result.moves, plan, planMachine, sampling))
            trace.push_back(s.at);
        analysis = analysisReport(trace, planMachine.kinematics);
        std::cout << "reversals of the planned motion:";
        for (const auto& [axis, times] : (*analysis)["reversals"].items())
            std::cout << " " << axis << " " << times.size();
        std::cout << "\n";
        if (analysis->contains("maxRotaryTipFeedMmPerMin")) {
            std::cout << "tip feed from the rotary axes up to:";
            for (const auto& [axis, feed] : (*analysis)["maxRotaryTipFeedMmPerMin"].items())
                std::cout << " v_" << axis << " " << base::formatFixed(feed.get<double>(), 0) << " mm/min";
            std::cout << "\n";
        }
    }
    std::optional<nlohmann::json> measured;
    if (!options.measured.empty()) {
        auto read = measuredReport(options.measured, planMachine, result.moves, options.measuredZOffsetMm);
        if (!read)
            return fail(read.error().toString());
        measured = std::move(read).value();
        std::cout << "measured trace: " << (*measured)["samples"].get<std::size_t>() << " samples, reversals";
        for (const auto& [axis, times] : (*measured)["reversals"].items())
            std::cout << " " << axis << " " << times.size();
        std::cout << "\n";
    }

    // Files.
    if (!options.stl.empty()) {
        if (!result.stock)
            return usageError("--stl needs a stock (a job, or --stock/--model for an NC program)");
        if (const base::Status written = sim::writeStl(result.stock->fileMesh(), options.stl, "camwb-cli sim");
            !written)
            return fail(written.error().toString());
    }
    if (!options.traceCsv.empty()) {
        std::string csv = "time_s,move,line,tip_x,tip_y,tip_z,axis_i,axis_j,axis_k,X,Y,Z,R1_deg,R2_deg,feed_mm_min\n";
        sim::SampleOptions sampling;
        sampling.stepSeconds = options.sampleMs / 1000;
        sim::sampleMotion(
            result.moves, plan, planMachine,
            [&](const sim::MotionSample& s) {
                const int line = placeOf(*input, options.input, result.moves.moves[s.move].record).line;
                csv += base::formatFixed(s.at.time, 4) + "," + std::to_string(s.move) + "," + std::to_string(line);
                for (double v : {s.at.tip.x, s.at.tip.y, s.at.tip.z})
                    csv += "," + base::formatFixed(v, 4);
                for (double v : {s.toolAxis.x, s.toolAxis.y, s.toolAxis.z})
                    csv += "," + base::formatFixed(v, 6);
                for (double v : {s.at.linear.x, s.at.linear.y, s.at.linear.z, s.at.rotaryDeg[0], s.at.rotaryDeg[1]})
                    csv += "," + base::formatFixed(v, 4);
                csv += "," + base::formatFixed(s.feedMmPerMin, 1) + "\n";
                return true;
            },
            sampling);
        if (const base::Status written = base::writeFileAtomically(options.traceCsv, csv); !written)
            return fail(written.error().toString());
    }
    if (!options.report.empty()) {
        nlohmann::json report;
        report["input"] = options.input;
        report["machine"] = input->machine ? input->machine->id : std::string();
        report["cycleTimeSeconds"] = times.planned.totalSeconds();
        report["simpleEstimateSeconds"] = times.simpleSeconds;
        report["moves"] = result.moves.moves.size();
        nlohmann::json perTool = nlohmann::json::array();
        for (const auto& [tool, split] : times.plannedPerTool) {
            const auto simple = times.simplePerTool.find(tool);
            perTool.push_back({{"tool", tool},
                               {"seconds", split.totalSeconds()},
                               {"simpleSeconds", simple == times.simplePerTool.end() ? 0.0 : simple->second}});
        }
        report["perTool"] = perTool;
        nlohmann::json perOperation = nlohmann::json::array();
        for (const sim::SectionTime& section : times.sections)
            perOperation.push_back(
                {{"name", section.name}, {"tool", section.tool}, {"seconds", section.planned.totalSeconds()}});
        report["perOperation"] = perOperation;
        report["stock"] = result.stock ? nlohmann::json{{"kind", result.tilts ? "tri-dexel" : "height-field"},
                                                        {"resolutionMm", result.stock->resolutionMm()},
                                                        {"min", point(stockBounds.min)},
                                                        {"max", point(stockBounds.max)},
                                                        {"remainingMm3", result.stock->volumeMm3()}}
                                       : nlohmann::json();
        if (turned)
            report["turning"] = {{"removedMm2", turned->removedMm2},
                                 {"rapidsInStock", turned->rapidsInStock},
                                 {"gouges", turned->gouges},
                                 {"feedsInAir", turned->feedsInAir},
                                 {"maxRapidDepthMm", turned->maxRapidDepthMm},
                                 {"leftoverMm2", turned->leftoverMm2},
                                 {"maxLeftoverMm", turned->maxLeftoverMm}};
        report["removedMm3"] = result.removedMm3;
        report["airCuttingMm"] = result.airCuttingMm;
        report["maxGougeMm"] = result.deviation.maxGougeMm;
        report["maxLeftoverMm"] = result.deviation.maxLeftoverMm;
        report["maxOutsideMm"] = result.deviation.maxOutsideMm;
        auto extreme = [&](const base::Vec3& at, std::int64_t move) {
            nlohmann::json j{{"at", point(at)}};
            if (move >= 0 && move < static_cast<std::int64_t>(result.moves.moves.size())) {
                const document::RecordPlace place = placeOf(*input, options.input, result.moves.moves[move].record);
                j["file"] = place.file;
                j["line"] = place.line;
                if (!place.operation.empty())
                    j["operation"] = place.operation;
            }
            return j;
        };
        report["gouge"] = extreme(result.deviation.gougeAt, result.deviation.gougeMove);
        report["leftover"] = extreme(result.deviation.leftoverAt, result.deviation.leftoverMove);
        nlohmann::json checks = nlohmann::json::array();
        for (std::size_t i = 0; i < result.checks.size(); ++i) {
            const sim::Check& check = result.checks[i];
            const document::RecordPlace& place = checkPlaces[i];
            nlohmann::json c{{"kind", sim::checkKindName(check.kind)},
                             {"severity", base::severityName(check.severity)},
                             {"file", place.file},
                             {"line", place.line},
                             {"message", check.message}};
            if (!place.operation.empty())
                c["operation"] = place.operation;
            if (check.record >= 0)
                c["record"] = check.record;
            if (check.move >= 0)
                c["at"] = point(check.at);
            if (check.valueMm != 0)
                c["valueMm"] = check.valueMm;
            checks.push_back(c);
        }
        for (const base::Diagnostic& d : input->diagnostics)
            checks.push_back({{"kind", "program"},
                              {"severity", base::severityName(d.severity)},
                              {"file", d.file},
                              {"line", d.line},
                              {"message", d.message}});
        report["checks"] = checks;
        if (measured)
            report["measured"] = *measured;
        if (analysis)
            report["analysis"] = *analysis;
        const std::string text = report.dump(2) + "\n";
        if (options.report == "-")
            std::cout << text;
        else if (const base::Status written = base::writeFileAtomically(options.report, text); !written)
            return fail(written.error().toString());
    }
    const bool programErrors = base::countOf(input->diagnostics, base::Severity::Error) > 0;
    return result.count(base::Severity::Error) > 0 || programErrors ? kExitError : kExitOk;
}

}  // namespace camwb::cli
