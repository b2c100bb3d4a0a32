// SINUMERIK 840D lathe (the Škoda SR 2000 of seed-001): the frame of the thesis' Kód 5 and the
// groove roughing either as G0/G1 blocks or as the thesis' five R-parameter subprograms.
// Frame: `G54 G18`, `G90 G71`, DIAMON (X written as a diameter, the CL's radius doubled) or
// DIAMOF (X the radius), a safe X before each tool (`G0 X`, the program's largest X plus a
// clearance), `T=<number> D1` (the number form Kód 5 uses, no M6: a lathe turret turns on T),
// `G96 S<m/min> LIMS=<rpm> M3` for constant surface speed (the CL's Spindle with a surface speed:
// its rpm is the limit) or `G97 S<rpm> M3`, `M8`, `G95` with F in mm/rev, G0/G1 X Z blocks in the
// XZ plane (only the axes a move gives), `M9 M5` and `M30` at the end.
// grooveOutput=subprograms: a section of strategy "groove-roughing" becomes its R-parameter input
// block (R0..R11, R30, one per line with the parameter's meaning), F, DIAMOF (the subprograms
// compute radii) / `PODPROG_ZAPICH` / DIAMON, and the five subprograms are written beside the
// program as PODPROG_*.SPF, copied from sinumerik840d-turn/groove/. The section's leading rapids
// in X alone (its retract to a safe X) are written; its other moves are the subprograms' to make.
// The narrow-groove fallback (parameter fallback = 1) has no subprogram form: an error.
var post = {
    id: "sinumerik840d-turn",
    description: "SINUMERIK 840D lathe (Škoda SR 2000), G18, DIAMON/DIAMOF, groove roughing expanded or as subprograms",
    vendor: "Siemens / Škoda",
    extension: "mpf",
    machine: "skoda-sr2000-840d",
    machines: ["skoda-sr2000-840d"],
    controls: ["sinumerik-840d"],
    capabilities: {
        arcPlanes: [],  // arcs are written as lines within the tolerance (the groove has none)
        helicalArcs: false,
        cycles: [],
        maxAxes: 3
    },
    properties: {
        diameterProgramming: {
            title: "Diameter programming (DIAMON)", type: "bool", default: true,
            description: "DIAMON and X as a diameter (twice the CL's radius); off: DIAMOF and X as the radius"
        },
        grooveOutput: {
            title: "Groove output", type: "enum", values: ["expanded", "subprograms"], default: "expanded",
            description: "Groove roughing as G0/G1 blocks, or as the call of PODPROG_ZAPICH with its R-parameter " +
                         "input block and the five PODPROG_*.SPF subprograms beside the program"
        },
        toolChangeClearance: {
            title: "Tool change clearance (radius, mm)", type: "number", default: 200, min: 0,
            description: "Before each tool the slide goes to X = the program's largest X + this (Kód 5: G0 X=R0+200)"
        }
    }
};

// The dialect's properties, formats, words and handlers shared with the other SINUMERIK posts.
include("sinumerik-common");

// A lathe drills nothing through CYCLE8x here, and Kód 5 writes G71 (not G710).
delete post.properties.drillingCalls;
post.properties.units.default = "G71";

var diameter = getProperty("diameterProgramming");
var subprograms = getProperty("grooveOutput") == "subprograms";
// X: the CL's radius, doubled under DIAMON (the control halves it again). X and Z with 4 decimals
// (5 in inch): the blocks then agree with the subprograms, which compute in full precision, within
// 1e-4 mm (seed REQ-22); the control rounds them to its own input resolution.
var xFormat = createFormat({decimals: inch ? 5 : 4, scale: (inch ? 1 / 25.4 : 1) * (diameter ? 2 : 1)});
xOutput = createVariable({prefix: "X"}, xFormat);
zOutput = createVariable({prefix: "Z"}, createFormat({decimals: inch ? 5 : 4, scale: inch ? 1 / 25.4 : 1}));
// Kód 5: G95 F0.2.
feedPerRevFormat = createFormat({decimals: 3, trim: true, scale: unitsWord == "G700" ? 1 / 25.4 : 1});
var inverseTimeFormat = createFormat({decimals: 3});  // named by the dialect's onFeedMode; G93 is refused here
var surfaceSpeedFormat = createFormat({decimals: 1, trim: true});
var parameterFormat = createFormat({decimals: 6, trim: true});
var speedModeModal = createModal({prefix: "G"});

// The groove's inputs in the thesis' R names, with what each means (no parentheses in comments).
var grooveParameters = [
    ["R0", "start point P: X, radius"], ["R1", "start point P: Z"], ["R2", "cone angle, deg"],
    ["R3", "depth below P"], ["R4", "bottom width"], ["R5", "right flank angle, deg"],
    ["R6", "left flank angle, deg"], ["R7", "bottom allowance in X"], ["R8", "flank allowance"],
    ["R9", "insert width"], ["R10", "step factor"], ["R11", "infeed per plunge"], ["R30", "safety distance"]];
var grooveFiles = ["PODPROG_ZAPICH", "PODPROG_ZL", "PODPROG_ZP", "PODPROG_DNO_ZL", "PODPROG_DNO_ZP"];

var largestX = null;      // of the whole program, for the safe X before a tool
var feedMode = "perMinute";
var grooveSection = null; // the section being written as the subprograms' call (mode B)
var grooveCalled = false; // its call is written: the rest of its moves are skipped
var subprogramsCalled = false;

function onOpen(program) {
    writeIdentity();
    if (program.extents && program.extents.max.x !== null)
        largestX = program.extents.max.x;
    writeBlock(workOffsetModal.format(workOffsetCode(program.workOffset)), planeModal.format(18));
    writeBlock("G90", unitsWord != "none" ? unitsWord : "");
    writeBlock(diameter ? "DIAMON" : "DIAMOF");
}

function onWorkOffset(index) {
    writeBlock(workOffsetModal.format(workOffsetCode(index)));
}

function onSection(section) {
    comment(section.operationName);
    forceMotion();
    grooveSection = null;
    grooveCalled = false;
    if (!subprograms || section.strategy != "groove-roughing")
        return;
    var p = section.parameters;
    if (p.fallback == 1)
        error("groove \"" + section.operationName + "\" uses the narrow-groove fallback (straight plunges), which " +
              "has no subprogram form: post it with grooveOutput=expanded");
    for (var i = 0; i < grooveParameters.length; ++i)
        if (typeof p[grooveParameters[i][0]] != "number")
            error("groove \"" + section.operationName + "\" carries no parameter " + grooveParameters[i][0] +
                  ": the subprograms cannot be called without it");
    grooveSection = section;
}

// The R-parameter input block and the call, where the groove's moves would begin.
function writeGrooveCall() {
    var p = grooveSection.parameters;
    if (feedMode != "perRevolution")
        error("groove \"" + grooveSection.operationName + "\": the subprograms cut at the programmed feed in mm/rev, " +
              "but the section sets no G95 before its moves");
    if (!(grooveSection.feeds.cutting > 0))
        error("groove \"" + grooveSection.operationName + "\" has no cutting feed for the subprograms");
    comment("groove roughing by PODPROG_ZAPICH, its inputs:");
    for (var i = 0; i < grooveParameters.length; ++i) {
        var name = grooveParameters[i][0];
        writeBlock(name + "=" + parameterFormat.format(p[name]), ";" + grooveParameters[i][1]);
    }
    feedOutput.reset();
    writeBlock(feedOutput.format(grooveSection.feeds.cutting));
    if (diameter)
        writeBlock("DIAMOF");  // the subprograms compute and program radii
    writeBlock("PODPROG_ZAPICH");
    if (diameter)
        writeBlock("DIAMON");
    // An alarm in the subprograms (an invalid input, a groove too narrow for them) stops with M0;
    // when the operator goes on, M17 returns here: stop again rather than run the next operation
    // over an unfinished groove. R31 = 1 only when a bottom phase finished it.
    writeBlock("IF R31<>1");
    writeBlock("MSG(\"groove " + grooveSection.operationName.replace(/[\"]/g, "") +
               " not finished: see the alarm of PODPROG_ZAPICH\")");
    writeBlock("SETAL(65019)");
    writeBlock("M0");
    writeBlock("ENDIF");
    forceMotion();  // the subprograms left G0/G1, X and Z where they ended
    grooveCalled = true;
    subprogramsCalled = true;
}

function onSectionEnd() {
    if (grooveSection && !grooveCalled)
        writeGrooveCall();
    grooveSection = null;
}

function onToolChange(tool) {
    // Spindle and coolant stop for the turret when the CL left them running.
    writeBlock(coolantOn === true ? "M9" : "", spindleOn === true ? "M5" : "");
    if (spindleOn === true)
        spindleOn = false;
    if (coolantOn === true)
        coolantOn = false;
    if (largestX !== null) {
        motionModal.reset();
        xOutput.reset();
        writeBlock(motionModal.format(0), xOutput.format(largestX + getProperty("toolChangeClearance")));
    }
    comment(getProperty("toolChangeComment"));
    writeBlock("T=" + Math.trunc(tool.number), "D1");
    forceMotion();
}

onSpindle = function (rpm, clockwise, surfaceSpeed) {
    var direction = clockwise ? "M3" : "M4";
    if (surfaceSpeed > 0) {
        if (!(rpm > 0))
            error("constant surface speed " + surfaceSpeed + " m/min without a speed limit: G96 needs LIMS");
        spindleOn = true;
        writeBlock(speedModeModal.format(96), "S" + surfaceSpeedFormat.format(surfaceSpeed),
                   "LIMS=" + Math.trunc(rpm), direction);
    } else if (rpm > 0) {
        spindleOn = true;
        writeBlock(speedModeModal.format(97), "S" + Math.trunc(rpm), direction);
    } else {
        spindleOn = false;
        writeBlock("M5");
    }
};

// The dialect's G94/G95 (sinumerik-common), remembered for mode B's check; no G93 on a lathe.
var dialectFeedMode = onFeedMode;
onFeedMode = function (mode) {
    if (mode != "perMinute" && mode != "perRevolution")
        error("inverse-time feed (G93) is not for a lathe");
    feedMode = mode;
    dialectFeedMode(mode);
};

// A lathe's tool stays in the XZ plane: the CL gives no Y, or Y = 0.
function checkY(y) {
    if (y !== null && Math.abs(y) > 1e-9)
        error("a move to Y" + y + ": the lathe has no Y axis (turning CL is in the XZ plane)");
}

function straight(code, x, y, z, feed) {
    checkY(y);
    if (grooveSection) {
        // The leading rapids in X alone (a retract to the safe X) go out; then the call replaces
        // the section's moves.
        var xOnly = code == 0 && (z === null || z === getCurrentAxis("z"));
        if (grooveCalled || !xOnly) {
            if (!grooveCalled)
                writeGrooveCall();
            return;
        }
    }
    var xWord = xOutput.format(x);
    var zWord = zOutput.format(z);
    if (!xWord && !zWord)
        return;  // nowhere to go: no block (and G0/G1 stays what the control has)
    writeBlock(motionModal.format(code), xWord, zWord, code == 1 ? feedOutput.format(feed) : "");
}

function onRapid(x, y, z) {
    straight(0, x, y, z, 0);
}

function onLinear(x, y, z, feed) {
    if (!(feed > 0))
        error("a feed move without a feed rate");
    straight(1, x, y, z, feed);
}

function onClose() {
    writeBlock(coolantOn !== false ? "M9" : "", spindleOn !== false ? "M5" : "");
    writeBlock("M30");
    if (!subprogramsCalled)
        return;
    // The five subprograms beside the program, as shipped (PROC name = file name, M17).
    for (var i = 0; i < grooveFiles.length; ++i) {
        var text = readPostFile("sinumerik840d-turn/groove/" + grooveFiles[i] + ".SPF");
        openFile(grooveFiles[i] + ".SPF");
        writeln(text.replace(/\r?\n$/, ""));
        closeFile();
    }
}
