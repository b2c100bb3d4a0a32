// Tilting on the iTNC for the Heidenhain posts, included with include("heidenhain-tilting"): 3+2
// working planes as PLANE SPATIAL ... TURN MB MAX FMAX SEQ+- / PLANE RESET or CYCL DEF 19 (the
// post's workingPlane property), and the frame of a simultaneous five-axis operation: retract,
// turn to the first pose, M128 / FUNCTION TCPM / M116 (the post's tcpm and rotaryFeed), and back.
// Uses the including post's czech, angleFormat, flushToolCall(), forceMotion() and the
// outputs bOutput and cOutput; planeTravel is the post's travel report's.

// The rotary positions the working planes turned to, for the travel report: {b: {min, max}, c: ...}.
var planeTravel = {};

function notePlaneTravel(axis, value) {
    var t = planeTravel[axis];
    planeTravel[axis] = t ? {min: Math.min(t.min, value), max: Math.max(t.max, value)} : {min: value, max: value};
}

// CYCL DEF 19 with the machine's B and C (0, 0: the plane reset), after retracting to the travel
// limit along the tool axis; the control needs the table turned by an L block. Cycle 19 sets up
// the machine's X as the turned table carries it, not the plane's: CYCL DEF 10 turns the
// coordinates about the tool axis by `rotation` degrees onto the plane's X (ROT+0 undoes it before
// the reset).
var planeRotation = 0;  // the CYCL DEF 10 rotation in force

function rotationCycle(degrees) {
    writeBlock("CYCL DEF 10.0", czech ? "ROTACE" : "ROTATION");
    writeBlock("CYCL DEF 10.1", "ROT" + angleFormat.format(degrees));
    planeRotation = degrees;
}

function cycle19Plane(b, c, rotation) {
    writeBlock("L", "M140 MB MAX");
    if (planeRotation != 0)
        rotationCycle(0);
    writeBlock("CYCL DEF 19.0", czech ? "NAKLOPENÍ ROVINY" : "WORKING PLANE");
    writeBlock("CYCL DEF 19.1", "B" + angleFormat.format(b), "C" + angleFormat.format(c));
    writeBlock("L", "C" + angleFormat.format(c), "B" + angleFormat.format(b), "R0", "FMAX");
    if (Math.abs(rotation) >= 0.00005)  // the angle as written (4 decimals) is not 0
        rotationCycle(rotation);
}

// The moves after it are in the plane's frame (the kernel forgets every axis). PLANE SPATIAL turns
// the table itself after retracting to the travel limit along the tool axis (TURN MB MAX), on the
// branch the kinematics chose (SEQ: the sign of B); CYCL DEF 19 needs the table turned by hand.
function onWorkingPlane(plane) {
    flushToolCall();
    var origin = plane.origin;
    if (origin.x != 0 || origin.y != 0 || origin.z != 0)
        throw new Error("a working plane whose origin is not the workpiece zero (a datum shift) is not written yet");
    var cycle19 = getProperty("workingPlane") == "cycle19";
    if (!plane.tilted) {
        if (cycle19) {
            cycle19Plane(0, 0, 0);
        } else {
            writeBlock("PLANE RESET TURN MB MAX FMAX");
        }
        forceMotion();
        return;
    }
    if (!plane.machine)
        throw new Error("a tilted working plane needs a machine with a five-axis chain (" + (machine ? machine.id : "none") +
                        " has none)");
    notePlaneTravel("b", plane.machine.b);
    notePlaneTravel("c", plane.machine.c);
    if (cycle19) {
        cycle19Plane(plane.machine.b, plane.machine.c, plane.machine.rotation);
    } else {
        writeBlock("PLANE SPATIAL", "SPA" + angleFormat.format(plane.spatialA), "SPB" + angleFormat.format(plane.spatialB),
                   "SPC" + angleFormat.format(plane.spatialC), "TURN MB MAX FMAX", plane.machine.branch < 0 ? "SEQ-" : "SEQ+");
    }
    forceMotion();
}

// --- Five-axis operations ---------------------------------------------------------------------

// Before a five-axis operation: away from the part along the tool axis to the travel limit, the
// table turned to the operation's first pose without TCPM, then TCPM (or M116) on.
function onFiveAxisBegin(section) {
    flushToolCall();
    var tcpmMode = getProperty("tcpm");  // the operation's own, if it sets one
    writeBlock("L", "M140 MB MAX");
    forceMotion();  // the retract moved X, Y and Z
    var turn = ["L", cOutput.format(section.c), bOutput.format(section.b)];
    if (turn[1] || turn[2])
        writeBlock.apply(null, turn.concat(["FMAX"]));
    if (tcpmMode == "m128")
        writeBlock("L", "M128");
    else if (tcpmMode == "function-tcpm")
        writeBlock("FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS");
    else if (getProperty("rotaryFeed") == "m116")
        writeBlock("L", "M116");
}

// After it: out along the tool axis, TCPM off, the table home as the kernel plans the next
// operation from (B+0, C at the nearest whole turn). X, Y and Z are then unknown.
function onFiveAxisEnd(pose, home) {
    var tcpmMode = getProperty("tcpm");
    writeBlock("L", "M140 MB MAX");
    if (tcpmMode == "m128")
        writeBlock("L", "M129");
    else if (tcpmMode == "function-tcpm")
        writeBlock("FUNCTION RESET TCPM");
    else if (getProperty("rotaryFeed") == "m116")
        writeBlock("L", "M117");
    var turn = ["L", cOutput.format(home.c), bOutput.format(home.b)];
    if (turn[1] || turn[2])
        writeBlock.apply(null, turn.concat(["FMAX"]));
    forceMotion();
}
