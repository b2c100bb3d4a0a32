// main() for GoogleTest binaries that need a QCoreApplication: QJSEngine (the post kernel) and
// QProcess (the rs274 runner) want one. gtest_main's main is not used where this is linked.
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
