// EMCO Concept MILL 105 with SINUMERIK 828D.
// Keeps every rule the control proved in seed-004 (SinuTrain and the real 828D, §3.2, §4.3, §4.4):
// numbered blocks from N10 step 10, ';' comments right after the block number, the `G17 G40` /
// `G54 G90` preamble, a comment before the tool change, `M6 T<n>`, `M3 S<n>`, modal G words and
// axes, 3 decimals, F in mm/min as a rounded integer and never on G0, G2/G3 with the two centre
// words of the plane always written (I J in G17, never K), X Y Z forced in helical arcs, `M30` and
// a final newline. Closes the gaps the thesis names (§7B): CYCLE81/82/83 (and CYCLE84/85) with
// MCALL or one call per hole, M5/M9 at the tool change and the end, D1 with the tool, coolant,
// G41/G42/G40, G710/G71/G700/G70 and the machine's limits (checked by the kernel).
var post = {
    id: "sinumerik828d-emco",
    description: "EMCO Concept MILL 105, SINUMERIK 828D (3-axis)",
    vendor: "EMCO / Siemens",
    extension: "mpf",
    machine: "emco-concept-mill-105",
    machines: ["emco-concept-mill-105"],
    capabilities: {
        arcPlanes: ["XY", "ZX", "YZ"],
        helicalArcs: true,
        maxArcSweep: 180,  // longer arcs and full circles are split into pieces of at most 180 deg
        cycles: ["drill", "drillDwell", "peck", "chipBreak", "tap", "bore"],
        maxAxes: 3
    },
    properties: {
        toolChangeComment: {
            title: "Tool change comment", type: "string", default: "Tool change",
            description: "Comment line before each tool change (the thesis post wrote 'Vymena nastroje')"
        },
        drillingCalls: {
            title: "Drilling cycle calls", type: "enum", values: ["mcall", "perHole"], default: "mcall",
            description: "MCALL CYCLE8x(...) followed by the hole positions, or one CYCLE8x(...) after each position"
        },
        units: {
            title: "Units word", type: "enum", values: ["G710", "G71", "G700", "G70", "none"], default: "G710",
            description: "G710/G71 metric (G710 also for feeds), G700/G70 inch output, none: the thesis preamble"
        },
        sequenceStart: {
            title: "First block number", type: "int", default: 10, min: 0,
            description: "Number of the first block"
        },
        sequenceStep: {
            title: "Block number step", type: "int", default: 10, min: 1, max: 1000,
            description: "Increment between block numbers"
        }
    }
};

var unitsWord = getProperty("units");
var inch = unitsWord == "G700" || unitsWord == "G70";
var xyzFormat = createFormat({decimals: inch ? 4 : 3, scale: inch ? 1 / 25.4 : 1});
// G700 takes feeds in inch/min as well; G70 changes only the geometry (the 828D's feed unit stays mm).
var feedFormat = unitsWord == "G700" ? createFormat({decimals: 1, scale: 1 / 25.4}) : createFormat({decimals: 0});
var feedPerRevFormat = createFormat({decimals: 3, scale: unitsWord == "G700" ? 1 / 25.4 : 1});
var inverseTimeFormat = createFormat({decimals: 3});
var secondsFormat = createFormat({decimals: 3, trim: true});
var cycleFormat = createFormat({decimals: inch ? 4 : 3, scale: inch ? 1 / 25.4 : 1});

var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var iOutput = createVariable({prefix: "I", force: true}, xyzFormat);
var jOutput = createVariable({prefix: "J", force: true}, xyzFormat);
var kOutput = createVariable({prefix: "K", force: true}, xyzFormat);
var feedOutput = createVariable({prefix: "F"}, feedFormat);
var motionModal = createModal({prefix: "G"});
var planeModal = createModal({prefix: "G"});
var compModal = createModal({prefix: "G"});
var workOffsetModal = createModal({prefix: "G"});
var feedModeModal = createModal({prefix: "G"});

// The per-move blocks run in C++ (no onRapid/onLinear/onCircular here): a million moves never
// enter the script engine. They share the modal variables above with the handlers below.
post.blocks = {
    rapid: [motionModal.bind("motion"), compModal.bind("comp"), xOutput.bind("x"), yOutput.bind("y"),
            zOutput.bind("z")],
    linear: [motionModal.bind("motion"), compModal.bind("comp"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), feedOutput.bind("feed")],
    circular: {
        // Without Y in helical blocks the 828D reports a wrong circle-centre definition (seed-004 §4.3).
        forceOnHelical: [xOutput, yOutput, zOutput],
        XY: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), iOutput.bind("i"), jOutput.bind("j"), feedOutput.bind("feed")],
        ZX: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), iOutput.bind("i"), kOutput.bind("k"), feedOutput.bind("feed")],
        YZ: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), jOutput.bind("j"), kOutput.bind("k"), feedOutput.bind("feed")]
    }
};

// What the CL left running; null until it says (the spindle may run from MDI): then M5/M9 are written.
var spindleOn = null;
var coolantOn = null;

// M5/M9 before a tool change and at the end, unless the CL already stopped spindle and coolant.
function stopSpindleAndCoolant() {
    writeBlock(spindleOn !== false ? "M5" : "", coolantOn !== false ? "M9" : "");
    spindleOn = false;
    coolantOn = false;
}

// Comments never carry parentheses (seed-004 R7).
function comment(text) {
    writeComment(String(text).replace(/[()]/g, ""));
}

function workOffsetCode(index) {
    if (index >= 1 && index <= 4)
        return 53 + index;      // G54..G57
    if (index >= 5 && index <= 99)
        return 500 + index;     // G505..G599, settable offsets of the 828D
    error("work offset " + index + " is not available on the SINUMERIK 828D (1..99)");
}

// The first move after a section start, a tool change or a cycle writes all axes, G and F again.
function forceMotion() {
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    feedOutput.reset();
    motionModal.reset();
}

function onOpen(program) {
    setBlockNumbering(getProperty("sequenceStart"), getProperty("sequenceStep"), true);
    comment(programName);
    comment("generated by CAM Workbench " + version + " post " + post.id);
    comment("user " + user);
    comment("date " + dateString);
    if (machine)
        comment("machine " + machine.name);
    writeBlock(planeModal.format(17), compModal.format(40));
    if (unitsWord != "none")
        writeBlock(unitsWord);
    writeBlock(workOffsetModal.format(workOffsetCode(program.workOffset)), "G90");
}

function onWorkOffset(index) {
    writeBlock(workOffsetModal.format(workOffsetCode(index)));
}

function onSection(section) {
    comment(section.operationName);
    forceMotion();
}

function onSectionEnd() {
}

function onToolChange(tool) {
    stopSpindleAndCoolant();
    comment(getProperty("toolChangeComment"));
    writeBlock("M6", "T" + Math.trunc(tool.number), "D1");
    forceMotion();
}

function onSpindle(rpm, clockwise) {
    spindleOn = rpm > 0;
    if (rpm <= 0)
        writeBlock("M5");
    else
        writeBlock(clockwise ? "M3" : "M4", "S" + Math.trunc(rpm));
}

function onCoolant(mode) {
    if (mode == "off") {
        writeBlock("M9");
        coolantOn = false;
    } else if (mode == "flood" || (mode == "mist" && machine && machine.coolants.indexOf("mist") >= 0)) {
        writeBlock(mode == "flood" ? "M8" : "M7");
        coolantOn = true;
    } else if (!machine || machine.coolants.indexOf(mode) >= 0) {
        // (Without this coolant on the machine, the kernel's limit check has said so already.)
        warning("coolant " + mode + " is not written by this post: not output");
    }
}

function onFeedMode(mode) {
    if (mode == "perMinute") {
        feedOutput.setFormat(feedFormat);
        writeBlock(feedModeModal.format(94));
    } else if (mode == "perRevolution") {
        feedOutput.setFormat(feedPerRevFormat);
        writeBlock(feedModeModal.format(95));
    } else {
        feedOutput.setFormat(inverseTimeFormat);
        writeBlock(feedModeModal.format(93));
    }
}

function onCutterComp(side) {
    // G41/G42/G40 go out with the next straight move (blocks.rapid/linear bind "comp"): the 828D
    // starts and ends compensation on a G0/G1 block, and the kernel refuses a change on an arc.
}

function onComment(text) {
    comment(text);
}

function onDwell(seconds) {
    writeBlock("G4", "F" + secondsFormat.format(seconds));  // F under G4 is seconds, this block only
}

function onStop(optional) {
    writeBlock(optional ? "M1" : "M0");
}

function onPassThrough(text) {
    writeBlock(text);
}

// --- Drilling: CYCLE81..85 with the parameter lists of the 828D (SINUMERIK Operate) ---------

var cycleCall = "";  // the CYCLE8x(...) text of the cycle in progress

function p(value) {  // one cycle parameter
    return cycleFormat.format(value);
}

function cycleText(cycle) {
    var rtp = cycle.returnZ, rfp = cycle.topZ, dp = cycle.bottomZ;
    var sdis = cycle.retractZ - cycle.topZ;
    if (sdis < 0)
        error("the R plane (" + cycle.retractZ + ") is below the hole top (" + cycle.topZ + "): no safety distance");
    var common = [p(rtp), p(rfp), p(sdis), p(dp)];
    var dwell = secondsFormat.format(cycle.dwell);
    switch (cycle.kind) {
    case "drill":
        return "CYCLE81(" + common.join(",") + ")";
    case "drillDwell":
        return "CYCLE82(" + common.concat(["", dwell]).join(",") + ")";
    case "peck":
    case "chipBreak":
        // FDEP: first depth (absolute); DAM 0: every infeed equals the first; FRF 1: full feed;
        // VARI 1 chip removal (full retract), 0 chip breaking; _VRT/_DIS1: the lift and re-entry
        // gap the kernel's own expansion uses; _DTD: dwell at the final depth.
        var first = cycle.peck > 0 ? Math.max(rfp - cycle.peck, dp) : dp;
        var vari = cycle.kind == "peck" ? 1 : 0;
        return "CYCLE83(" + common.concat(["", p(first), "", "0", "0", "0", "1", vari, "",
                                           p(cycle.peck > 0 ? cycle.peck : rfp - dp), p(cycle.peckClearance),
                                           dwell, p(cycle.peckClearance)]).join(",") + ")";
    case "tap":
        // Rigid tapping: the pitch is feed / speed; SDAC 3: spindle clockwise (M3) after the cycle.
        if (!(cycle.spindleRpm > 0))
            error("tapping needs the spindle running: no spindle speed before the cycle");
        var pitch = cycle.feed / cycle.spindleRpm * (cycle.spindleClockwise ? 1 : -1);
        return "CYCLE84(" + common.concat(["", dwell, cycle.spindleClockwise ? "3" : "4", "", p(pitch), "0",
                                           Math.trunc(cycle.spindleRpm), Math.trunc(cycle.spindleRpm)]).join(",") + ")";
    case "bore":
        // Feed in and out (FFR, RFF), as the kernel's expansion of a bore cycle does.
        return "CYCLE85(" + common.concat(["", dwell, feedFormat.format(cycle.feed),
                                           feedFormat.format(cycle.feed)]).join(",") + ")";
    }
    error("cycle " + cycle.kind + " is not supported by this post");
}

function onCycle(cycle) {
    cycleCall = cycleText(cycle);
    if (cycle.kind != "tap")
        writeBlock(feedOutput.format(cycle.feed));  // the cycles drill at the programmed F
    // Move over the holes at the return plane: the cycle itself only moves along Z. Below it, or
    // at a height nobody knows yet (right after a tool change), go there first.
    var z = getCurrentAxis("z");
    if (z === null || z < cycle.returnZ) {
        motionModal.reset();
        zOutput.reset();
        writeBlock(motionModal.format(0), zOutput.format(cycle.returnZ));
    }
    if (getProperty("drillingCalls") == "mcall")
        writeBlock("MCALL", cycleCall);
}

function onCyclePoint(x, y, z) {
    var words = [motionModal.format(0), xOutput.format(x), yOutput.format(y)];
    if (!words[1] && !words[2]) {  // the same position twice: MCALL needs a motion block to drill again
        xOutput.reset();
        words[1] = xOutput.format(x);
    }
    writeBlock(words[0], words[1], words[2]);
    if (getProperty("drillingCalls") != "mcall")
        writeBlock(cycleCall);
}

function onCycleEnd(cycle) {
    if (getProperty("drillingCalls") == "mcall")
        writeBlock("MCALL");
    zOutput.reset();  // the cycle left Z at its return plane
    motionModal.reset();
}

function onClose() {
    stopSpindleAndCoolant();
    writeBlock("M30");
}
