// Runs a GUI test program's QtTest classes and adds up what they report, so that ctest can tell a
// run that skipped something from one that passed. The last line it prints is
//   camwb gui tests: <passed> passed, <failed> failed, <skipped> skipped
// and tests/gui/CMakeLists.txt counts a test as skipped when that line says "0 failed" and at
// least one skip (CAMWB_GUI_SKIP_REGEX): a skip never hides a failure in the same program.
#pragma once

#include <QByteArray>
#include <QFile>
#include <QObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <vector>

class QtTestRun {
public:
    QtTestRun(int argc, char** argv) : m_args(argv, argv + argc) {}

    // QTest::qExec on `test`, its results written to stdout as usual and read back from a file.
    void run(QObject* test)
    {
        const QString log = m_dir.filePath(QStringLiteral("run%1.txt").arg(m_runs++));
        const QByteArray toFile = log.toLocal8Bit() + ",txt";
        std::vector<char*> args = m_args;
        for (const char* extra : {"-o", "-,txt", "-o"})
            args.push_back(const_cast<char*>(extra));
        args.push_back(const_cast<char*>(toFile.constData()));
        const int failedBefore = m_failed;
        const int failures = QTest::qExec(test, static_cast<int>(args.size()), args.data());
        // No totals (the class did not run through) or a failure they do not show: a failure.
        if (!addTotals(log) || (failures > 0 && m_failed == failedBefore))
            m_failed += std::max(failures, 1);
    }

    // A whole class left out on request (an environment variable): counted as skipped.
    void skip(const char* name, const char* why)
    {
        std::printf("SKIP   : %s not run: %s\n", name, why);
        ++m_skipped;
    }

    // A class that needs what this platform does not offer (OpenGL on the offscreen platform) and
    // that the other registration of the same program runs: printed, not counted.
    void notOnThisPlatform(const char* name, const char* why)
    {
        std::printf("NOTE   : %s runs in the other registration of this test: %s\n", name, why);
    }

    // Prints the summary line; the process exit code.
    int finish() const
    {
        std::printf("camwb gui tests: %d passed, %d failed, %d skipped\n", m_passed, m_failed, m_skipped);
        std::fflush(stdout);
        return m_failed == 0 ? 0 : 1;
    }

private:
    bool addTotals(const QString& log)
    {
        QFile file(log);
        if (!file.open(QIODevice::ReadOnly))
            return false;
        static const QRegularExpression totals(QStringLiteral("^Totals: (\\d+) passed, (\\d+) failed, (\\d+) skipped"),
                                               QRegularExpression::MultilineOption);
        const QRegularExpressionMatch match = totals.match(QString::fromUtf8(file.readAll()));
        if (!match.hasMatch())
            return false;
        m_passed += match.captured(1).toInt();
        m_failed += match.captured(2).toInt();
        m_skipped += match.captured(3).toInt();
        return true;
    }

    std::vector<char*> m_args;
    QTemporaryDir m_dir;
    int m_runs = 0;
    int m_passed = 0;
    int m_failed = 0;
    int m_skipped = 0;
};
