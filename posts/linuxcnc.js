// LinuxCNC 2.9 (RS274NGC) three-axis mill, millimetres: plain ISO output that LinuxCNC's own
// interpreter (`rs274`) reads back to the CL path within 0.0005 mm (tests/external). Every word
// follows the LinuxCNC 2.9 G-code reference (docs/src/gcode in the LinuxCNC sources):
//   overview.adoc "Overview" (% demarcation), "Format of a line" (at most 256 characters; rs274 2.9
//     refuses lines over 252), "Comments" (no nesting), "Messages"/"Logging"/"Print" (active
//     comments MSG, DEBUG, PRINT, LOG*, PROBE*), "Modal Groups" (M7 and M8 can both be on);
//   g-code.adoc "G2, G3 Arc Move" (center format I/J/K per plane, G2 = clockwise seen from the
//     positive axis, start = end is a full circle, radius mismatch tolerance 0.005 mm, at least 3
//     decimals for mm), "G4 Dwell" (P in seconds), "G17 - G19.1", "G40" (the move after G40 must be
//     straight), "G41, G42" (D = tool number; not in G19), "G43" (H = tool number),
//     "G54-G59.3", "G80-G89 Canned Cycles" (preliminary motion, sticky Z and R, retract mode,
//     "cutter compensation active during a canned cycle" and "inverse time" are errors), "G73",
//     "G81", "G82", "G83", "G84" (floating tap: no spindle sync, needs M3), "G85", "G89",
//     "G90.1, G91.1", "G93, G94, G95" (G93: F on every feed block), "G98, G99"; P, Q and R are
//     sticky across cycles in rs274 2.9 (a G82's P reappears in a later G84), so they are always written;
//   m-code.adoc "M0, M1", "M2, M30", "M3, M4, M5", "M6", "M7, M8, M9".
// Conventions: no block numbers, 3 decimals (mm: the reference's minimum for arcs, and what FreeCAD
// 0.20's linuxcnc_post writes), modal G words and axes, F/S/P trimmed (G93/G95 feeds need
// decimals), I/J/K relative to the *written* start point so rounding never breaks the radius check.
var post = {
    id: "linuxcnc",
    description: "LinuxCNC 2.9 (RS274NGC), 3-axis mill, mm",
    vendor: "LinuxCNC",
    extension: "ngc",
    controls: ["linuxcnc"],
    capabilities: {
        arcPlanes: ["XY", "ZX", "YZ"],  // arcs in other planes reach the post as lines
        helicalArcs: true,
        // Whole circles and whole helix turns are one block each (LinuxCNC takes start = end as a full turn).
        maxArcSweep: 360,
        arcWords: "center",
        cycles: ["drill", "drillDwell", "peck", "chipBreak", "tap", "bore"],
        maxAxes: 3
    }
};

var xyzFormat = createFormat({decimals: 3});
var feedFormat = createFormat({decimals: 3, trim: true});
var rpmFormat = createFormat({decimals: 3, trim: true});
var secondsFormat = createFormat({decimals: 3, trim: true});

var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var iOutput = createVariable({prefix: "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: "J", force: true}, xyzFormat);
var kOutput = createVariable({prefix: "K", force: true}, xyzFormat);
var feedOutput = createVariable({prefix: "F"}, feedFormat);
var motionModal = createModal({prefix: "G"});
var planeModal = createModal({prefix: "G"});
var feedModeModal = createModal({prefix: "G"});
var workOffsetModal = createModal({prefix: "G"});

// Moves are written by the kernel in C++ from these templates, sharing the variables above with the
// handlers below. The kernel measures I/J/K from the start as written and writes an arc whose
// written end is its start as a G1 (LinuxCNC would read it as a full circle); the plane word is
// written when it changes; helices are arcs whose third axis moves.
post.blocks = {
    rapid: [motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"), zOutput.bind("z")],
    linear: [motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"), zOutput.bind("z"),
             feedOutput.bind("feed")],
    circular: {
        XY: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), iOutput.bind("i"), jOutput.bind("j"), feedOutput.bind("feed")],
        ZX: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), iOutput.bind("i"), kOutput.bind("k"), feedOutput.bind("feed")],
        YZ: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), jOutput.bind("j"), kOutput.bind("k"), feedOutput.bind("feed")]
    }
};

var feedMode = "perMinute";
var toolNumber = 0;
var toolRadius = 0;
var spindle = "off";        // "off", "cw", "ccw": G84 needs "cw"
var spindleRpm = 0;
var coolant = "off";
var compSide = "off";

// LinuxCNC acts on comments that start with these words (after removing blanks, any case).
var activeComments = /^(msg,|debug,|print,|log,|logopen,|logappend,|logclose|probeopen|probeclose|abort,|py,)/;
var maxCommentBytes = 250;  // "(" + text + ")" stays within rs274's 252-character lines

function utf8Length(text) {
    var bytes = 0;
    for (var i = 0; i < text.length; ++i) {
        var c = text.charCodeAt(i);
        bytes += c < 0x80 ? 1 : c < 0x800 ? 2 : (c >= 0xd800 && c < 0xe000) ? 2 : 3;  // a surrogate pair: 4 in all
    }
    return bytes;
}

// Comments never nest, never span lines and never trigger LinuxCNC's active comments.
function comment(text) {
    var clean = String(text).replace(/[\r\n\t]+/g, " ").replace(/\(/g, "[").replace(/\)/g, "]").trim();
    if (!clean)
        return;
    if (activeComments.test(clean.replace(/\s+/g, "").toLowerCase()))
        clean = "- " + clean;
    while (utf8Length(clean) > maxCommentBytes) {
        var cut = clean.length - 1;
        if (cut > 0 && clean.charCodeAt(cut - 1) >= 0xd800 && clean.charCodeAt(cut - 1) < 0xdc00)
            --cut;  // never half a surrogate pair
        clean = clean.substring(0, cut);
    }
    writeBlock("(" + clean + ")");
}

function workOffsetCode(index) {
    if (index >= 1 && index <= 6)
        return String(53 + index);            // G54..G59
    if (index >= 7 && index <= 9)
        return "59." + (index - 6);           // G59.1..G59.3
    error("work offset " + index + " is not available on LinuxCNC (1..9 = G54..G59.3)");
}

// The first move after a section start or a tool change writes all axes, G and F again.
function forceMotion() {
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    feedOutput.reset();
    motionModal.reset();
}

function onOpen(program) {
    setBlockNumbering(1, 1, false);
    writeln("%");
    comment(programName);
    comment("generated by CAM Workbench " + version + " post " + post.id);
    comment("user " + user);
    comment("date " + dateString);
    writeBlock("G21", "G90", feedModeModal.format(94), planeModal.format(17), "G40", "G49", "G80", "G91.1");
    writeBlock(workOffsetModal.format(workOffsetCode(program.workOffset)));
}

function onWorkOffset(index) {
    if (compSide != "off")
        error("work offset selected with cutter compensation on: LinuxCNC refuses G54..G59.3 under G41/G42");
    writeBlock(workOffsetModal.format(workOffsetCode(index)));
}

function onSection(section) {
    comment(section.operationName);
    forceMotion();
}

function onSectionEnd() {
}

function onToolChange(tool) {
    var number = Math.trunc(tool.number);
    if (!(number >= 1))
        error("tool number " + tool.number + ": LinuxCNC tool numbers for T and H start at 1");
    if (compSide != "off")
        error("tool change with cutter compensation on: turn it off (G40) first");
    comment("T" + number + (tool.name ? " " + tool.name : "") + " dia " + xyzFormat.format(tool.diameter));
    writeBlock("T" + number, "M6");
    writeBlock("G43", "H" + number);
    toolNumber = number;
    toolRadius = tool.diameter / 2;
    if (spindle != "off")  // M6 stops the spindle; in the CL it keeps turning until a Spindle record stops it
        writeBlock(spindle == "cw" ? "M3" : "M4", "S" + rpmFormat.format(spindleRpm));
    forceMotion();
}

function onSpindle(rpm, clockwise) {
    if (rpm <= 0) {
        writeBlock("M5");
        spindle = "off";
    } else {
        writeBlock(clockwise ? "M3" : "M4", "S" + rpmFormat.format(rpm));
        spindle = clockwise ? "cw" : "ccw";
        spindleRpm = rpm;
    }
}

function onCoolant(mode) {
    var code = {off: "M9", flood: "M8", mist: "M7"}[mode];
    if (!code) {
        warning("coolant mode " + mode + " has no LinuxCNC code (M7 mist, M8 flood): not output");
        return;
    }
    if (mode == coolant)
        return;
    if (mode != "off" && coolant != "off")
        writeBlock("M9");  // M7 and M8 add up: switching from one to the other turns the first off
    writeBlock(code);
    coolant = mode;
}

function onFeedMode(mode) {
    var code = {perMinute: 94, perRevolution: 95, inverseTime: 93}[mode];
    if (!code)
        error("feed mode " + mode + " is not known to this post");
    writeBlock(feedModeModal.format(code));
    feedMode = mode;
    feedOutput.reset();  // LinuxCNC wants a new F after G93, G94 and G95
    feedOutput.setForce(mode == "inverseTime");  // and under G93 an F in every G1/G2/G3 block
}

function onCutterComp(side) {
    if (side == compSide)
        return;
    // The kernel makes sure a straight move follows and warns when it is not longer than the
    // tool radius; arcs outside XY under compensation it refuses.
    if (side == "off") {
        writeBlock("G40");
    } else {
        if (compSide != "off")
            error("cutter compensation changes from " + compSide + " to " + side + " without turning off first");
        writeBlock(planeModal.format(17), side == "left" ? "G41" : "G42", toolNumber ? "D" + toolNumber : "");
    }
    compSide = side;
}

function onComment(text) {
    comment(text);
}

function onDwell(seconds) {
    if (!(seconds >= 0))
        error("dwell of " + seconds + " s: LinuxCNC needs P >= 0");
    writeBlock("G4", "P" + secondsFormat.format(seconds));
}

function onStop(optional) {
    writeBlock(optional ? "M1" : "M0");
}

function onPassThrough(text) {
    writeln(String(text));
}

var cycleCodes = {drill: 81, drillDwell: 82, chipBreak: 73, peck: 83, tap: 84, bore: 85};

function onCycle(cycle) {
    if (!cycle.holes.length)
        return;
    if (compSide != "off")
        error("canned cycle with cutter compensation on: LinuxCNC refuses G73..G89 under G41/G42");
    if (feedMode == "inverseTime")
        error("canned cycle in inverse time feed mode (G93): LinuxCNC refuses it");
    var code = cycleCodes[cycle.kind];
    if (!code)
        error("cycle kind " + cycle.kind + " is not known to this post");
    var dwell = cycle.dwell > 0 ? cycle.dwell : 0;
    if (code == 81 && dwell > 0)
        code = 82;
    if (code == 85 && dwell > 0)
        code = 89;  // bore, dwell, feed out
    if ((code == 73 || code == 83) && !(cycle.peck > 0))
        error("peck cycle without a peck depth: LinuxCNC needs Q > 0");
    if ((code == 73 || code == 83) && dwell > 0)
        warning("dwell of " + dwell + " s not output: LinuxCNC 2.9 has no dwell in G73/G83 (its P is refused there)");
    if (code == 84 && spindle != "cw")
        error("tapping cycle without the spindle turning clockwise: LinuxCNC's G84 needs M3");
    if (!(cycle.feed > 0))
        error("canned cycle without a feed rate");
    if (!(cycle.retractZ > cycle.bottomZ))
        error("cycle R plane " + xyzFormat.format(cycle.retractZ) + " is not above the depth " +
              xyzFormat.format(cycle.bottomZ));
    var toClearance = cycle.returnToClearance !== false;

    // G98 returns to the Z held before the cycle: stand at the clearance plane first. G99 returns
    // to R; LinuxCNC then rises to R if below it and travels to the first hole at that height.
    if (toClearance) {
        var zWord = zOutput.format(cycle.clearanceZ);
        if (zWord)
            writeBlock(motionModal.format(0), zWord);
    }
    feedOutput.reset();
    for (var i = 0; i < cycle.holes.length; ++i) {
        var hole = cycle.holes[i];
        var words = ["X" + xyzFormat.format(hole.x), "Y" + xyzFormat.format(hole.y)];
        if (i == 0) {
            words = [planeModal.format(17), toClearance ? "G98" : "G99", "G" + code].concat(words);
            words.push("Z" + xyzFormat.format(cycle.bottomZ), "R" + xyzFormat.format(cycle.retractZ));
            if (code == 73 || code == 83)
                words.push("Q" + xyzFormat.format(cycle.peck));
            if (code == 82 || code == 84 || code == 89)  // P is sticky across cycles: always written
                words.push("P" + secondsFormat.format(dwell));
            words.push(feedOutput.format(cycle.feed));
        }
        writeBlock.apply(null, words);
    }
    writeBlock("G80");

    // The tool stands over the last hole at LinuxCNC's clear Z (the higher of R and the start Z
    // under G98, R under G99), where the kernel continues too: later moves omit unchanged axes.
    var last = cycle.holes[cycle.holes.length - 1];
    motionModal.reset();
    xOutput.format(last.x);
    yOutput.format(last.y);
    zOutput.reset();
    zOutput.format(toClearance ? Math.max(cycle.clearanceZ, cycle.retractZ) : cycle.retractZ);
}

function onClose() {
    writeBlock("M5", "M9");
    writeBlock("M2");
    writeln("%");
}
