<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
<context>
    <name>NcEditorActions</name>
    <message>
        <source>Removed %1 block number(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Numbered %1 block(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 jump target(s) follow their blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (and %1 more note(s))</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;NC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Find…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find text in the NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Go to Block…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jump to the block with a given number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Go to Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block number:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No block number %1 in the program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Renumber Blocks…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Renumber the blocks of the NC program (one undo step)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The NC program is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;move Block Numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove the N numbers (blocks a GOTO jumps to keep theirs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Compare with File…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare the NC program with another file side by side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (in the editor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program &amp;Information…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Extents, path lengths and machining time of the NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>NcLexer</name>
    <message>
        <source>Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>M word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis word</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed, speed, tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keyword or cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>String</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SimulationRequest</name>
    <message>
        <source>Nothing to simulate yet: the NC program is being traced (or none is open).</source>
        <translation>Zatím není co simulovat: NC program se právě trasuje (nebo žádný není otevřen).</translation>
    </message>
    <message>
        <source>Nothing to simulate: the NC program makes no records.</source>
        <translation>Není co simulovat: NC program nevytváří žádné záznamy.</translation>
    </message>
</context>
<context>
    <name>SimulatorActions</name>
    <message>
        <source>&amp;Simulate</source>
        <translation>&amp;Simulovat</translation>
    </message>
    <message>
        <source>Simulate the NC program in the editor: the machine&apos;s motion, the stock cut, the analysis</source>
        <translation>Simulovat NC program v editoru: pohyb stroje, obrábění polotovaru, analýza</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Přehrát</translation>
    </message>
    <message>
        <source>P&amp;ause</source>
        <translation>Po&amp;zastavit</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Krok &amp;zpět</translation>
    </message>
    <message>
        <source>S&amp;tep Block</source>
        <translation>&amp;Krok o blok</translation>
    </message>
    <message>
        <source>&amp;Jump to Line</source>
        <translation>Přejít na ř&amp;ádek</translation>
    </message>
    <message>
        <source>Move the playback to the first run of the line given beside the button</source>
        <translation>Přesunout přehrávání na první provedení řádku zadaného vedle tlačítka</translation>
    </message>
</context>
<context>
    <name>camwb::gui::CompareDialog</name>
    <message>
        <source>Compare NC Programs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Left…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open &amp;Right…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ignore block &amp;numbers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ignore &amp;blanks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Previous Difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ne&amp;xt Difference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Left NC Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Right NC Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open two programs to compare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The programs are identical</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Difference %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a program on the right to compare</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a program on the left to compare</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::ContourPanel</name>
    <message>
        <source>Side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Outside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left (open chains)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right (open chains)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axial stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step-down (0 = one level)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial passes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial stepover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lead-in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lead-out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lead radius / length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Entry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plunge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ramp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ramp angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> °</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix diameter (0 = tool)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix pitch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tabs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tab width</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tab height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool centre path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contour, G41/G42</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::DrillPanel</name>
    <message>
        <source>Cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drill</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drill with dwell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peck (full retract)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chip breaking</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peck depth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dwell</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depths from each hole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each hole from its top to its bottom; unchecked: the start and final Z of the heights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retract to clearance (G98)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Between holes; unchecked: to the safe plane (R, G99)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the listed order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unchecked: the order that shortens the rapids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth at full diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The final depth is where the drill has its full diameter: the tip goes deeper by the point length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Breakthrough</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::GeometryList</name>
    <message>
        <source>Add selected faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click faces in the 3D view (Ctrl+click for several), then add them here. For holes, click the hole&apos;s wall.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hole (face)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This operation takes no %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>holes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model has no face %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model has no edge %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 is not the wall of a vertical cylindrical hole.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Already in the list.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>face %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 (not in the model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 — not planar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 — planar, Z %2, %3 mm²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edge %1 (not in the model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edge %1 — %2, %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hole %1 — Ø%2 at (%3, %4), Z %5 → %6%7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, through</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hole %1 (not a hole of the model)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 — planar, normal (%2, %3, %4), %5 mm²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 — %2, ruled, drive edge %3, %4 mm²</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::HeightsBox</name>
    <message>
        <source>Clearance Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safe Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Final Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>auto</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Derived from the model and the stock; uncheck to set it</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::HelixPanel</name>
    <message>
        <source>Pitch per turn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depths from each hole</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each hole from its top to its bottom; unchecked: the start and final Z of the heights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Breakthrough</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finishing circle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::InspectorPanel</name>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SINUMERIK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heidenhain Klartext</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ISO (LinuxCNC, Fanuc)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC program (traced)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operations&apos; toolpath</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dialect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D shows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>T%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>before the first tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine the program is traced on: its limits are checked, and five-axis NC (M128, TRAORI, B and C words) is read through its kinematics</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None: no limits checked, three axes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::JobTree</name>
    <message>
        <source>Item</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Work offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Post</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, Ø%2 mm, S%3, F%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>faces %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>edges %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>holes %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no geometry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, T%2, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not loaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::MainWindow</name>
    <message>
        <source>Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Main</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D view unavailable: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open Job…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAM Workbench jobs (*.camwb)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save Job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Job &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Import Model…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Models (*.step *.stp *.iges *.igs *.brep *.brp *.stl);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit Operation…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Post</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save NC Program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC programs (*.%1);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit &amp;All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About CAM Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About CAM Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAM Workbench %1
CAM and post-processor workbench.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Working…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1%2 — CAM Workbench</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC inspector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened NC program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;NC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open NC Program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Trace NC Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>posted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tracing the NC program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment from the called program %1; the editor shows its call.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Task</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Contour…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New P&amp;ocket…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Helix…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Drilling…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Task: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select an operation in the job tree first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The job&apos;s model is not loaded: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unapplied changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The task panel of &quot;%1&quot; has changes that are not applied.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The job has changes that are not saved. Save them?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No NC program: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Out of date — the last post failed; this is the previous program and it cannot be saved:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source> (and %n more, see the job tree)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Opening the job %1 replaces them with its program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening %1 replaces them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opening another job replaces them with its program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Posting the job replaces them with its program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save NC File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The job&apos;s program, posted again, replaces them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The editor keeps the unsaved edits of %1; the job&apos;s new program is not shown (Post shows it).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC program — %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (out of date)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closing the window loses them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The NC program is traced without a machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The NC program is traced on the machine %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New &amp;Swarf (five-axis)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulator</source>
        <translation>Simulátor</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ModalStatePanel</name>
    <message>
        <source>unknown (no move yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped (M5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CW (M3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CCW (M4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 m/min constant surface speed, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 rpm %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off (M9)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>flood (M8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mist (M7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>through tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Work offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abs/inc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No NC program traced yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1</source>
        <translation type="unfinished">řádek %1</translation>
    </message>
    <message>
        <source>, runs %1 times (first run shown)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none called yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (G%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none in the trace (control default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, from the last arc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no arc yet (not in the trace)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm (inch programs converted)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not in the trace; positions absolute</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n diagnostic(s) in this program.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1 mm/min (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm/rev (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 1/min (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left of the contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right of the contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (absolute)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (incremental)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (absolute and incremental words)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (absolute or incremental per coordinate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (inch; positions shown in mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none programmed (control default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (five-axis move)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (3-axis move)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none known (trace with a five-axis machine)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rotary axes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcDocument</name>
    <message>
        <source>Save NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved NC program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved NC edits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 has edits that are not saved. %2

Save them first?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcEditor</name>
    <message>
        <source>column %1: </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcFindBar</name>
    <message>
        <source>Find:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Previous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find the previous match (Shift+Enter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find the next match (Enter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Match case</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whole words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the find bar (Escape)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not found</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcInspector</name>
    <message>
        <source>Tracing the NC program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 more diagnostics not listed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (guessed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 five-axis moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Traced %1 as %2%3: %4 blocks, %5 lines, %6 arcs, %7 rapids, %8 cycles%9 in %10 ms</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::OperationPanel</name>
    <message>
        <source>Contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drilling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>new operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preview pending…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished">Zrušit</translation>
    </message>
    <message>
        <source>Stop computing the preview (the operation stays as edited)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preview</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>T%1 %2 (Ø%3 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Geometry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preview cancelled; change a parameter to compute it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computing…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 lines, %2 arcs, %3 helices, %4 cycles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (%1 rapids; %2 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not applied: this operation cannot be made. Change it, or Cancel.
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Working plane (3+2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Swarf (simultaneous five-axis)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::PocketPanel</name>
    <message>
        <source>Pattern</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset (spiral inward)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zig-zag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zig-zag angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> °</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stepover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> % of Ø</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stepover (mm, 0 = use %)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step-down (0 = one level)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wall stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Floor stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finish walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finish floor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Entry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ramp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plunge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix diameter (0 = 90 % Ø)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Helix pitch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ramp angle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::ProgramInfoDialog</name>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program Information</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm/min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapid rate the time estimate assumes (the machine&apos;s, when it says)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapid rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interpreting the program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 blocks interpreted, %2 diagnostic(s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Extents (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation type="unfinished">%1 mm</translation>
    </message>
    <message>
        <source>Rapid length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapid time (at %1 mm/min)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dwell time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapids / feed moves / arcs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle holes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed moves without a usable feed (not timed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Per tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed length (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rapid length (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z min (cutting)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diagnostics</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 blocks interpreted; %2 error(s), %3 other diagnostic(s): the figures cover what could be interpreted; %4 move(s) of blocks with an error are left out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Estimate from distance and feed</source>
        <translation>Odhad z dráhy a posuvu</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cycle time with accelerations&lt;/b&gt; (no machine chosen: default limits)</source>
        <translation>&lt;b&gt;Čas cyklu se zrychleními&lt;/b&gt; (bez zvoleného stroje: výchozí limity)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cycle time with accelerations&lt;/b&gt; (%1)</source>
        <translation>&lt;b&gt;Čas cyklu se zrychleními&lt;/b&gt; (%1)</translation>
    </message>
    <message>
        <source>Time (distance/feed)</source>
        <translation>Čas (dráha/posuv)</translation>
    </message>
    <message>
        <source>Time with accelerations</source>
        <translation>Čas se zrychleními</translation>
    </message>
</context>
<context>
    <name>camwb::gui::RenumberDialog</name>
    <message>
        <source>Renumber Blocks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Start at:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;tep:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number &amp;comment-only lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number &amp;empty lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keep existing numbers, number only blocks without one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Renumber &amp;only blocks that have a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heidenhain Klartext blocks are always numbered 0, 1, 2, … on every line (continuation lines excepted).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jump targets (GOTOF N100, GOTO 100) follow their blocks. Labels, comments and strings are left as they are.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::ReportView</name>
    <message>
        <source>warning: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error: </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::SimChart</name>
    <message>
        <source>Chart unavailable: %1</source>
        <translation>Graf není k dispozici: %1</translation>
    </message>
</context>
<context>
    <name>camwb::gui::SimDock</name>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>Tool and holder</source>
        <translation>Nástroj a držák</translation>
    </message>
    <message>
        <source>line </source>
        <translation>řádek </translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Rychlost</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Out of date: the program was changed after it was simulated. Simulate again to see what it does now.</source>
        <translation>Zastaralé: program byl po simulaci změněn. Simulujte znovu, abyste viděli, co dělá nyní.</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>The stock&apos;s cell size for the next simulation</source>
        <translation>Velikost buňky polotovaru pro příští simulaci</translation>
    </message>
    <message>
        <source>Colour path by</source>
        <translation>Barvit dráhu podle</translation>
    </message>
    <message>
        <source>Limits</source>
        <translation>Meze</translation>
    </message>
    <message>
        <source>Deviation ±</source>
        <translation>Odchylka ±</translation>
    </message>
    <message>
        <source>Stock resolution</source>
        <translation>Rozlišení polotovaru</translation>
    </message>
    <message>
        <source>Simulating…</source>
        <translation>Simuluje se…</translation>
    </message>
    <message>
        <source>No simulation: press Simulate</source>
        <translation>Žádná simulace: stiskněte Simulovat</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>řádek %1</translation>
    </message>
    <message>
        <source>no line</source>
        <translation>bez řádku</translation>
    </message>
    <message>
        <source>move %1 of %2</source>
        <translation>pohyb %1 z %2</translation>
    </message>
    <message>
        <source>%1 / %2 · %3 · %4</source>
        <translation>%1 / %2 · %3 · %4</translation>
    </message>
    <message>
        <source>Cycle time %1 (distance / feed estimate %2)</source>
        <translation>Čas cyklu %1 (odhad z dráhy a posuvu %2)</translation>
    </message>
    <message>
        <source>Moves (rapid / feed)</source>
        <translation>Pohyby (rychloposuv / posuv)</translation>
    </message>
    <message>
        <source>No stock: the tool plays over the path only.</source>
        <translation>Bez polotovaru: nástroj se přehrává jen po dráze.</translation>
    </message>
    <message>
        <source>The deviation map shows when the end of the program is cut.</source>
        <translation>Mapa odchylek se zobrazí po obrobení konce programu.</translation>
    </message>
    <message>
        <source>No model to compare the stock with.</source>
        <translation>Žádný model, se kterým by se polotovar porovnal.</translation>
    </message>
    <message>
        <source>%1 mm (line %2)</source>
        <translation>%1 mm (řádek %2)</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>At the program&apos;s end: largest gouge %1 · largest leftover %2 · %3 mm beside the part</source>
        <translation>Na konci programu: největší podříznutí %1 · největší zbytek %2 · %3 mm vedle dílce</translation>
    </message>
</context>
<context>
    <name>camwb::gui::SimPlayer</name>
    <message>
        <source>Simulation cancelled</source>
        <translation>Simulace zrušena</translation>
    </message>
    <message>
        <source>Simulated %1: cycle time %2 s, %3 errors, %4 warnings</source>
        <translation>Simulováno %1: čas cyklu %2 s, chyby: %3, varování: %4</translation>
    </message>
</context>
<context>
    <name>camwb::gui::SwarfPanel</name>
    <message>
        <source>Climb milling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axial offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tool tip above (+) or below (−) the face&apos;s bottom edge, along the tool axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial stock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial passes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radial stepover</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chord tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Angle tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The most the tool axis turns from one point to the next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gouge tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How deep the tool may enter the model before the operation fails</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::View3D</name>
    <message>
        <source>3D view unavailable: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenGL is disabled (CAMWB_NO_OPENGL=1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no GUI application</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the &apos;%1&apos; platform has no OpenGL display</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot create an offscreen OpenGL surface</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot create an OpenGL 3.2 core context</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot make an OpenGL 3.2 core context current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>only OpenGL ES is available</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OpenGL %1.%2 found, 3.2 needed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::Workbench</name>
    <message>
        <source>Opened job %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved job %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no NC program to save; post the job first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote NC program %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Busy; import the model again when the current work has finished.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Imported %1 (%2 faces)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toolpath: %1 lines, %2 arcs, %3 rapids</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Posted %1 lines with %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save job</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save NC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The NC program is out of date and was not saved: %1
Fix the job and post it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import model</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>The previous model is not loaded, so the references of the %n operation(s) cannot be checked against %1. Keep them with their face, edge and hole numbers (check each operation), or delete them?</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Keep the operations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete the operations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These references of the operations are not in %1:
%2

Keep the operations without them (they are marked until you choose new geometry in their task panels), or delete the operations that lost references?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete those operations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import of %1 cancelled; the job is unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Deleted %n operation(s) that lost references.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Kept the operations; these references are not in the new model:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Post</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unresolved: the model is not loaded (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The job is being computed; save the NC program when the post has finished.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::WorkingPlaneBox</name>
    <message>
        <source>Flat (tool along Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Along a face&apos;s normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spatial angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3+2: the plane the operation is computed in; the post tilts the machine to it. Flat drilling turns to each hole&apos;s own axis.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The planar face whose outward normal the tool follows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A (about X)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>B (about Y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C (about Z)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
