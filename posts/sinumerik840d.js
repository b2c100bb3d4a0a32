// SINUMERIK 840D sl, three to five axes: a DMU 50-class B/C table-table machine by default, any
// machine whose file gives a five-axis chain for simultaneous moves.
// Three-axis output keeps the dialect the 828D proved on the control (seed-004, the
// sinumerik828d-emco post): numbered blocks from N10 step 10, ';' comments, `G17 G40` / `G710` /
// `G54 G90`, a comment and `M6 T<n> D1` per tool, `M3 S<n>`, modal G words and axes, 3 decimals,
// integer F never on G0, G2/G3 with the plane's two centre words, CYCLE81..85, M5/M9, M30.
// Five-axis moves (MULTAX CL, ToolAxisMove) go out under TRAORI: X Y Z of the tool tip in the
// workpiece frame and the tool vector A3= B3= C3= (normalised, 7 decimals; the control turns B and
// C itself, Programming Manual Job Planning, "Three, four and five axis transformation (TRAORI)").
// Each run of them: TRAORI, ORIWKS ORIVECT ... TRAFOOF, then Z to the top of its travel and the
// table home; after each tool change the table home too, so three-axis moves never run on a table
// another program left tilted. With the property orientation=angles the kernel plans each
// operation's rotary positions (post.fiveAxis: the branch over the whole operation, within the
// limits) and the blocks give B and C instead of the vector: the table turned at the top of Z
// first, TRAORI, X/Y then Z; an endless C by DC, or ACP/ACN for half a turn or more (the turn on
// the pole). G93 inverse-time feed is a property. 3+2 working planes as CYCLE800
// (the plane's spatial angles, the table turned by the control on the kernel's branch), CYCLE800()
// and the table home after them.
var post = {
    id: "sinumerik840d",
    description: "SINUMERIK 840D sl, DMU 50-class B/C table (TRAORI, simultaneous 5-axis)",
    vendor: "Siemens / DMG MORI",
    extension: "mpf",
    machine: "dmu50-840d",
    controls: ["sinumerik-840d"],
    capabilities: {
        arcPlanes: ["XY", "ZX", "YZ"],
        helicalArcs: true,
        maxArcSweep: 180,  // full circles in two halves: every block's end differs from its start
        cycles: ["drill", "drillDwell", "peck", "chipBreak", "tap", "bore"],
        maxAxes: 5
    },
    properties: {
        inverseTime: {
            title: "Inverse-time feed (G93)", type: "bool", default: false,
            description: "Five-axis feed moves in G93: F = 1 / the block's time in minutes (the tool tip's " +
                         "length at the CL feed, or the tool vector's turn in degrees at the feed as deg/min " +
                         "where the tip stands), G94 again after them; off: F is the tip's feed in mm/min"
        },
        orientation: {
            title: "Five-axis orientation", type: "enum", values: ["vector", "angles"], default: "vector",
            description: "Under TRAORI: the tool vector A3= B3= C3= (the control chooses the rotary positions), or " +
                         "the rotary axes' positions as the kernel plans them over each operation (within the " +
                         "machine's limits; an endless axis by DC, or ACP/ACN for a turn of half a revolution or more)"
        },
        swivelDataSet: {
            title: "Swivel data set (CYCLE800 _TC)", type: "string", default: "TC1",
            description: "Name of the machine's swivel data set (tool carrier) that CYCLE800 swivels with, as set up " +
                         "on the control"
        }
    }
};

// The dialect's properties, formats, words and handlers shared with the other SINUMERIK post.
include("sinumerik-common");

var inverseTime = getProperty("inverseTime");
// G93: 1/min. Four decimals keep a long block's time within 0.5 % down to F0.01 (a 100 mm block at
// 1 mm/min); beyond the control's F range (999 999.999) a block is too short for its feed: an error.
var inverseTimeFormat = createFormat({decimals: 4, trim: true, max: 999999.999});
// Tool vector components: 7 decimals keep the written vector within 1e-7 of the CL's per component.
var vectorFormat = createFormat({decimals: 7, trim: true});
var angleFormat = createFormat({decimals: 3, trim: true});

var inverseFeedOutput = createVariable({prefix: "F", force: true}, inverseTimeFormat);  // each G93 block its own time

// Rotary positions (orientation angles): the kernel plans each five-axis operation's poses
// (kinematics::planBranches, for every post on a five-axis machine) and hands them to onLinear5D
// with each step; post.fiveAxis says how (G93 by the kernel's inverse time).
var angleOutput = getProperty("orientation") == "angles";
if (angleOutput)
    post.fiveAxis = {output: "tip", feed: inverseTime ? "inverse" : "tip"};

// A straight move or arc of the CL between five-axis moves has the tool along +Z: under TRAORI
// its block carries that vector (the control would keep the last one), and under G93 it needs G94
// first. Both are set when a five-axis move leaves them due and ride on the next such block.
var verticalVector = createPending();
var backToG94 = createPending();

// The per-move blocks run in C++ (no onRapid/onLinear/onCircular here): a million three-axis
// moves never enter the script engine. They share the modal variables with the handlers below.
post.blocks = {
    before: [backToG94],
    rapid: [motionModal.bind("motion"), compModal.bind("comp"), xOutput.bind("x"), yOutput.bind("y"),
            zOutput.bind("z"), verticalVector],
    linear: [motionModal.bind("motion"), compModal.bind("comp"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), verticalVector, feedOutput.bind("feed")],
    circular: {
        // Without Y in helical blocks the 828D reports a wrong circle-centre definition (seed-004 §4.3).
        forceOnHelical: [xOutput, yOutput, zOutput],
        XY: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), iOutput.bind("i"), jOutput.bind("j"), verticalVector, feedOutput.bind("feed")],
        ZX: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), iOutput.bind("i"), kOutput.bind("k"), verticalVector, feedOutput.bind("feed")],
        YZ: [planeModal.bind("plane"), motionModal.bind("motion"), xOutput.bind("x"), yOutput.bind("y"),
             zOutput.bind("z"), jOutput.bind("j"), kOutput.bind("k"), verticalVector, feedOutput.bind("feed")]
    }
};

var compCode = 40;  // G40/G41/G42 as the CL last said

// --- Five-axis: TRAORI with the tool vector ---------------------------------------------------

var traori = false;      // a run of five-axis moves is open
var g93 = false;         // G93 is in force
var vectorText = null;   // "A3=.. B3=.. C3=.." as last written under TRAORI

// The machine's chain, or an error: TRAORI turns B and C as the control's own kinematics says, but
// a post that writes it for a machine whose file knows no chain would write blind.
function fiveAxisChain() {
    var chain = machine ? machine.kinematics : null;
    if (!chain)
        error("five-axis move but " + (machine ? "machine " + machine.id + " has no five-axis kinematic chain"
                                               : "no machine is given") +
              ": post " + post.id + " writes TRAORI only for a machine whose file gives one");
    return chain;
}

function axisOf(name) {
    for (var i = 0; i < machine.axes.length; ++i)
        if (machine.axes[i].name == name)
            return machine.axes[i];
    return null;
}

// A table-table chain whose second axis turns endlessly about Z (the rotary table) reaches a tool
// vector iff its tilt from +Z is within the tilt axis' larger reach (the other sign with C + 180):
// refused here, naming the CL record, before the control stops on it. Other chains are left to the
// control (and the kernel's pose solver).
var reachDeg;  // undefined: not known yet; null: not checked here

function checkReach(chain, i, j, k) {
    if (reachDeg === undefined) {
        var tilt = axisOf(chain.rotaries[0].axis), turn = axisOf(chain.rotaries[1].axis);
        var d = chain.rotaries[1].direction;
        reachDeg = chain.type == "table-table" && tilt && turn && turn.endless && tilt.min !== null &&
                           Math.abs(Math.abs(d[2]) - 1) < 1e-9
                       ? Math.max(tilt.max, -tilt.min)
                       : null;
    }
    if (reachDeg === null)
        return;
    var tiltDeg = Math.acos(Math.min(1, Math.max(-1, k))) * 180 / Math.PI;
    if (tiltDeg > reachDeg + 1e-6) {
        var tilt = axisOf(chain.rotaries[0].axis);
        error("tool vector (" + vectorFormat.format(i) + ", " + vectorFormat.format(j) + ", " + vectorFormat.format(k) +
              ") is tilted " + angleFormat.format(tiltDeg) + " deg from Z; the " + machine.name + "'s " + tilt.name +
              " axis reaches " + angleFormat.format(tilt.min) + ".." + angleFormat.format(tilt.max) + " deg");
    }
}

function beginTraori() {
    writeBlock("TRAORI");
    // A3/B3/C3 in the workpiece frame (ORIWKS) and the vector turned on the great circle between
    // blocks (ORIVECT), as CL vectors mean: both G groups reset to machine data, so say them.
    writeBlock("ORIWKS", "ORIVECT");
    traori = true;
    vectorText = null;
    lastVector = [0, 0, 1];
    verticalDue = false;
    forceMotion();
}

// Z to the top of its travel in machine coordinates without the length offset (SUPA ... D0: the
// tool's tip is above the part wherever it was), the table home (tableHome), the length offset back
// for the next move.
function retractAndHome() {
    var z = axisOf("Z");
    writeBlock("G0", "SUPA", "Z" + xyzFormat.format(z && z.max !== null ? z.max : 0), "D0");
    writeBlock(tableHome());
    writeBlock("D1");
}

// After the run: transformation off, then retractAndHome.
function endTraori() {
    if (!traori)
        return;
    if (g93 && backToG94.isSet()) {  // else a three-axis block has written G94 already
        backToG94.take();
        writeBlock("G94");
        feedModeModal.reset();
    }
    g93 = false;
    verticalVector.take();
    verticalDue = false;
    writeBlock("TRAFOOF");
    retractAndHome();
    traori = false;
    motionModal.reset();
    forceMotion();
}

// "G0 B0 C=DC(0)": the rotaries at 0, an endless one the short way (DC).
function tableHome() {
    var chain = machine.kinematics;
    var home = ["G0"];
    for (var r = 0; r < chain.rotaries.length; ++r) {
        var axis = axisOf(chain.rotaries[r].axis);
        home.push(axis && axis.endless ? axis.name + "=DC(0)" : chain.rotaries[r].axis + "0");
    }
    return home.join(" ");
}

var verticalText = "A3=0 B3=0 C3=1";  // vectorWords(0, 0, 1)

function vectorWords(i, j, k) {
    var n = Math.sqrt(i * i + j * j + k * k);
    return "A3=" + vectorFormat.format(i / n) + " B3=" + vectorFormat.format(j / n) + " C3=" + vectorFormat.format(k / n);
}

// Degrees between two unit vectors.
function turnDeg(a, b) {
    var dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    return Math.acos(Math.min(1, Math.max(-1, dot))) * 180 / Math.PI;
}

var lastVector = [0, 0, 1];  // the tool's last unit vector: vertical with the table home
var verticalDue = false;     // verticalVector was set: a three-axis block may have written it

function onLinear5D(x, y, z, i, j, k, feed, pose) {
    if (angleOutput) {  // a step of the kernel's plan: orientation by rotary positions
        writeRotaryPose(feed, pose);
        return;
    }
    if (!traori && Math.abs(i) < 1e-9 && Math.abs(j) < 1e-9 && k > 0) {
        // Along +Z outside a five-axis run: a three-axis move, on any machine.
        var move = [motionModal.format(feed > 0 ? 1 : 0), compModal.format(compCode),
                    xOutput.format(x), yOutput.format(y), zOutput.format(z)];
        if (move[2] || move[3] || move[4])
            writeBlock.apply(null, move.concat([feed > 0 ? feedOutput.format(feed) : ""]));
        return;
    }
    var chain = fiveAxisChain();
    if (compCode != 40)
        error("cutter compensation is on in a five-axis move: TRAORI moves are written without G41/G42");
    var n = Math.sqrt(i * i + j * j + k * k);
    checkReach(chain, i / n, j / n, k / n);
    if (!traori)
        beginTraori();
    var consumed = verticalDue && !verticalVector.isSet();
    if (consumed) {  // a three-axis block wrote the vertical vector
        vectorText = verticalText;
        lastVector = [0, 0, 1];
    }
    var start = inverseTime && feed > 0 ? getCurrentPosition() : null;
    var vector = vectorWords(i, j, k);
    var words = [xOutput.format(x), yOutput.format(y), zOutput.format(z), vector != vectorText ? vector : ""];
    var unit = [i / n, j / n, k / n];
    var turned = turnDeg(lastVector, unit);
    lastVector = unit;
    vectorText = vector;
    // A tool along +Z on the next three-axis block: its vector is due only if this one is not.
    // (Each kernel call costs: the pending is set once per tilted stretch, not per block.)
    var due = vector != verticalText;
    if (due && (!verticalDue || consumed))
        verticalVector.set(verticalText);
    else if (!due && verticalDue)
        verticalVector.take();
    verticalDue = due;
    if (!words[0] && !words[1] && !words[2] && !words[3])
        return;  // nothing moves
    if (!(feed > 0)) {
        writeBlock(motionModal.format(0), words[0], words[1], words[2], words[3]);
        return;
    }
    var f;
    if (inverseTime) {
        if (machine.maxCuttingFeed > 0 && feed > machine.maxCuttingFeed)
            error("feed " + feed + " mm/min is above the " + machine.name + "'s maximum of " + machine.maxCuttingFeed +
                  " mm/min: G93 would ask for a block time the machine cannot keep");
        if (!start)
            error("inverse-time feed needs the move's start: no move gave X, Y and Z before it");
        var length = Math.sqrt(Math.pow(x - start.x, 2) + Math.pow(y - start.y, 2) + Math.pow(z - start.z, 2));
        // The tip's length at the feed; where the tip stands, the vector's turn at the feed as deg/min.
        var minutes = length > 1e-9 ? length / feed : turned / feed;
        if (!(minutes > 0))
            error("inverse-time feed of a move that neither moves the tip nor turns the tool");
        if (g93 && !backToG94.isSet())  // a three-axis block between wrote the G94
            g93 = false;
        if (!g93) {
            writeBlock("G93");
            feedModeModal.reset();
            g93 = true;
        }
        backToG94.set("G94");
        feedOutput.reset();  // F in mm/min again after G94
        f = inverseFeedOutput.format(1 / minutes);
    } else {
        f = feedOutput.format(feed);
    }
    writeBlock(motionModal.format(1), words[0], words[1], words[2], words[3], f);
}

// --- Five-axis by rotary positions (orientation angles) ----------------------------------------

var rotaryAt = {};    // endless axes: the kernel's (continuous) angle each was last sent to
var rotaryText = {};  // limited axes: the word last written
// Rotary positions to 4 decimals: the tool axis within 1e-6 rad of the plan's per axis.
var rotaryFormat = createFormat({decimals: 4, trim: true});

// The word that sends rotary axis `name` to `deg` ("" when it stands there): a limited axis by its
// position, an endless one (modulo 360 on the control) by DC, the shorter way, or by ACP/ACN where
// the plan turns it half a revolution or more, so that it turns the way the plan does.
function rotaryWord(name, deg) {
    var axis = axisOf(name);
    if (!axis || !axis.endless) {
        var word = name + rotaryFormat.format(deg);
        if (rotaryText[name] == word)
            return "";
        rotaryText[name] = word;
        return word;
    }
    var from = rotaryAt[name];
    rotaryAt[name] = deg;
    var turn = from === undefined ? 0 : deg - from;
    if (from !== undefined && Math.abs(turn) < 0.00005)
        return "";
    var position = rotaryFormat.format(((deg % 360) + 360) % 360);
    if (Math.abs(turn) < 180 - 1e-6)
        return name + "=DC(" + position + ")";
    if (Math.abs(turn) < 360 - 1e-6)
        return name + (turn > 0 ? "=ACP(" : "=ACN(") + position + ")";
    error("axis " + name + " would turn " + rotaryFormat.format(turn) + " degrees in one block: more than a revolution");
}

// The rotary words of a planned pose ({b: .., c: ..} by axis name), in the chain's order.
function rotaryWords(pose) {
    var chain = fiveAxisChain();
    var words = [];
    for (var r = 0; r < chain.rotaries.length; ++r) {
        var name = chain.rotaries[r].axis;
        var deg = pose[name.toLowerCase()];
        var word = deg === undefined ? "" : rotaryWord(name, deg);
        if (word)
            words.push(word);
    }
    return words;
}

// Before an operation: Z up to its travel, the table turned to the first pose there, TRAORI on.
function onFiveAxisBegin(section) {
    if (!angleOutput)
        return;  // the vector: TRAORI opens with the first five-axis move (onLinear5D)
    var z = axisOf("Z");
    writeBlock("G0", "SUPA", "Z" + xyzFormat.format(z && z.max !== null ? z.max : 0), "D0");
    rotaryAt = {};
    rotaryText = {};
    writeBlock.apply(null, ["G0"].concat(rotaryWords(section)));
    writeBlock("D1");
    writeBlock("TRAORI");
    if (inverseTime)
        writeBlock("G93");
    forceMotion();
}

function writeRotaryPose(feed, pose) {
    var words = [pose.x !== undefined ? xOutput.format(pose.x) : "", pose.y !== undefined ? yOutput.format(pose.y) : "",
                 pose.z !== undefined ? zOutput.format(pose.z) : ""].concat(rotaryWords(pose));
    if (!(feed > 0)) {
        writeBlock.apply(null, [motionModal.format(0)].concat(words));
        return;
    }
    // G93: the kernel's inverse time (1/min); else the tip's feed in mm/min.
    var f = inverseTime ? inverseFeedOutput.format(feed) : feedOutput.format(feed);
    writeBlock.apply(null, [motionModal.format(1)].concat(words, [f]));
}

// After it: G94, TRAFOOF, Z up to its travel, the table home, the length offset back.
function onFiveAxisEnd(pose, home) {
    if (!angleOutput)
        return;  // the vector: TRAFOOF at the section's end (endTraori)
    if (inverseTime) {
        writeBlock("G94");
        feedModeModal.reset();
        feedOutput.reset();
    }
    writeBlock("TRAFOOF");
    retractAndHome();
    motionModal.reset();
    forceMotion();
}

// --- 3+2: CYCLE800 ---------------------------------------------------------------------------

// CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR) (840D sl
// Programming Manual Cycles, "Swiveling - CYCLE800"): _FR 1 retracts in machine Z before the table
// turns (as the iTNC post's MB MAX); _ST 0 a new plane; _MODE 27 axis by axis about Z, then the
// turned Y, then X'' (bits 1-0 11 Z, 3-2 10 Y, 5-4 01 X), which are the kernel's spatial angles
// (about the fixed X, Y, Z) in reverse order; the plane's origin as the offset before the turn;
// _DIR the branch the kinematics chose (the sign of rotary axis 1). The moves after it are in the
// plane's frame (the kernel forgets every axis). The default plane swivels back the same way: the
// zero plane with _DIR, so the control retracts and turns the table home (B0 C0) before 3-axis work.
var swivelled = false;

function swivel(origin, a, b, c, branch) {
    writeBlock("CYCLE800(" + [1, "\"" + getProperty("swivelDataSet") + "\"", 0, 27, xyzFormat.format(origin.x),
                              xyzFormat.format(origin.y), xyzFormat.format(origin.z), angleFormat.format(c),
                              angleFormat.format(b), angleFormat.format(a), 0, 0, 0, branch < 0 ? -1 : 1].join(",") + ")");
}

function onWorkingPlane(plane) {
    endTraori();
    if (!plane.tilted) {
        if (swivelled)
            swivel({x: 0, y: 0, z: 0}, 0, 0, 0, 1);
        swivelled = false;
        forceMotion();
        return;
    }
    fiveAxisChain();
    if (!plane.machine)
        error("the working plane's pose is unknown: machine " + machine.id + " cannot point the tool along it");
    swivel(plane.origin, plane.spatialA, plane.spatialB, plane.spatialC, plane.machine.branch);
    swivelled = true;
    forceMotion();
}

// --- Program frame ----------------------------------------------------------------------------

function onOpen(program) {
    writeHeader(program);
}

function onWorkOffset(index) {
    endTraori();
    writeBlock(workOffsetModal.format(workOffsetCode(index)));
}

function onSection(section) {
    comment(section.operationName);
    forceMotion();
}

function onSectionEnd() {
    endTraori();
}

function onToolChange(tool) {
    endTraori();
    stopSpindleAndCoolant();
    comment(getProperty("toolChangeComment"));
    writeBlock("M6", "T" + Math.trunc(tool.number), "D1");
    // Three-axis moves take the table at home, whatever the last program left: turn it there while
    // the spindle stands at the tool change position, above everything.
    if (machine && machine.kinematics)
        writeBlock(tableHome());
    forceMotion();
}

function onCutterComp(side) {
    // G41/G42/G40 go out with the next straight move (blocks.rapid/linear bind "comp").
    compCode = side == "left" ? 41 : side == "right" ? 42 : 40;
}

// --- Drilling: CYCLE81..85 (include/sinumerik-common.js), out of TRAORI --------------------------

function onCycle(cycle) {
    endTraori();
    startCycle(cycle);
}

function onClose() {
    endTraori();
    stopSpindleAndCoolant();
    writeBlock("M30");
}
