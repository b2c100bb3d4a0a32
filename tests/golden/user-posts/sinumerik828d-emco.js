// A user's own copy of a built-in post (same id): it must be listed as overriding the built-in one
// and be the one `camwb-cli post --post sinumerik828d-emco` uses.
var post = {description: "user copy of the 828D post", vendor: "Me", extension: "mpf"};
function onOpen() { writeln("; user copy"); }
function onRapid(x, y, z) { writeln("RAPID " + x + " " + y + " " + z); }
function onClose() { writeln("M30"); }
