// The iTNC's drilling cycles for the Heidenhain posts, included with include("heidenhain-cycles"):
// CYCL DEF 200/201/203/205/207 with their Q lists in the control's order and texts (English as the
// iTNC writes them, or the thesis' Czech), called with CYCL CALL at the first hole and M99 after.
// Uses the including post's czech, qFormat, qCoordinateFormat, feedFormat, n(), flushToolCall(),
// the outputs xOutput yOutput zOutput compOutput and the pendings spindleStart and coolantBlock.

var qTexts = czech ? {
    200: "BEZPEČNÁ VZDÁLENOST", 201: "HLOUBKA", 206: "POSUV PŘÍSUVU DO HLOUBKY", 202: "HLOUBKA PŘÍSUVU",
    210: "ČASOVÁ PRODLEVA NAHOŘE", 203: "SOUŘADNICE POVRCHU", 204: "2. BEZPEČNÁ VZDÁLENOST",
    211: "ČASOVÁ PRODLEVA DOLE", 208: "POSUV PŘI VYJÍŽDĚNÍ", 212: "HODNOTA ÚBĚRU", 213: "POČET ZLOMENÍ TŘÍSKY",
    205: "MIN. HLOUBKA PŘÍSUVU", 256: "ODSKOK PŘI LOMU TŘÍSKY", 258: "HORNÍ PŘEDSTAVNÁ VZDÁLENOST",
    259: "DOLNÍ PŘEDSTAVNÁ VZDÁLENOST", 257: "HLOUBKA VRTÁNÍ DO LOMU TŘÍSKY", 239: "STOUPÁNÍ ZÁVITU"
} : {
    200: "SET-UP CLEARANCE", 201: "DEPTH", 206: "FEED RATE FOR PLNGNG", 202: "PLUNGING DEPTH",
    210: "DWELL TIME AT TOP", 203: "SURFACE COORDINATE", 204: "2ND SET-UP CLEARANCE", 211: "DWELL TIME AT DEPTH",
    208: "RETRACTION FEED RATE", 212: "DECREMENT", 213: "NR OF BREAKS", 205: "MIN. PLUNGING DEPTH",
    256: "DIST. FOR CHIP BRKNG", 258: "UPPER ADV. STOP DIST.", 259: "LOWER ADV. STOP DIST.",
    257: "DEPTH FOR CHIP BRKNG", 239: "PITCH"
};
var cycleNames = czech ? {200: "VRTÁNÍ", 201: "VYSTRUŽOVÁNÍ", 203: "UNIVERZÁLNÍ VRTÁNÍ",
                          205: "UNIVERZÁLNÍ HLUBOKÉ VRTÁNÍ", 207: "ŘEZÁNÍ ZÁVITU GS NOVÉ"}
                       : {200: "DRILLING", 201: "REAMING", 203: "UNIVERSAL DRILLING", 205: "UNIVERSAL PECKING",
                          207: "RIGID TAPPING NEW"};

// The cycle number and its Q values, in the control's order, for a CL cycle.
function cycleDefinition(cycle) {
    var setup = cycle.retractZ - cycle.topZ;
    if (setup < 0)
        error("the R plane (" + cycle.retractZ + ") is below the hole top (" + cycle.topZ + "): no set-up clearance");
    var depth = cycle.bottomZ - cycle.topZ;  // negative: the iTNC drills in the direction of its sign
    if (!(depth < 0))
        error("the hole bottom (" + cycle.bottomZ + ") is not below its top (" + cycle.topZ + ")");
    // After the hole the tool rises to Q200, then to Q204 above the surface if that is higher.
    var second = cycle.returnToClearance ? Math.max(cycle.clearanceZ - cycle.topZ, 0) : 0;
    var q = function (number, value) { return [number, qFormat.format(value)]; };
    var surface = [203, qCoordinateFormat.format(cycle.topZ)];
    switch (cycle.kind) {
    case "drill":
    case "drillDwell":
        return [200, [q(200, setup), q(201, depth), [206, feedFormat.format(cycle.feed)], q(202, -depth),
                      [210, "0"], surface, q(204, second), [211, n(cycle.dwell)]]];
    case "peck":
        return [205, [q(200, setup), q(201, depth), [206, feedFormat.format(cycle.feed)], q(202, cycle.peck), surface,
                      q(204, second), [212, "0"], [205, "0"], q(258, cycle.peckClearance),
                      q(259, cycle.peckClearance), [257, "0"], q(256, cycle.peckClearance), [211, n(cycle.dwell)]]];
    case "chipBreak":
        // Breaks the chip after every infeed and leaves the hole only at the bottom, as G73 does.
        var breaks = Math.min(99, Math.max(1, Math.ceil(-depth / cycle.peck - 1e-9) - 1));
        return [203, [q(200, setup), q(201, depth), [206, feedFormat.format(cycle.feed)], q(202, cycle.peck),
                      [210, "0"], surface, q(204, second), [212, "0"], [213, String(breaks)], [205, "0"],
                      [211, n(cycle.dwell)], [208, "0"], q(256, cycle.peckClearance)]];
    case "bore":
        // Feed in and feed out, as the kernel's expansion of a bore cycle does.
        return [201, [q(200, setup), q(201, depth), [206, feedFormat.format(cycle.feed)], [211, n(cycle.dwell)],
                      [208, feedFormat.format(cycle.feed)], surface, q(204, second)]];
    case "tap":
        if (!(cycle.spindleRpm > 0))
            error("tapping needs the spindle running: no spindle speed before the cycle");
        var pitch = cycle.feed / cycle.spindleRpm * (cycle.spindleClockwise ? 1 : -1);  // + right-hand thread
        return [207, [q(200, setup), q(201, depth), [239, qCoordinateFormat.format(pitch)], surface, q(204, second)]];
    }
    error("cycle " + cycle.kind + " is not supported by this post");
}

var holeCount = 0;

function onCycle(cycle) {
    flushToolCall();
    var definition = cycleDefinition(cycle);
    for (var q = 0; q < definition[1].length; ++q)  // the control's input range of a Q value
        if (!(Math.abs(parseFloat(definition[1][q][1])) <= 99999.9999))
            error("Q" + definition[1][q][0] + "=" + definition[1][q][1] + " is out of the iTNC's range (+-99999.9999)");
    writeBlock("CYCL DEF " + definition[0], cycleNames[definition[0]]);
    for (var i = 0; i < definition[1].length; ++i) {
        var entry = definition[1][i];
        writeln("  Q" + entry[0] + "=" + entry[1] + " ;" + qTexts[entry[0]]);
    }
    // The cycle goes down to Q200 at FMAX itself, from where it is called: the holes are reached
    // at the return plane, or right after a tool call at the height the change left (seed-000
    // 5.8: L X Y FMAX M3, CYCL CALL), as the kernel moves X/Y before Z after a change.
    var z = getCurrentAxis("z");
    if (z !== null && z < cycle.returnZ) {
        zOutput.reset();
        writeBlock("L", zOutput.format(cycle.returnZ), compOutput.format("R0"), "FMAX");
    }
    holeCount = 0;
}

function onCyclePoint(x, y, z) {
    var block = ["L", xOutput.format(x), yOutput.format(y)];
    if (!block[1] && !block[2]) {  // the same position again: a block still needs a word to call the cycle
        xOutput.reset();
        block[1] = xOutput.format(x);
    }
    block.push(compOutput.format("R0"), "FMAX", spindleStart.take());
    if (holeCount++ == 0) {
        writeBlock.apply(null, block);
        writeBlock("CYCL CALL");
    } else {
        block.push("M99");
        writeBlock.apply(null, block);
    }
    var pendingCoolant = coolantBlock.take();
    if (pendingCoolant)
        writeBlock(pendingCoolant);
}

function onCycleEnd(cycle) {
    zOutput.reset();  // the cycle left Z at its return plane
}
