// Screenshots of the GUI tests: written to $CAMWB_SHOTS_DIR when it is set (to look at them),
// else to a temporary folder, so the cases that take them always run; and the check that a
// picture shows something (a blank or single-colour grab means the widget drew nothing).
#pragma once

#include <QDir>
#include <QImage>
#include <QSet>
#include <QString>
#include <QTemporaryDir>
#include <QTest>
#include <QWidget>

inline QString shotsDir()
{
    const QString chosen = qEnvironmentVariable("CAMWB_SHOTS_DIR");
    if (!chosen.isEmpty()) {
        QDir().mkpath(chosen);
        return chosen;
    }
    static QTemporaryDir scratch;  // removed when the test program ends
    return scratch.path();
}

// Distinct colours on a coarse grid: a window with text, frames and icons has dozens.
inline int distinctColours(const QImage& image)
{
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 5)
        for (int x = 0; x < image.width(); x += 5)
            colours.insert(image.pixel(x, y));
    return static_cast<int>(colours.size());
}

inline bool showsSomething(const QImage& image) { return !image.isNull() && distinctColours(image) >= 8; }

// Shows the widget (a no-op when it is shown already), grabs it, checks the picture shows
// something and saves it as shotsDir()/name.
inline void saveShot(QWidget* widget, const QString& name)
{
    widget->show();
    QVERIFY(QTest::qWaitForWindowExposed(widget));
    QTest::qWait(100);
    const QImage image = widget->grab().toImage();
    QVERIFY2(showsSomething(image), qPrintable(name + QStringLiteral(": the grab shows nothing")));
    QVERIFY(image.save(shotsDir() + QLatin1Char('/') + name));
}
