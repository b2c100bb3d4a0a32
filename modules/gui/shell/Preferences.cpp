#include "gui/shell/Preferences.h"

#include <QSettings>

#include <algorithm>
#include <atomic>

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

namespace {
constexpr double kMmPerInch = 25.4;
std::atomic<LengthUnit> g_displayUnit{LengthUnit::Millimetre};
}  // namespace

LengthUnit displayUnit() { return g_displayUnit.load(); }

void setDisplayUnit(LengthUnit unit) { g_displayUnit.store(unit); }

double toDisplayUnit(double mm, LengthUnit unit) { return unit == LengthUnit::Inch ? mm / kMmPerInch : mm; }

double fromDisplayUnit(double value, LengthUnit unit) { return unit == LengthUnit::Inch ? value * kMmPerInch : value; }

QString unitSymbol(LengthUnit unit) { return unit == LengthUnit::Inch ? QStringLiteral("in") : QStringLiteral("mm"); }

int lengthDecimals(LengthUnit unit) { return unit == LengthUnit::Inch ? 4 : 3; }

QString formatLengthNumber(double mm, LengthUnit unit)
{
    return QLocale().toString(toDisplayUnit(mm, unit), 'f', lengthDecimals(unit));
}

QString formatLength(double mm, LengthUnit unit) { return formatLengthNumber(mm, unit) + ' ' + unitSymbol(unit); }

QString formatLength(double mm) { return formatLength(mm, displayUnit()); }

QString formatLengthNumber(double mm) { return formatLengthNumber(mm, displayUnit()); }

QString unitSymbol() { return unitSymbol(displayUnit()); }

}  // namespace camwb::gui
