// EMCO Concept MILL 105 with SINUMERIK 828D.
// Keeps every rule the control proved in seed-004 (SinuTrain and the real 828D, §3.2, §4.3, §4.4):
// numbered blocks from N10 step 10, ';' comments right after the block number, the `G17 G40` /
// `G54 G90` preamble, a comment before the tool change, `M6 T<n>`, `M3 S<n>`, modal G words and
// axes, 3 decimals, F in mm/min as a rounded integer and never on G0, G2/G3 with the two centre
// words of the plane always written (I J in G17, never K), X Y Z forced in helical arcs, `M30` and
// a final newline. Closes the gaps the thesis names (§7B): CYCLE81/82/83 (and CYCLE84/85) with
// MCALL or one call per hole, M5/M9 at the tool change and the end, D1 with the tool, coolant,
// G41/G42/G40, G710/G71/G700/G70 and the machine's limits (checked by the kernel). What the 840D
// post writes alike is in include/sinumerik-common.js.
var post = {
    id: "sinumerik828d-emco",
    description: "EMCO Concept MILL 105, SINUMERIK 828D (3-axis)",
    vendor: "EMCO / Siemens",
    extension: "mpf",
    machine: "emco-concept-mill-105",
    machines: ["emco-concept-mill-105"],
    controls: ["sinumerik-828d"],
    capabilities: {
        arcPlanes: ["XY", "ZX", "YZ"],
        helicalArcs: true,
        maxArcSweep: 180,  // longer arcs and full circles are split into pieces of at most 180 deg
        cycles: ["drill", "drillDwell", "peck", "chipBreak", "tap", "bore"],
        maxAxes: 3
    },
    properties: {}
};

// The dialect's properties, formats, words and handlers shared with the other SINUMERIK post.
include("sinumerik-common");

var inverseTimeFormat = createFormat({decimals: 3});

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

function onOpen(program) {
    writeHeader(program);
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

function onCutterComp(side) {
    // G41/G42/G40 go out with the next straight move (blocks.rapid/linear bind "comp"): the 828D
    // starts and ends compensation on a G0/G1 block, and the kernel refuses a change on an arc.
}

function onCycle(cycle) {
    startCycle(cycle);
}

function onClose() {
    stopSpindleAndCoolant();
    writeBlock("M30");
}
