#include "gui/shell/Preferences.h"

#include <QSettings>

#include <algorithm>

namespace camwb::gui {

namespace {

// Stored as words, so a settings file stays readable and an unknown value falls back to the default.
QString unitKey(LengthUnit unit) { return unit == LengthUnit::Inch ? QStringLiteral("inch") : QStringLiteral("mm"); }

QString languageKey(Language language)
{
    switch (language) {
    case Language::English:
        return QStringLiteral("en");
    case Language::Czech:
        return QStringLiteral("cs");
    case Language::System:
        break;
    }
    return QStringLiteral("system");
}

Language languageFrom(const QString& key)
{
    if (key == QLatin1String("en"))
        return Language::English;
    if (key == QLatin1String("cs"))
        return Language::Czech;
    return Language::System;
}

}  // namespace

std::unique_ptr<QSettings> appSettings()
{
    return std::make_unique<QSettings>(QStringLiteral("camwb"), QStringLiteral("CAM Workbench"));
}

Preferences Preferences::load()
{
    const auto settings = appSettings();
    Preferences p;
    settings->beginGroup(QStringLiteral("preferences"));
    p.units = settings->value(QStringLiteral("units")).toString() == QLatin1String("inch") ? LengthUnit::Inch
                                                                                           : LengthUnit::Millimetre;
    p.defaultPostId = settings->value(QStringLiteral("defaultPost")).toString();
    p.defaultMachineId = settings->value(QStringLiteral("defaultMachine")).toString();
    p.toolLibraryPath = settings->value(QStringLiteral("toolLibrary")).toString();
    p.language = languageFrom(settings->value(QStringLiteral("language")).toString());
    // Below 5 s the writes would follow every keystroke; above an hour they protect little.
    p.autosaveSeconds = std::clamp(settings->value(QStringLiteral("autosaveSeconds"), 60).toInt(), 5, 3600);
    settings->endGroup();
    return p;
}

void Preferences::save() const
{
    const auto settings = appSettings();
    settings->beginGroup(QStringLiteral("preferences"));
    settings->setValue(QStringLiteral("units"), unitKey(units));
    settings->setValue(QStringLiteral("defaultPost"), defaultPostId);
    settings->setValue(QStringLiteral("defaultMachine"), defaultMachineId);
    settings->setValue(QStringLiteral("toolLibrary"), toolLibraryPath);
    settings->setValue(QStringLiteral("language"), languageKey(language));
    settings->setValue(QStringLiteral("autosaveSeconds"), autosaveSeconds);
    settings->endGroup();
}

QLocale uiLocale(Language language)
{
    switch (language) {
    case Language::English:
        return QLocale(QLocale::English, QLocale::UnitedStates);
    case Language::Czech:
        return QLocale(QLocale::Czech, QLocale::CzechRepublic);
    case Language::System:
        break;
    }
    return QLocale();
}

QString formatLength(double mm, LengthUnit unit)
{
    if (unit == LengthUnit::Inch)
        return QLocale().toString(mm / 25.4, 'f', 4) + QStringLiteral(" in");
    return QLocale().toString(mm, 'f', 3) + QStringLiteral(" mm");
}

}  // namespace camwb::gui
