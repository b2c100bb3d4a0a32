#include "sheet/SheetHtml.h"

#include "base/NumberFormat.h"

#include <cmath>

namespace camwb::sheet {

namespace {

using document::SetupSheet;
using document::workOffsetName;

std::string whole(double value) { return base::formatFixed(value, 0); }

// Lengths and feeds as the sheet shows them: mm and mm/min (the job's own), or inch and in/min.
struct Units {
    bool inch = false;
    double shown(double mm) const { return inch ? mm / 25.4 : mm; }
    std::string len(double mm) const { return base::formatFixed(shown(mm), inch ? 4 : 3); }
    std::string signedLen(double mm) const { return (mm >= 0 ? "+" : "") + len(mm); }
    std::string path(double mm) const { return base::formatFixed(shown(mm), inch ? 2 : 1); }  // path lengths
    std::string feed(double mmPerMin) const { return inch ? base::formatFixed(shown(mmPerMin), 1) : whole(mmPerMin); }
    std::string unit() const { return inch ? "in" : "mm"; }
    std::string feedUnit() const { return inch ? "in/min" : "mm/min"; }
};

// One table row: header cells (th) or data cells (td), each escaped.
std::string row(const std::vector<std::string>& cells, bool header = false)
{
    const char* tag = header ? "th" : "td";
    std::string out = "<tr>";
    for (const std::string& cell : cells)
        out += std::string("<") + tag + ">" + escapeHtml(cell) + "</" + tag + ">";
    return out + "</tr>\n";
}

std::string table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows)
{
    std::string out = "<table border=\"1\" cellspacing=\"0\" cellpadding=\"3\" width=\"100%\">\n" + row(header, true);
    for (const auto& cells : rows)
        out += row(cells);
    return out + "</table>\n";
}

std::string image(const SheetImage& picture, const std::string& alt)
{
    if (picture.file.empty())
        return {};
    return "<p><img src=\"" + escapeHtml(picture.file) + "\" width=\"" + std::to_string(picture.width) +
           "\" height=\"" + std::to_string(picture.height) + "\" alt=\"" + escapeHtml(alt) + "\"></p>\n";
}

std::string vec(const Units& u, const base::Vec3& p)
{
    return "X " + u.len(p.x) + "  Y " + u.len(p.y) + "  Z " + u.len(p.z);
}

std::string summary(const SetupSheet& sheet, const Units& u)
{
    std::vector<std::vector<std::string>> rows{
        {"NC program", sheet.ncFile},
        {"Job file", sheet.jobFile},
        {"Model", sheet.modelFile},
        {"Machine",
         sheet.machineId.empty() ? "none given (default limits)" : sheet.machineName + " (" + sheet.machineId + ")"},
        {"Post", sheet.postDescription + " (" + sheet.postId + ")"},
        {"Work offset",
         workOffsetName(sheet.workOffset, sheet.postId) + " (work offset " + std::to_string(sheet.workOffset) + ")"},
        {"Cycle time", formatDuration(sheet.cycleSeconds) + " planned on the machine (distance/feed estimate " +
                           formatDuration(sheet.simpleSeconds) + ")"},
        {"Path length", "rapid " + u.path(sheet.rapidLengthMm) + " " + u.unit() + ", feed " +
                            u.path(sheet.feedLengthMm) + " " + u.unit()},
        {"Tools / operations", std::to_string(sheet.tools.size()) + " / " + std::to_string(sheet.operations.size())}};
    for (const auto& [name, value] : sheet.postProperties)
        rows.push_back({"Post property " + name, value});
    return table({"Item", "Value"}, rows);
}

std::string toolTable(const SetupSheet& sheet, const Units& u)
{
    std::vector<std::vector<std::string>> rows;
    for (const document::SheetTool& t : sheet.tools) {
        const toolpath::Tool& tool = t.controller.tool;
        std::string stickOut = t.stickOutMm ? u.len(*t.stickOutMm) : std::string("not used");
        if (t.tooShort)
            stickOut += " - TOOL TOO SHORT (" + u.len(tool.lengthMm) + " overall)";
        std::string users;
        for (const std::string& op : t.operations)
            users += (users.empty() ? "" : ", ") + op;
        rows.push_back({"T" + std::to_string(tool.number), tool.name, tool.kind, u.len(tool.diameterMm),
                        u.len(tool.cornerRadiusMm), u.len(tool.fluteLengthMm), u.len(tool.lengthMm),
                        tool.holder.empty() ? "-" : tool.holder, stickOut, whole(t.controller.spindleRpm), users});
    }
    const std::string in = " " + u.unit();
    return table({"Tool", "Name", "Kind", "\u00d8" + in, "Corner R" + in, "Flute length" + in, "Overall length" + in,
                  "Holder", "Min. stick-out" + in, "Spindle rpm", "Used by"},
                 rows);
}

std::string stockTable(const SetupSheet& sheet, const Units& u)
{
    std::vector<std::vector<std::string>> rows;
    const base::Box3 model = sheet.modelBounds;
    if (sheet.stock) {
        const base::Box3& s = *sheet.stock;
        rows.push_back({"Stock box (from, to)", vec(u, s.min) + "  to  " + vec(u, s.max)});
        rows.push_back({"Stock size (X \u00d7 Y \u00d7 Z)", u.len(s.max.x - s.min.x) + " \u00d7 " +
                                                                u.len(s.max.y - s.min.y) + " \u00d7 " +
                                                                u.len(s.max.z - s.min.z) + " " + u.unit()});
        // Where the program zero lies, measured from what the operator touches off: the stock's
        // front left corner and its top.
        rows.push_back({"Program zero X0 Y0", u.signedLen(-s.min.x) + " / " + u.signedLen(-s.min.y) + " " + u.unit() +
                                                  " from the stock's front left corner (X min, Y min)"});
        const std::string belowTop =
            s.max.z >= 0 ? u.len(s.max.z) + " " + u.unit() + " below" : u.len(-s.max.z) + " " + u.unit() + " above";
        rows.push_back(
            {"Program zero Z0", belowTop + " the stock top (the stock bottom is at Z " + u.len(s.min.z) + ")"});
    } else if (sheet.verification.turning) {
        rows.push_back({"Stock",
                        "the shaft each groove is cut in: under the groove's surface line (its start point and "
                        "cone angle), X a radius"});
    } else {
        rows.push_back({"Stock", "none given: the model's bounds"});
    }
    if (!sheet.verification.turning)  // a lathe job has no model
        rows.push_back({"Model bounds (from, to)", vec(u, model.min) + "  to  " + vec(u, model.max)});
    rows.push_back(
        {"Work offset", workOffsetName(sheet.workOffset, sheet.postId) + ": set it to the program zero above"});
    return table({"Item", "Value"}, rows);
}

std::string operationTable(const SetupSheet& sheet, const Units& u)
{
    std::vector<std::vector<std::string>> rows;
    int index = 1;
    for (const document::SheetOperation& op : sheet.operations) {
        const auto z = [&](double ops::Heights::*height) { return op.heights ? u.len((*op.heights).*height) : "-"; };
        rows.push_back({std::to_string(index++), op.name, op.kind, "T" + std::to_string(op.toolNumber),
                        op.turningSpeed.empty() ? whole(op.spindleRpm) : op.turningSpeed,
                        op.turningFeed.empty() ? u.feed(op.cuttingFeed) : op.turningFeed,
                        op.turningFeed.empty() ? u.feed(op.plungeFeed) : "-",
                        op.turningFeed.empty() ? u.feed(op.rampFeed) : "-", z(&ops::Heights::clearanceZ),
                        z(&ops::Heights::safeZ), z(&ops::Heights::startZ), z(&ops::Heights::finalZ),
                        op.stepDownMm > 0 ? u.len(op.stepDownMm) : "-", formatDuration(op.seconds)});
    }
    const std::string feed = " " + u.feedUnit();
    return table({"#", "Operation", "Kind", "Tool", "Spindle rpm", "Feed" + feed, "Plunge" + feed, "Ramp" + feed,
                  "Clearance Z", "Safe Z", "Top Z", "Bottom Z", "Step-down " + u.unit(), "Time"},
                 rows);
}

std::string verificationSection(const SetupSheet& sheet, const Units& u)
{
    const document::SheetVerification& v = sheet.verification;
    if (!v.run)
        return "<p>The simulator was not run for this sheet (--no-sim): nothing below is verified "
               "beyond the stick-out.</p>\n";
    const int errors = v.gouges + v.holderCollisions + v.rapidsInStock + v.machineLimits + v.otherErrors;
    std::string out = std::string("<p><b>") + (errors == 0 ? "Simulated: no errors." : "Simulated: ERRORS FOUND.") +
                      (v.turning ? "</b> The grooves' shaft (a revolved profile) cut by the insert, checked against "
                                   "their offset contour (the allowances must stay).</p>\n"
                                 : "</b> Stock cut at " + u.len(v.resolutionMm) + " " + u.unit() +
                                       " resolution against the model.</p>\n");
    out += table({"Check", "Count"}, {{"Gouges into the model", std::to_string(v.gouges)},
                                      {"Holder or shank collisions with the stock", std::to_string(v.holderCollisions)},
                                      {"Rapids through stock", std::to_string(v.rapidsInStock)},
                                      {"Machine limits exceeded", std::to_string(v.machineLimits)},
                                      {"Other errors", std::to_string(v.otherErrors)},
                                      {"Warnings", std::to_string(v.warnings)},
                                      {"Deepest gouge " + u.unit(), u.len(v.maxGougeMm)},
                                      {"Cycle time", formatDuration(sheet.cycleSeconds)}});
    if (!v.firstFindings.empty()) {
        out += "<ul>\n";
        for (const std::string& finding : v.firstFindings)
            out += "<li>" + escapeHtml(finding) + "</li>\n";
        out += "</ul>\n";
    }
    return out;
}

}  // namespace

std::string escapeHtml(const std::string& text)
{
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string formatDuration(double seconds)
{
    seconds = std::round(seconds * 10) / 10;  // as shown, so that 119.97 s is not "1 min 60.0 s"
    if (seconds < 60)
        return base::formatFixed(seconds, 1) + " s";
    const double minutes = std::floor(seconds / 60);
    return base::formatFixed(minutes, 0) + " min " + base::formatFixed(seconds - minutes * 60, 1) + " s";
}

std::string sheetHtml(const SetupSheet& sheet, const SheetImages& images, SheetUnit unit)
{
    Units u;
    u.inch = unit == SheetUnit::Inch;
    const std::string title = "Setup sheet: " + sheet.jobName;
    std::string out = "<!DOCTYPE html>\n<html>\n<head>\n<meta charset=\"utf-8\">\n<title>" + escapeHtml(title) +
                      "</title>\n<style>\nbody { font-family: sans-serif; font-size: 10pt; }\n"
                      "table { border-collapse: collapse; margin-bottom: 8pt; }\n"
                      "th { background: #e0e0e0; text-align: left; }\n</style>\n</head>\n<body>\n";
    out += "<h1>" + escapeHtml(title) + "</h1>\n";
    out += "<p>Created " + escapeHtml(sheet.created) + " UTC by " + escapeHtml(sheet.user) + " with CAM Workbench " +
           escapeHtml(sheet.version) + ". Lengths in " + u.unit() + ", feeds in " + u.feedUnit() +
           ", Z values in the work offset's frame.</p>\n";
    out += summary(sheet, u);
    out += "<h2>Tools</h2>\n<p>Minimum stick-out: from the holder face to the tool tip, the deepest the tip goes "
           "below the highest point the holder must clear (stock or model top) plus " +
           u.len(sheet.stickOutMarginMm) + " " + u.unit() +
           "; for a tilted tool, below the highest corner of the stock along its axis.</p>\n";
    out += toolTable(sheet, u);
    out += "<h2>Stock and work zero</h2>\n" + stockTable(sheet, u);
    out += image(images.part,
                 "the part on its stock with the whole toolpath; the work zero's axes X red, Y green, Z blue");
    out += "<h2>Operations</h2>\n" + operationTable(sheet, u);
    for (std::size_t i = 0; i < sheet.operations.size(); ++i) {
        const document::SheetOperation& op = sheet.operations[i];
        out += "<h3>" + std::to_string(i + 1) + ". " + escapeHtml(op.name) + " (T" + std::to_string(op.toolNumber) +
               ", " + escapeHtml(formatDuration(op.seconds)) + ")</h3>\n";
        if (i < images.operations.size())
            out += image(images.operations[i], op.name + ": its toolpath highlighted");
    }
    out += "<h2>Verification</h2>\n" + verificationSection(sheet, u);
    out += "</body>\n</html>\n";
    return out;
}

}  // namespace camwb::sheet
