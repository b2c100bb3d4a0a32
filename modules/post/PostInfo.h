// What a post declares about itself, read once when it is loaded and without running any event
// handler: identity, capabilities (which arcs and cycles it writes natively) and typed user
// properties. Qt-free, so the CLI and the GUI can list and validate without a script engine.
#pragma once

#include "base/Result.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace camwb::post {

// What the kernel may hand to the post; everything else it converts first (arcs into lines,
// cycles into moves) or refuses with an error.
struct PostCapabilities {
    std::vector<std::string> arcPlanes{"XY", "ZX", "YZ"};      // other planes' arcs are linearised
    std::vector<std::string> helicalPlanes{"XY", "ZX", "YZ"};  // helices in other planes are linearised
    double maxArcSweepDeg = 180;    // longer arcs and full circles are split into equal pieces
    double maxHelixSweepDeg = 0;    // helices: the same, at most this per piece (0: maxArcSweepDeg)
    double minArcRadiusMm = 0.001;  // arcs outside [min, max] are linearised
    double maxArcRadiusMm = 100000;
    bool arcRadiusWords = false;      // the post writes R/CR (no full circles, signed radius) instead of centres
    double toleranceMm = 0.01;        // chord error when the kernel linearises an arc
    std::vector<std::string> cycles;  // cycle kinds written natively ("drill", "peck", ...); others expanded
    bool cyclesDeclared = false;      // false: native when the post has onCycle/onCyclePoint, else expanded
    int maxAxes = 3;                  // 3: five-axis moves are refused

    bool writesCycle(const std::string& kind) const;
    bool writesHelix(const std::string& plane) const;
};

enum class PropertyType { Bool, Integer, Number, Enum, String };

struct PropertyDef {
    std::string name;
    std::string title;
    std::string description;
    PropertyType type = PropertyType::String;
    std::string defaultValue;         // canonical text: "true", "12", "0.5", an enum value, any text
    std::optional<double> min, max;   // Integer and Number
    std::vector<std::string> values;  // Enum
    int line = 0;                     // where the post script declares it, for messages
    bool perOperation = false;        // the post reads it per section: an operation may set its own
};

// A property value resolved for one run: from the user, or the default.
struct PropertyValue {
    PropertyType type = PropertyType::String;
    bool boolean = false;
    double number = 0;
    std::string text;  // Enum and String; canonical text for the others
    bool fromUser = false;
};

struct PostInfo {
    std::string id;  // the file's base name (post.id, when given, must match it)
    std::string description;
    std::string vendor;
    std::string extension;  // without the dot, e.g. "mpf"; "nc" when the post names none
    std::string filePath;
    PostCapabilities capabilities;
    std::vector<PropertyDef> properties;
    std::vector<std::string> machines;  // machine ids the post accepts; empty: any
    std::string defaultMachine;         // used when the job or the command line names none
    std::vector<std::string> controls;  // controls it writes for ("sinumerik-828d"); empty: any

    const PropertyDef* property(const std::string& name) const;
};

const char* propertyTypeName(PropertyType type);  // "bool", "int", "number", "enum", "string"
std::optional<PropertyType> propertyTypeFromName(const std::string& name);

// `text` as a value of `def`, or an Error saying what the property accepts.
base::Result<PropertyValue> parsePropertyValue(const PropertyDef& def, const std::string& text);

// Every declared property with the user's value (given as text, by name) or its default. Unknown
// names are an error that lists the post's properties.
base::Result<std::map<std::string, PropertyValue>>
resolveProperties(const PostInfo& info, const std::map<std::string, std::string>& userValues);

// "name=value" from the command line.
base::Result<std::pair<std::string, std::string>> splitPropertyAssignment(const std::string& text);

}  // namespace camwb::post
