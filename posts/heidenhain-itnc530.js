// MAS MCVL 1000 (NIKKEN 5AX-220 B/C table) with the HEIDENHAIN iTNC 530, Klartext (.h).
// The output rules of seed-000 (Machala 2017, §2.5, §3.6-3.9, §7): every line numbered from 0
// step 1 except cycle Q lines; `BEGIN PGM <file name> MM` ... `END PGM`; header comments, BLK
// FORM from the stock, `M135 M126`; machining time and tool list; operation banners; a tool box
// before each `TOOL CALL n Z S`; no M6 (the operator changes tools); `L` with the changed,
// signed coordinates; FMAX rapids with R0; R0/RL/RR from the CL; M3 on the first move and the
// coolant block after it; CC + C DR+- in the three planes (or CR), CC + CP IPA IZ for helices;
// parametric feeds Q601/Q602/Q603; cycles 200/201/203/205/207 with their Q lists; the min/max
// travel report before END PGM. The words of the comments in English or in the thesis' Czech.
//
// Five-axis (seed-000 §2.4, §3.3-3.6): the kernel chooses the machine poses of each five-axis
// operation (post.fiveAxis, FiveAxisPlan.h) and writes them through rapid5D/linear5D: with TCPM
// (M128 or FUNCTION TCPM) the tip in the workpiece frame plus C and B, without it the machine
// coordinates about MRZP (P = X^T Q, eqs. 20-24), linearised in joint space, F for all axes
// together (or M116). C before B as the thesis writes them; M126 in the header: C is not unwound.
// Each five-axis operation: M140 MB MAX, the rotaries turned, TCPM on ... TCPM off, M140 MB MAX,
// the table home (B+0, C at the nearest whole turn). B and C join the min/max report.
// The cycles and the tilting (3+2 planes, the frame of five-axis operations) are in
// include/heidenhain-cycles.js and include/heidenhain-tilting.js, for the Heidenhain posts to share.
var post = {
    id: "heidenhain-itnc530",
    description: "MAS MCVL 1000, HEIDENHAIN iTNC 530 Klartext (B/C table, simultaneous 5-axis)",
    vendor: "MAS / HEIDENHAIN",
    extension: "h",
    machine: "mas-mcvl1000",
    machines: ["mas-mcvl1000", "mas-mcvl1000-nikken-guaranteed"],
    controls: ["heidenhain-itnc530"],
    capabilities: {
        arcPlanes: ["XY", "ZX", "YZ"],
        // CP IPA IZ in the working plane only: the iTNC 530 manual allows a helix about another main
        // plane, the TNC 430's takes the height on the tool axis alone, and Autodesk's iTNC posts
        // linearise such helices too; the kernel writes them as lines within the tolerance.
        helicalArcs: ["XY"],
        maxArcSweep: 180,     // full circles as two halves: every C block's end differs from its start
        maxHelixSweep: 5400,  // IPA's range on the control: multi-turn helices in one CP block
        cycles: ["drill", "drillDwell", "peck", "chipBreak", "tap", "bore"],
        maxAxes: 5
    },
    properties: {
        language: {
            title: "Comment language", type: "enum", values: ["english", "czech"], default: "english",
            description: "Words of the comments and cycle texts: English as the iTNC writes them, or the thesis' Czech"
        },
        units: {
            title: "Units", type: "enum", values: ["mm", "inch"], default: "mm",
            description: "BEGIN PGM ... MM (coordinates mm, feeds mm/min) or INCH (inch, inch/min)"
        },
        parametricFeeds: {
            title: "Parametric feeds (Posuv F)", type: "bool", default: false,
            description: "Q601 cutting, Q602 finishing, Q603 plunge defined once per operation and F+Q60x in the " +
                         "blocks that use them, so the operator changes a feed in one place"
        },
        arcOutput: {
            title: "Arc words", type: "enum", values: ["CC", "CR"], default: "CC",
            description: "CC centre + C end point, or CR end point with the signed radius (R- above 180 degrees)"
        },
        machiningTime: {
            title: "Machining time", type: "bool", default: true,
            description: "The estimated machining time near the top (STROJNI CAS), from the CL with the machine's rapid"
        },
        rotaryModes: {
            title: "M135 M126 in the header", type: "bool", default: true,
            description: "M135: no exact stop at rotary transitions; M126: rotary axes take the shorter way"
        },
        travelReport: {
            title: "Travel report", type: "bool", default: true,
            description: "The smallest and largest position of each axis as comments before END PGM (seed-000 5.9)"
        },
        tcpm: {
            title: "TCPM (five-axis)", type: "enum", values: ["m128", "function-tcpm", "off"], default: "m128",
            perOperation: true,
            description: "Five-axis operations: M128 or FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS (the control keeps " +
                         "the tip; X Y Z of the tip in the workpiece frame), or off: machine coordinates about MRZP " +
                         "computed by the post (the preset at MRZP, seed-000 3.3); an operation may set its own"
        },
        rotaryFeed: {
            title: "Feed without TCPM", type: "enum", values: ["combined", "m116"], default: "combined",
            perOperation: true,
            description: "tcpm off: F for all axes together in mm and degrees, so that each block takes the time " +
                         "the tip needs at the CL feed (capped by the machine's maximum), or M116 (software option " +
                         "1: F in mm/min on the rotary table, the CL feed as it is)"
        },
        poleCone: {
            title: "Pole cone (deg)", type: "number", default: 0, min: 0, max: 10,
            description: "A tool axis within this angle of the C axis keeps C and is written on the pole (a " +
                         "warning says how far from the CL's); 0: only an axis exactly on the pole keeps C"
        },
        reconfigure: {
            title: "Rotary reconfiguration", type: "enum", values: ["retract", "refuse"], default: "retract",
            description: "Where no branch finishes an operation without a flip or rewind of B/C: retract along " +
                         "the tool axis, turn, re-enter (retract), or stop with an error naming the CL record"
        },
        workingPlane: {
            title: "Tilted working plane (3+2)", type: "enum", values: ["plane-spatial", "cycle19"],
            default: "plane-spatial",
            description: "PLANE SPATIAL SPA SPB SPC TURN MB MAX FMAX SEQ+- (PLANE RESET after), or the older CYCL DEF " +
                         "19 WORKING PLANE with the machine's B and C (the control set for axis angles) and the " +
                         "table turned by an L block"
        },
        retractDistance: {
            title: "Reconfiguration retract (mm)", type: "number", default: 50, min: 1, max: 1000,
            description: "How far the tool leaves the part along its axis before the table turns to reconfigure"
        },
        stopBeforeToolCall: {
            title: "Stop before each tool call (Stop_M0)", type: "bool", default: false,
            description: "M0 before every TOOL CALL, for the operator who changes the tool by hand"
        }
    }
};
post.capabilities.arcWords = getProperty("arcOutput") == "CR" ? "radius" : "center";
// tcpm and rotaryFeed are read per five-axis operation (an operation may set its own).
function combinedFeed() {
    var combined = getProperty("tcpm") == "off" && getProperty("rotaryFeed") == "combined";
    if (combined && inch)
        error("tcpm off with the combined feed is written in mm programs only (F mixes mm and degrees): " +
              "use units mm or rotaryFeed m116");
    return combined;
}
post.fiveAxis = {
    output: function () { return getProperty("tcpm") == "off" ? "machine" : "tip"; },
    feed: function () { return combinedFeed() ? "combined" : "tip"; },
    poleCone: getProperty("poleCone"),
    reconfigure: getProperty("reconfigure"),
    retract: getProperty("retractDistance")
};

var czech = getProperty("language") == "czech";
var inch = getProperty("units") == "inch";
var unitWord = inch ? "INCH" : "MM";
var words = czech ? {
    machine: "STROJ", control: "SYSTEM", post: "POSTPROCESSOR", version: "GPP_VER.", programmer: "PROGRAMATOR",
    project: "Projekt", date: "Datum", time: "Cas", tool: "NASTROJ", type: "TYP", holder: "UPINAC",
    operation: "OPERACE", toolList: "SEZNAM NASTROJU", machiningTime: "STROJNI CAS", cutting: "hrubovaci",
    finishing: "dokoncovaci", plunge: "posuv v Z", stockWarning: "Polotovar mimo +-2000: BLK FORM nelze spravne nastavit",
    flood: "Kapalina", mist: "Mlha"
} : {
    machine: "MACHINE", control: "CONTROL", post: "POST", version: "POST VERSION", programmer: "PROGRAMMER",
    project: "PROJECT", date: "DATE", time: "TIME", tool: "TOOL", type: "TYPE", holder: "HOLDER",
    operation: "OPERATION", toolList: "TOOL LIST", machiningTime: "MACHINING TIME", cutting: "CUTTING FEED",
    finishing: "FINISHING FEED", plunge: "PLUNGE FEED", stockWarning: "Stock beyond +-2000: BLK FORM cannot be set",
    flood: "Flood coolant", mist: "Mist coolant"
};
// The tool box names the type in the comment language; the tool list keeps the CAM's English
// tool type in both, as the thesis' program does (5.3 KULOVA FREZA, 5.10 BALL NOSE MILL).
var toolTypes = {flat: "FLAT END MILL", ball: "BALL NOSE MILL", bull: "BULL NOSE MILL", drill: "DRILL",
                 chamfer: "CHAMFER MILL"};
var toolTypesCzech = {flat: "VALCOVA FREZA", ball: "KULOVA FREZA", bull: "TORICKA FREZA", drill: "VRTAK",
                      chamfer: "SRAZECI FREZA"};

var limit = inch ? 9999.99999 : 99999.9999;  // the largest coordinate the iTNC reads
var xyzFormat = createFormat({decimals: inch ? 4 : 3, trim: true, forceSign: true, scale: inch ? 1 / 25.4 : 1,
                              max: limit});
var angleFormat = createFormat({decimals: 4, trim: true, forceSign: true});
// Inch programs take F in 0.1 inch/min (the iTNC's unit): 150 mm/min is F59.1.
var feedFormat = inch ? createFormat({decimals: 1, trim: true, scale: 1 / 2.54}) : createFormat({decimals: 0});
var feedPerRevolutionFormat = createFormat({decimals: 4, trim: true, scale: inch ? 1 / 2.54 : 1});  // same unit rule
var numberFormat = createFormat({decimals: 4, trim: true});  // Q values, tool data, the travel report
var qFormat = createFormat({decimals: 4, trim: true, scale: inch ? 1 / 25.4 : 1});
var qCoordinateFormat = createFormat({decimals: 4, trim: true, forceSign: true, scale: inch ? 1 / 25.4 : 1});

var xOutput = createVariable({prefix: "X"}, xyzFormat);
var yOutput = createVariable({prefix: "Y"}, xyzFormat);
var zOutput = createVariable({prefix: "Z"}, xyzFormat);
var ccX = createVariable({prefix: "X", force: true}, xyzFormat);
var ccY = createVariable({prefix: "Y", force: true}, xyzFormat);
var ccZ = createVariable({prefix: "Z", force: true}, xyzFormat);
var radiusOutput = createVariable({prefix: "R", force: true}, xyzFormat);
var ipaOutput = createVariable({prefix: "IPA", force: true}, angleFormat);
var izOutput = createVariable({prefix: "IZ", force: true}, xyzFormat);
var feedOutput = createVariable({prefix: "F"}, feedFormat);
var bOutput = createVariable({prefix: "B"}, angleFormat);
var cOutput = createVariable({prefix: "C"}, angleFormat);
var compOutput = createModal({prefix: ""});
var directionOutput = createModal({prefix: "DR", force: true});
var compTexts = {texts: {40: "R0", 41: "RL", 42: "RR"}};
var spindleStart = createPending();  // M3/M4 ride on the first move after TOOL CALL (seed-000 5.4)
var coolantBlock = createPending();  // then the coolant in a block of its own
var toolCallBlock = createPending(); // TOOL CALL waiting for its speed, written before a move at the latest

function direction() {
    return directionOutput.bind("motion", {texts: {2: "-", 3: "+"}});
}
function arcBlocks(centre, end) {
    if (getProperty("arcOutput") == "CR")
        return [["CR"].concat(end, [radiusOutput.bind("radius"), direction(), feedOutput.bind("feed")])];
    return [["CC"].concat(centre), ["C"].concat(end, [direction(), feedOutput.bind("feed")])];
}
var always = {force: true};  // both end coordinates in every C block, as the iTNC writes them

post.blocks = {
    rapid: ["L", xOutput.bind("x"), yOutput.bind("y"), zOutput.bind("z"), compOutput.bind("comp", {force: true,
            texts: compTexts.texts}), "FMAX", spindleStart],
    linear: ["L", xOutput.bind("x"), yOutput.bind("y"), zOutput.bind("z"), compOutput.bind("comp", compTexts),
             feedOutput.bind("feed"), spindleStart],
    // Five-axis: C before B after the linear axes (seed-000 2.5: "C+0 B+0").
    rapid5D: ["L", xOutput.bind("x"), yOutput.bind("y"), zOutput.bind("z"), cOutput.bind("c"), bOutput.bind("b"),
              compOutput.bind("comp", {force: true, texts: compTexts.texts}), "FMAX", spindleStart],
    linear5D: ["L", xOutput.bind("x"), yOutput.bind("y"), zOutput.bind("z"), cOutput.bind("c"), bOutput.bind("b"),
               compOutput.bind("comp", compTexts), feedOutput.bind("feed"), spindleStart],
    circular: {
        XY: arcBlocks([ccX.bind("cx"), ccY.bind("cy")], [xOutput.bind("x", always), yOutput.bind("y", always)]),
        ZX: arcBlocks([ccX.bind("cx"), ccZ.bind("cz")], [xOutput.bind("x", always), zOutput.bind("z", always)]),
        YZ: arcBlocks([ccY.bind("cy"), ccZ.bind("cz")], [yOutput.bind("y", always), zOutput.bind("z", always)]),
        helix: {
            XY: [["CC", ccX.bind("cx"), ccY.bind("cy")],
                 ["CP", ipaOutput.bind("angle"), izOutput.bind("axial"), direction(), feedOutput.bind("feed")]]
        }
    },
    before: [toolCallBlock],
    after: [coolantBlock]
};

var currentTool = null;    // the tool in the spindle (TOOL CALL written or waiting)
var sectionFeeds = null;   // the operation's feeds, for the Q60x parameters
var feedsDefined = false;  // the Q60x of this operation are written

function comment(text) {
    writeComment(String(text).replace(/[\r\n]+/g, " "));
}

function pad(number, digits) {
    var text = String(number);
    while (text.length < digits)
        text = "0" + text;
    return text;
}

// R in the tool data: the corner radius of a mill (half the diameter for a ball), the point
// angle of a drill or chamfer mill (seed-000 5.10: "DRILL D3 R118").
function toolR(tool) {
    if (tool.kind == "drill" || tool.kind == "chamfer")
        return tool.pointAngle;
    return tool.kind == "ball" && !(tool.cornerRadius > 0) ? tool.diameter / 2 : tool.cornerRadius;
}

function n(value) {
    return numberFormat.format(value);
}

function programFileName() {
    var name = outputName || programName;
    // The iTNC's file names (User's Manual 3.3): up to 25 characters of A-Z a-z 0-9 . _ -
    if (!/^[A-Za-z0-9._-]{1,25}$/.test(name))
        error("program name '" + name + "' is not accepted by the iTNC 530: use up to 25 characters of " +
              "A-Z a-z 0-9 . _ - (the program name is the output file's name)");
    return name;
}
var pgmName = null;

function header() {
    var now = new Date();
    var date = now.getUTCDate() + "." + (now.getUTCMonth() + 1) + "." + now.getUTCFullYear();
    var time = pad(now.getUTCHours(), 2) + ":" + pad(now.getUTCMinutes(), 2) + ":" + pad(now.getUTCSeconds(), 2);
    comment(words.machine + ": " + (machine ? machine.name : "-"));
    comment(words.control + ": HEIDENHAIN iTNC530 Dialog");
    comment(words.post + ": " + post.id);
    comment(words.version + ": " + version);
    comment(words.programmer + ": " + user.toUpperCase());
    comment(words.project + ": " + (job.name || programName));
    comment(words.date + ": " + date);
    comment(words.time + ": " + time);
    comment("");
}

// BLK FORM from the job's stock, else from the program's extents (the control draws it only).
function blankForm(program) {
    var box = job.stock || program.extents;
    if (!box || box.min.x === null || box.min.y === null || box.min.z === null)
        return;
    var values = [box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z];
    var outside = values.some(function (v) { return Math.abs(v) > 2000; });
    if (outside) {  // seed-000 §3.2: a model error puts the stock out of reach; zeros then
        warning("the stock reaches beyond +-2000 mm: BLK FORM written with zeros");
        comment(words.stockWarning);
        values = [0, 0, 0, 0, 0, 0];
    }
    writeBlock("BLK FORM 0.1 Z", "X" + xyzFormat.format(values[0]), "Y" + xyzFormat.format(values[1]),
               "Z" + xyzFormat.format(values[2]));
    writeBlock("BLK FORM 0.2", "X" + xyzFormat.format(values[3]), "Y" + xyzFormat.format(values[4]),
               "Z" + xyzFormat.format(values[5]));
}

function duration(seconds) {
    var total = Math.round(seconds);
    return pad(Math.floor(total / 3600), 3) + ":" + pad(Math.floor(total / 60) % 60, 2) + ":" + pad(total % 60, 2);
}

function toolList(tools) {
    comment("=====");
    comment("..... " + words.toolList + " .....");
    for (var i = 0; i < tools.length; ++i) {
        var t = tools[i];
        comment("T" + pad(Math.trunc(t.number), 2) + " - " + (toolTypes[t.kind] || t.kind.toUpperCase()) + " D" +
                n(t.diameter) + " R" + n(toolR(t)));
    }
    comment("=====");
}

var travel = null;  // the program's extents, for the report at the end

function onOpen(program) {
    pgmName = programFileName();
    setBlockNumbering(0, 1, true, "");
    writeBlock("BEGIN PGM", pgmName, unitWord);
    header();
    blankForm(program);
    if (getProperty("rotaryModes"))
        writeBlock("M135 M126");
    if (getProperty("machiningTime"))
        comment(" " + words.machiningTime + ": " + duration(machiningSeconds()));
    if (program.tools.length > 0)
        toolList(program.tools);
    travel = program.extents;
}

var presetChanged = false;  // a work offset other than the first was activated

// Work offset n is preset n of the preset table (CYCL DEF 247). The first work offset of a
// program is the preset the operator set (seed-000 §5.3: at MRZP) and writes nothing.
function onWorkOffset(index) {
    if (index == 1 && !presetChanged)
        return;
    if (index > 65535)
        error("work offset " + index + ": the iTNC's preset numbers end at 65535 (Q339)");
    presetChanged = true;
    flushPending();
    writeBlock("CYCL DEF 247", czech ? "NASTAVENÍ VZTAŽNÉHO BODU" : "DATUM SETTING");
    writeln("  Q339=+" + Math.trunc(index) + " ;" + (czech ? "ČÍSLO VZTAŽNÉHO BODU" : "DATUM NUMBER"));
}

function defineFeedParameters() {
    feedsDefined = true;
    if (!getProperty("parametricFeeds") || !sectionFeeds)
        return;
    var parameters = {};
    var list = [["cutting", 601, words.cutting], ["finishing", 602, words.finishing], ["plunge", 603, words.plunge]];
    for (var i = 0; i < list.length; ++i) {
        var feed = sectionFeeds[list[i][0]];
        if (!(feed > 0))
            continue;
        writeBlock("Q" + list[i][1] + "=" + feedFormat.format(feed), ";" + list[i][2]);
        parameters[list[i][0]] = {text: "+Q" + list[i][1], feed: feed};
    }
    feedOutput.setFeedParameters(parameters);
}

function onSection(section) {
    comment("=====");
    comment(" " + words.operation + ": " + section.operationName);
    comment("=====");
    sectionFeeds = section.feeds;
    feedsDefined = false;
    feedOutput.setFeedParameters({});
    // With the tool already in the spindle the parameters come now, else after its TOOL CALL.
    if (currentTool && section.toolNumber == currentTool.number)
        defineFeedParameters();
}

function onSectionEnd() {
    flushPending();
}

// A TOOL CALL, spindle start or coolant still waiting for a move, written before anything else
// that must come after them (a dwell for the spindle to run up, a stop, the operation's end).
function flushPending() {
    flushToolCall();
    var start = spindleStart.take();
    if (start)
        writeBlock("L", start);
    var coolant = coolantBlock.take();
    if (coolant)
        writeBlock(coolant);
}

function onToolChange(tool) {
    flushToolCall();
    spindleStart.take();  // the spindle of the tool going out: it never started
    coolantBlock.take();
    if (getProperty("stopBeforeToolCall"))
        writeBlock("L", "M0");
    currentTool = tool;
    comment(" *****");
    comment(" " + words.tool + ": T" + Math.trunc(tool.number) + " D" + n(tool.diameter) + " R" + n(toolR(tool)) +
            " L" + n(tool.length) + " DB" + n(tool.fluteLength) + " Z" + Math.trunc(tool.flutes));
    comment(" " + words.type + ": " + ((czech ? toolTypesCzech : toolTypes)[tool.kind] || tool.kind.toUpperCase()));
    if (tool.holder)
        comment(" " + words.holder + ": " + tool.holder);
    comment(" *****");
    // TOOL CALL carries the speed: it waits for the spindle record (or the next move).
    toolCallBlock.set("TOOL CALL " + Math.trunc(tool.number) + " Z");
    forceMotion();
}

// The TOOL CALL still waiting for its speed, written now; then this operation's feed parameters.
function flushToolCall(speed) {
    if (!toolCallBlock.isSet())
        return false;
    writeBlock(toolCallBlock.take(), speed || "");
    if (!feedsDefined)
        defineFeedParameters();
    return true;
}

function onSpindle(rpm, clockwise) {
    if (rpm <= 0) {
        flushToolCall();
        spindleStart.take();
        writeBlock("L", "M5");
        return;
    }
    var speed = "S" + Math.trunc(rpm);
    if (!flushToolCall(speed))
        writeBlock("TOOL CALL", "Z", speed);  // a new speed for the tool in the spindle
    spindleStart.set(clockwise ? "M3" : "M4");
}

function onCoolant(mode) {
    var block = null;
    if (mode == "off")
        block = "L M9";
    else if (mode == "flood")
        block = "L M8 ;" + words.flood;
    else if (mode == "mist" && machine && machine.coolants.indexOf("mist") >= 0)
        block = "L M7 ;" + words.mist;
    else if (!machine || machine.coolants.indexOf(mode) >= 0)
        warning("coolant " + mode + " is not written by this post: not output");
    if (!block)
        return;
    // Coolant comes on after the move that starts the spindle (seed-000 5.4), else at once.
    if (mode != "off" && spindleStart.isSet())
        coolantBlock.set(block);
    else
        writeBlock(block);
}

// M136: F in mm (inch) per spindle revolution until M137; the iTNC has no inverse-time feed.
function onFeedMode(mode) {
    if (mode == "inverseTime")
        error("inverse-time feed is not available on the iTNC 530 (F is per minute, or per revolution with M136)");
    flushPending();
    var perRevolution = mode == "perRevolution";
    feedOutput.setFormat(perRevolution ? feedPerRevolutionFormat : feedFormat);
    writeBlock("L", perRevolution ? "M136" : "M137");
}

function onCutterComp(side) {
    // R0/RL/RR go out with the next L block (post.blocks binds "comp").
}

function onComment(text) {
    comment(text);
}

function onDwell(seconds) {
    flushPending();
    writeBlock("CYCL DEF 9.0", czech ? "ČASOVÁ PRODLEVA" : "DWELL TIME");
    writeBlock("CYCL DEF 9.1", (czech ? "PRODLEVA " : "DWELL ") + numberFormat.format(seconds));
}

function onStop(optional) {
    flushPending();
    writeBlock("L", optional ? "M1" : "M0");
}

function onPassThrough(text) {
    flushPending();
    writeBlock(text);
}

// The first move after a tool call writes all its axes and its feed again. R0/RL/RR stay what
// was last written (rapids always write theirs; a cycle's positioning writes R0 only if needed).
function forceMotion() {
    xOutput.reset();
    yOutput.reset();
    zOutput.reset();
    feedOutput.reset();
}

include("heidenhain-cycles");   // CYCL DEF 200..207, CYCL CALL, M99
include("heidenhain-tilting");  // PLANE SPATIAL / CYCL DEF 19, M128 / FUNCTION TCPM around five-axis operations

// --- The end: retract, M30, the min/max travel report, END PGM ---------------------------------

// X Y Z from the program's extents widened by what five-axis blocks wrote (without TCPM machine
// coordinates, so the report may be wider than either), then B and C as written.
function travelReport() {
    var five = getFiveAxisTravel() || {};
    for (var axis in planeTravel) {  // 3+2 positions count as the rotary axes' travel too
        var p = planeTravel[axis];
        five[axis] = five[axis] ? {min: Math.min(five[axis].min, p.min), max: Math.max(five[axis].max, p.max)} : p;
    }
    if (!travel && Object.keys(five).length == 0)
        return;
    var axes = ["x", "y", "z", "b", "c"];
    for (var i = 0; i < axes.length; ++i) {
        var a = axes[i];
        var min = travel && travel.min[a] !== undefined ? travel.min[a] : null;
        var max = travel && travel.max[a] !== undefined ? travel.max[a] : null;
        if (five && five[a]) {
            min = min === null ? five[a].min : Math.min(min, five[a].min);
            max = max === null ? five[a].max : Math.max(max, five[a].max);
        }
        if (min === null)
            continue;
        var scale = inch && i < 3 ? 1 / 25.4 : 1;
        comment(" " + a.toUpperCase() + "min = " + n(min * scale));
        comment(" " + a.toUpperCase() + "max = " + n(max * scale));
    }
}

function onClose() {
    flushToolCall();
    // The final retract: straight up to the highest Z of the program, unless the tool is there
    // (or nobody knows where it is: then no Z is written).
    var z = getCurrentAxis("z");
    if (travel && travel.max.z !== null && z !== null && z < travel.max.z) {
        var retract = zOutput.format(travel.max.z);
        if (retract)
            writeBlock("L", retract, compOutput.format("R0"), "FMAX");
    }
    writeBlock("L", "M30");
    if (getProperty("travelReport"))
        travelReport();
    writeBlock("END PGM", pgmName, unitWord);
}
