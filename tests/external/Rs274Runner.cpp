#include "Rs274Runner.h"

#include "base/NumberFormat.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

#include <fstream>

namespace camwb::external {

namespace {

constexpr double kMmPerInch = 25.4;

}  // namespace

base::Status writeRs274ToolTable(const std::string& path, const std::vector<Rs274Tool>& tools)
{
    std::ofstream out(path, std::ios::binary);
    for (const Rs274Tool& tool : tools)
        out << "T" << tool.number << " P" << tool.number << " Z" << base::formatFixed(tool.lengthMm / kMmPerInch, 12)
            << " D" << base::formatFixed(tool.diameterMm / kMmPerInch, 12) << " ;\n";
    out.close();
    if (!out)
        return base::makeError("cannot write the rs274 tool table", path);
    return {};
}

base::Result<Rs274Run> runRs274(const std::string& rs274Binary, const std::string& ngcFile,
                                const std::string& toolTable, const std::string& workDir, int timeoutMs)
{
    QProcess process;
    process.setWorkingDirectory(QString::fromStdString(workDir));
    // LinuxCNC 2.9 keeps the tool table in a memory-mapped $HOME/.tool.mmap: one file for every
    // rs274 of a user, so parallel runs read each other's tools, and one truncating it while
    // another maps it dies of a bus error. A HOME of its own per run keeps them apart.
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("HOME"), QString::fromStdString(workDir));
    process.setProcessEnvironment(environment);
    process.setProgram(QString::fromStdString(rs274Binary));
    process.setArguments({QStringLiteral("-t"), QString::fromStdString(toolTable), QStringLiteral("-g"),
                          QString::fromStdString(ngcFile)});
    QElapsedTimer timer;
    timer.start();
    process.start();
    if (!process.waitForStarted(10000))
        return base::makeError("cannot start rs274: " + process.errorString().toStdString(), rs274Binary);
    process.closeWriteChannel();  // as `< /dev/null`: rs274 would otherwise wait for MDI input at the end
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished(5000);
        return base::makeError("rs274 did not finish in " + std::to_string(timeoutMs / 1000) + " s", ngcFile);
    }
    Rs274Run run;
    run.seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.trace = process.readAllStandardOutput().toStdString();
    run.errors = process.readAllStandardError().toStdString();
    return run;
}

}  // namespace camwb::external
