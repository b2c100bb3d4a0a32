// A post that writes two subprograms beside its main program (openFile/closeFile): the CLI puts
// them beside the -o file and names them in its report line.
var post = {description: "main program and two subprograms", extension: "mpf"};
function onRapid(x, y, z) {
    writeBlock("G0 X" + x);
}
function onLinear(x, y, z, feed) {
    writeBlock("G1 X" + x);
}
function onSection() {}
function onSectionEnd() {}
function onToolChange() {}
function onFeedMode() {}
function onSpindle() {}
function onCoolant() {}
function onClose() {
    writeBlock("SUB1");
    writeBlock("M30");
    openFile("SUB1.SPF");
    writeln("PROC SUB1");
    writeBlock("SUB2");
    writeBlock("M17");
    closeFile();
    openFile("SUB2.SPF");
    writeln("PROC SUB2");
    writeBlock("M17");
    closeFile();
}
