// A post that fails half way: nothing may reach the output file.
var post = {description: "fails at its second move"};
var moves = 0;
function onRapid(x, y, z) {
    writeln("G0 X" + x);
    if (++moves == 2)
        error("second move refused");
}
