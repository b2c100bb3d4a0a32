// Screenshots of the GUI tests: written to $CAMWB_SHOTS_DIR when it is set (to look at them),
// else to a temporary folder, so the cases that take them always run; and the check that a
// picture shows something (a blank or single-colour grab means the widget drew nothing).
#pragma once

#include <QDir>
#include <QImage>
#include <QSet>
#include <QString>
#include <QTemporaryDir>

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
