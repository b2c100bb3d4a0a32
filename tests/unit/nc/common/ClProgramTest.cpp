// A CL file read through the interpreter's entry point: its importer's records at their
// statements' lines, its errors and warnings at theirs, the machine check as for NC, and NC
// reading when a dialect is asked for.
#include "kinematics/Machine.h"
#include "nc/Interpreter.h"
#include "toolpath/ToolpathRecorder.h"

#include <gtest/gtest.h>

#include <string>
#include <variant>

namespace camwb::nc {
namespace {

using namespace camwb::toolpath;

// Line 1..9; the GOTOs on lines 5, 7 and 8.
constexpr const char* kApt = "PARTNO/BRACKET\n"
                             "CUTTER/10,0\n"
                             "LOADTL/3\n"
                             "RAPID\n"
                             "GOTO/0,0,20\n"
                             "FEDRAT/MMPM,300\n"
                             "GOTO/0,0,-2\n"
                             "GOTO/40,0,-2\n"
                             "FINI\n";

InterpretResult read(std::string_view text, Toolpath& out, const kinematics::Machine* machine = nullptr)
{
    InterpretOptions options;
    options.clFormat = ClFormat::Apt;
    options.fileName = "bracket.cls";
    options.machine = machine;
    ToolpathRecorder recorder;
    InterpretResult result = interpret(text, options, recorder);
    out = recorder.take();
    return result;
}

std::vector<int> linesOfMoves(const Toolpath& program)
{
    std::vector<int> lines;
    for (std::size_t i = 0; i < program.size(); ++i)
        if (std::holds_alternative<Rapid>(program.record(i)) || std::holds_alternative<Linear>(program.record(i)))
            lines.push_back(program.source(i).line);
    return lines;
}

TEST(ClProgram, RecordsComeAtTheirStatementsLines)
{
    Toolpath program;
    const InterpretResult result = read(kApt, program);
    EXPECT_FALSE(result.hasErrors());
    EXPECT_TRUE(result.completed);
    ASSERT_EQ(result.files, std::vector<std::string>{"bracket.cls"});
    EXPECT_EQ(linesOfMoves(program), (std::vector<int>{5, 7, 8}));
    for (std::size_t i = 0; i < program.size(); ++i)
        EXPECT_EQ(program.source(i).file, 0);
    const auto* last = std::get_if<Linear>(&program.record(program.size() - 1));
    ASSERT_NE(last, nullptr);
    EXPECT_DOUBLE_EQ(last->to.x, 40);
    EXPECT_DOUBLE_EQ(last->feedMmPerMin, 300);
}

TEST(ClProgram, WhatTheImporterCannotReadIsOneErrorAtItsLineAndNoRecords)
{
    std::string text = kApt;
    text.replace(text.find("GOTO/40"), 7, "GOTO/4O");
    Toolpath program;
    const InterpretResult result = read(text, program);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(result.diagnostics[0].file, "bracket.cls");
    EXPECT_EQ(result.diagnostics[0].line, 8);
    EXPECT_TRUE(program.empty());
    EXPECT_FALSE(result.completed);
}

TEST(ClProgram, TheMachineIsCheckedAtTheStatementsLines)
{
    kinematics::Machine machine;
    machine.name = "Small mill";
    machine.spindleMaxRpm = 5000;
    machine.maxToolDiameterMm = 8;
    Toolpath program;
    const InterpretResult result = read(kApt, program, &machine);
    ASSERT_EQ(result.diagnostics.size(), 1u) << formatDiagnostic(result.diagnostics.front());
    EXPECT_EQ(result.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(result.diagnostics[0].file, "bracket.cls");
    EXPECT_EQ(result.diagnostics[0].line, 3);  // LOADTL: the tool change
    EXPECT_NE(result.diagnostics[0].message.find("10 mm"), std::string::npos) << result.diagnostics[0].message;
}

TEST(ClProgram, AFilesNameMakesItCLUnlessADialectIsAsked)
{
    const std::string path = std::string(CAMWB_TEST_DATA_DIR) + "/tests/data/cl/creo_inch_holes.apt";
    ToolpathRecorder asCl;
    const InterpretResult cl = interpretFile(path, std::nullopt, {}, asCl);
    EXPECT_FALSE(cl.hasErrors());
    EXPECT_FALSE(asCl.take().empty());

    ToolpathRecorder asIso;
    const InterpretResult iso = interpretFile(path, Dialect::Iso, {}, asIso);
    EXPECT_TRUE(iso.hasErrors());  // APT words are not ISO words
}

}  // namespace
}  // namespace camwb::nc
