// The user's preferences, kept with QSettings (organisation "camwb", application "CAM Workbench"):
// display units, the post and machine a new job starts with, the tool library's file, the
// language and the autosave interval. Units are for display only: jobs and NC stay in mm.
#pragma once

#include <QLocale>
#include <QString>

#include <memory>

class QSettings;

namespace camwb::gui {

enum class LengthUnit { Millimetre, Inch };
enum class Language { System, English, Czech };

struct Preferences {
    LengthUnit units = LengthUnit::Millimetre;
    QString defaultPostId;     // empty: the job format's default post
    QString defaultMachineId;  // empty: the post's default machine
    QString toolLibraryPath;   // empty: the library in the user's data folder
    Language language = Language::System;
    int autosaveSeconds = 60;  // how often unsaved edits are written to the side file

    static Preferences load();
    void save() const;
    bool operator==(const Preferences&) const = default;
};

// The application's settings store; tests redirect it with QSettings::setPath or XDG_CONFIG_HOME.
std::unique_ptr<QSettings> appSettings();

// The locale whose translations the GUI loads for `language` (System: the user's locale).
QLocale uiLocale(Language language);

// The one place lengths change unit for display (jobs, panels' values and NC stay in mm).
// The unit the window shows lengths in now: Session sets it from the preferences when it starts
// and when they change; what shows lengths reads it when it is made (a panel already open keeps
// the unit it opened with; the job tree is rebuilt).
LengthUnit displayUnit();
void setDisplayUnit(LengthUnit unit);
// mm -> `unit`, and back.
double toDisplayUnit(double mm, LengthUnit unit);
double fromDisplayUnit(double value, LengthUnit unit);
// "mm" or "in".
QString unitSymbol(LengthUnit unit);
QString unitSymbol();  // of displayUnit()
// Decimals a length shows with: 3 in mm, 4 in inch (about the same resolution).
int lengthDecimals(LengthUnit unit);

// A length held in mm as the user reads it: "12.500 mm" or "0.4921 in" (3 or 4 decimals, the
// locale's decimal separator). Display only: never feed the text back into a job or NC.
QString formatLength(double mm, LengthUnit unit);
QString formatLength(double mm);  // in displayUnit()
// The number alone ("12.500", "0.4921"), for texts that name the unit once.
QString formatLengthNumber(double mm, LengthUnit unit);
QString formatLengthNumber(double mm);  // in displayUnit()

}  // namespace camwb::gui
