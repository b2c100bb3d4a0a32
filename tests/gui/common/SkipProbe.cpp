// A QtTest program that passes, skips or fails on request (argument: pass, skip, skip_fail,
// fail_skip, skip_class), run by CheckSkipsCounted.cmake to prove how ctest counts GUI tests:
// a skip without a failure is "Skipped", a failure stays "Failed" whatever else was skipped.
#include "QtTestRun.h"

#include <QCoreApplication>

#include <cstring>

class Passes : public QObject {
    Q_OBJECT
private slots:
    void passes() { QVERIFY(true); }
};

class Skips : public QObject {
    Q_OBJECT
private slots:
    void skips() { QSKIP("the probe skips on request"); }
};

class Fails : public QObject {
    Q_OBJECT
private slots:
    void fails() { QFAIL("the probe fails on request"); }
};

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const char* mode = argc > 1 ? argv[1] : "pass";
    QtTestRun run(1, argv);  // the mode is no QtTest option
    Passes passes;
    Skips skips;
    Fails fails;
    run.run(&passes);
    if (std::strcmp(mode, "skip") == 0 || std::strcmp(mode, "skip_fail") == 0)
        run.run(&skips);
    if (std::strcmp(mode, "skip_fail") == 0 || std::strcmp(mode, "fail_skip") == 0)
        run.run(&fails);
    if (std::strcmp(mode, "fail_skip") == 0)
        run.run(&skips);
    if (std::strcmp(mode, "skip_class") == 0)
        run.skip("Large", "left out on request");
    return run.finish();
}

#include "SkipProbe.moc"
