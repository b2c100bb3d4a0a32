<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
<context>
    <name>JobSetupActions</name>
    <message>
        <source>Job &amp;Setup…</source>
        <translation>&amp;Nastavení úlohy…</translation>
    </message>
    <message>
        <source>&amp;Job</source>
        <translation>Ú&amp;loha</translation>
    </message>
    <message>
        <source>Model, stock, work coordinates, machine, post and output</source>
        <translation>Model, polotovar, souřadnice obrobku, stroj, postprocesor a výstup</translation>
    </message>
</context>
<context>
    <name>NcEditorActions</name>
    <message>
        <source>Removed %1 block number(s)</source>
        <translation>Odstraněno čísel bloků: %1</translation>
    </message>
    <message>
        <source>Numbered %1 block(s)</source>
        <translation>Očíslováno bloků: %1</translation>
    </message>
    <message>
        <source>, %1 jump target(s) follow their blocks</source>
        <translation>, cíle skoků (%1) následují své bloky</translation>
    </message>
    <message>
        <source>; line %1: %2</source>
        <translation>; řádek %1: %2</translation>
    </message>
    <message>
        <source>; %1</source>
        <translation>; %1</translation>
    </message>
    <message>
        <source> (and %1 more note(s))</source>
        <translation> (a další poznámky: %1)</translation>
    </message>
    <message>
        <source>&amp;NC</source>
        <translation>&amp;NC</translation>
    </message>
    <message>
        <source>&amp;Find…</source>
        <translation>&amp;Najít…</translation>
    </message>
    <message>
        <source>Find text in the NC program</source>
        <translation>Najít text v NC programu</translation>
    </message>
    <message>
        <source>&amp;Go to Block…</source>
        <translation>&amp;Přejít na blok…</translation>
    </message>
    <message>
        <source>Jump to the block with a given number</source>
        <translation>Přejít na blok se zadaným číslem</translation>
    </message>
    <message>
        <source>Go to Block</source>
        <translation>Přejít na blok</translation>
    </message>
    <message>
        <source>Block number:</source>
        <translation>Číslo bloku:</translation>
    </message>
    <message>
        <source>No block number %1 in the program</source>
        <translation>V programu není blok číslo %1</translation>
    </message>
    <message>
        <source>&amp;Renumber Blocks…</source>
        <translation>Př&amp;ečíslovat bloky…</translation>
    </message>
    <message>
        <source>Renumber the blocks of the NC program (one undo step)</source>
        <translation>Přečíslovat bloky NC programu (jeden krok zpět)</translation>
    </message>
    <message>
        <source>The NC program is read-only</source>
        <translation>NC program je jen pro čtení</translation>
    </message>
    <message>
        <source>Re&amp;move Block Numbers</source>
        <translation>Odstranit čísla &amp;bloků</translation>
    </message>
    <message>
        <source>Remove the N numbers (blocks a GOTO jumps to keep theirs)</source>
        <translation>Odstranit čísla N (bloky, na které skáče GOTO, si je ponechají)</translation>
    </message>
    <message>
        <source>&amp;Compare with File…</source>
        <translation>Po&amp;rovnat se souborem…</translation>
    </message>
    <message>
        <source>Compare the NC program with another file side by side</source>
        <translation>Porovnat NC program s jiným souborem vedle sebe</translation>
    </message>
    <message>
        <source>Current program</source>
        <translation>Aktuální program</translation>
    </message>
    <message>
        <source>%1 (in the editor)</source>
        <translation>%1 (v editoru)</translation>
    </message>
    <message>
        <source>Program &amp;Information…</source>
        <translation>&amp;Informace o programu…</translation>
    </message>
    <message>
        <source>Extents, path lengths and machining time of the NC program</source>
        <translation>Rozměry, délky drah a čas obrábění NC programu</translation>
    </message>
    <message>
        <source>Compare with File</source>
        <translation>Porovnat se souborem</translation>
    </message>
    <message>
        <source>Cannot read %1</source>
        <translation>Nelze přečíst %1</translation>
    </message>
    <message>
        <source>%1 is a CL file: block numbers are for NC programs</source>
        <translation>%1 je soubor CL: čísla bloků patří NC programům</translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;CL files (*.apt *.aptsource *.cl *.cls *.dump *.trace);;All files (*)</source>
        <translation>NC programy (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;Soubory CL (*.apt *.aptsource *.cl *.cls *.dump *.trace);;Všechny soubory (*)</translation>
    </message>
</context>
<context>
    <name>NcLexer</name>
    <message>
        <source>Default</source>
        <translation>Výchozí</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>Komentář</translation>
    </message>
    <message>
        <source>Block number</source>
        <translation>Číslo bloku</translation>
    </message>
    <message>
        <source>G word</source>
        <translation>Slovo G</translation>
    </message>
    <message>
        <source>M word</source>
        <translation>Slovo M</translation>
    </message>
    <message>
        <source>Axis word</source>
        <translation>Slovo osy</translation>
    </message>
    <message>
        <source>Feed, speed, tool</source>
        <translation>Posuv, otáčky, nástroj</translation>
    </message>
    <message>
        <source>Keyword or cycle</source>
        <translation>Klíčové slovo nebo cyklus</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>Číslo</translation>
    </message>
    <message>
        <source>String</source>
        <translation>Řetězec</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parametr</translation>
    </message>
</context>
<context>
    <name>PostSettingsActions</name>
    <message>
        <source>Post &amp;&amp; &amp;Properties…</source>
        <translation>Postprocesor a &amp;vlastnosti…</translation>
    </message>
    <message>
        <source>&amp;Job</source>
        <translation>Ú&amp;loha</translation>
    </message>
    <message>
        <source>Choose the job&apos;s post and set its properties</source>
        <translation>Zvolit postprocesor úlohy a nastavit jeho vlastnosti</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Go to &amp;Job Tree</source>
        <translation>Přejít na strom ú&amp;lohy</translation>
    </message>
    <message>
        <source>Go to Tas&amp;k Panel</source>
        <translation>Přejít na panel ú&amp;kolu</translation>
    </message>
    <message>
        <source>No task panel is open.</source>
        <translation>Není otevřen žádný panel úkolu.</translation>
    </message>
    <message>
        <source>Go to &amp;NC Program</source>
        <translation>Přejít na &amp;NC program</translation>
    </message>
    <message>
        <source>Go to Re&amp;port</source>
        <translation>Přejít na pr&amp;otokol</translation>
    </message>
    <message>
        <source>Go to 3D &amp;View</source>
        <translation>Přejít na &amp;3D pohled</translation>
    </message>
    <message>
        <source>%1 (not found)</source>
        <translation>%1 (nenalezeno)</translation>
    </message>
</context>
<context>
    <name>SetupSheetActions</name>
    <message>
        <source>Setup &amp;Sheet…</source>
        <translation>&amp;Seřizovací list…</translation>
    </message>
    <message>
        <source>Write the setup sheet of the job for the operator: HTML and PDF</source>
        <translation>Vytvořit seřizovací list úlohy pro obsluhu stroje: HTML a PDF</translation>
    </message>
    <message>
        <source>Save setup sheet</source>
        <translation>Uložit seřizovací list</translation>
    </message>
    <message>
        <source>Setup sheets (*.html);;All files (*)</source>
        <translation>Seřizovací listy (*.html);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Setup sheet</source>
        <translation>Seřizovací list</translation>
    </message>
    <message>
        <source>The setup sheet was not written: %1</source>
        <translation>Seřizovací list nebyl zapsán: %1</translation>
    </message>
    <message>
        <source>Setup sheet written: %1</source>
        <translation>Zapsán seřizovací list: %1</translation>
    </message>
    <message>
        <source>The job changed while the setup sheet was being made, so it was not written. Make it again when the program is current.</source>
        <translation>Úloha se během tvorby seřizovacího listu změnila, proto nebyl zapsán. Vytvořte jej znovu, až bude program aktuální.</translation>
    </message>
    <message>
        <source>Setup sheet cancelled: nothing was written</source>
        <translation>Seřizovací list zrušen: nic nebylo zapsáno</translation>
    </message>
    <message>
        <source>Making the setup sheet (simulating the program)…</source>
        <translation>Vytváří se seřizovací list (simulace programu)…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
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
    <message>
        <source>The blank stock&apos;s file is not read (the report says why): nothing to cut yet.</source>
        <translation>Soubor tvarového polotovaru není načten (důvod je ve zprávě): zatím není co obrábět.</translation>
    </message>
</context>
<context>
    <name>SimulatorActions</name>
    <message>
        <source>&amp;Simulate</source>
        <translation>Si&amp;mulovat</translation>
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
        <translation>Pozastav&amp;it</translation>
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
    <message>
        <source>&amp;Import Measured Trace…</source>
        <translation>&amp;Importovat naměřený záznam…</translation>
    </message>
    <message>
        <source>Overlay a trace the control recorded (TNCscope CSV) on the simulated program: nominal and actual paths on the workpiece, the deviation per sample</source>
        <translation>Překrýt simulovaný program záznamem z řídicího systému (CSV z TNCscope): požadovaná a skutečná dráha na obrobku, odchylka v každém vzorku</translation>
    </message>
    <message>
        <source>C&amp;lear Measured Trace</source>
        <translation>O&amp;dstranit naměřený záznam</translation>
    </message>
    <message>
        <source>&amp;Machine Frame</source>
        <translation>Souřadnice &amp;stroje</translation>
    </message>
    <message>
        <source>Show the scene as the machine sees it: the tool along the spindle, the stock, the model, the path and the rotary table turned by the table&apos;s axes (a head&apos;s axes tilt the tool)</source>
        <translation>Zobrazit scénu tak, jak ji vidí stroj: nástroj v ose vřetena, polotovar, model, dráha a otočný stůl natočené osami stolu (osy hlavy naklápějí nástroj)</translation>
    </message>
    <message>
        <source>Machine frame: simulate a five-axis program first</source>
        <translation>Souřadnice stroje: nejprve simulujte pětiosý program</translation>
    </message>
    <message>
        <source>Machine frame: no machine is chosen for this program, so no kinematic chain says what the table turns (choose a five-axis machine in the NC inspector)</source>
        <translation>Souřadnice stroje: pro tento program není zvolen žádný stroj, takže žádný kinematický řetězec neříká, co stůl otáčí (zvolte pětiosý stroj v NC inspektoru)</translation>
    </message>
    <message>
        <source>Machine frame: the machine %1 has no five-axis kinematic chain in its file, so nothing says what its table turns</source>
        <translation>Souřadnice stroje: soubor stroje %1 neobsahuje pětiosý kinematický řetězec, takže nic neříká, co jeho stůl otáčí</translation>
    </message>
</context>
<context>
    <name>ToolActions</name>
    <message>
        <source>&amp;Tools</source>
        <translation>Nás&amp;troje</translation>
    </message>
    <message>
        <source>Tool &amp;Library…</source>
        <translation>&amp;Knihovna nástrojů…</translation>
    </message>
    <message>
        <source>The tool library: add its tools to the job, import, export</source>
        <translation>Knihovna nástrojů: přidat její nástroje do úlohy, import, export</translation>
    </message>
    <message>
        <source>Compute &amp;Feeds and Speeds</source>
        <translation>&amp;Vypočítat řezné podmínky</translation>
    </message>
    <message>
        <source>Set the job&apos;s tools&apos; spindle speed and feeds from their cutting data and the job&apos;s stock material</source>
        <translation>Nastavit otáčky vřetena a posuvy nástrojů úlohy podle jejich řezných dat a materiálu polotovaru úlohy</translation>
    </message>
</context>
<context>
    <name>camwb::gui::Autosaver</name>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatické uložení selhalo: %1</translation>
    </message>
</context>
<context>
    <name>camwb::gui::CompareDialog</name>
    <message>
        <source>Compare NC Programs</source>
        <translation>Porovnat NC programy</translation>
    </message>
    <message>
        <source>Open &amp;Left…</source>
        <translation>Otevřít &amp;levý…</translation>
    </message>
    <message>
        <source>Open &amp;Right…</source>
        <translation>Otevřít &amp;pravý…</translation>
    </message>
    <message>
        <source>Ignore block &amp;numbers</source>
        <translation>Ignorovat čísla &amp;bloků</translation>
    </message>
    <message>
        <source>Ignore &amp;blanks</source>
        <translation>Ignorovat &amp;mezery</translation>
    </message>
    <message>
        <source>&amp;Previous Difference</source>
        <translation>Př&amp;edchozí rozdíl</translation>
    </message>
    <message>
        <source>Ne&amp;xt Difference</source>
        <translation>&amp;Další rozdíl</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>Nelze přečíst %1: %2</translation>
    </message>
    <message>
        <source>Open Left NC Program</source>
        <translation>Otevřít levý NC program</translation>
    </message>
    <message>
        <source>Open Right NC Program</source>
        <translation>Otevřít pravý NC program</translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;All files (*)</source>
        <translation>NC programy (*.mpf *.spf *.MPF *.SPF *.h *.H *.nc *.ngc *.tap *.iso *.cnc *.txt);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Open two programs to compare</source>
        <translation>Otevřete dva programy k porovnání</translation>
    </message>
    <message>
        <source>The programs are identical</source>
        <translation>Programy jsou shodné</translation>
    </message>
    <message numerus="yes">
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n rozdíl</numerusform>
            <numerusform>%n rozdíly</numerusform>
            <numerusform>%n rozdílů</numerusform>
        </translation>
    </message>
    <message>
        <source>Difference %1 of %2</source>
        <translation>Rozdíl %1 z %2</translation>
    </message>
    <message>
        <source>Open a program on the right to compare</source>
        <translation>Otevřete program vpravo k porovnání</translation>
    </message>
    <message>
        <source>Open a program on the left to compare</source>
        <translation>Otevřete program vlevo k porovnání</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ContourPanel</name>
    <message>
        <source>Side</source>
        <translation>Strana</translation>
    </message>
    <message>
        <source>Outside</source>
        <translation>Vně</translation>
    </message>
    <message>
        <source>Inside</source>
        <translation>Uvnitř</translation>
    </message>
    <message>
        <source>On the contour</source>
        <translation>Na kontuře</translation>
    </message>
    <message>
        <source>Left (open chains)</source>
        <translation>Vlevo (otevřené řetězce)</translation>
    </message>
    <message>
        <source>Right (open chains)</source>
        <translation>Vpravo (otevřené řetězce)</translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation>Sousledné frézování</translation>
    </message>
    <message>
        <source>Radial stock</source>
        <translation>Radiální přídavek</translation>
    </message>
    <message>
        <source>Axial stock</source>
        <translation>Axiální přídavek</translation>
    </message>
    <message>
        <source>Step-down (0 = one level)</source>
        <translation>Přísuv Z (0 = najednou)</translation>
    </message>
    <message>
        <source>Radial passes</source>
        <translation>Radiální průchody</translation>
    </message>
    <message>
        <source>Radial stepover</source>
        <translation>Radiální krok</translation>
    </message>
    <message>
        <source>None</source>
        <translation>Žádné</translation>
    </message>
    <message>
        <source>Arc</source>
        <translation>Oblouk</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Přímka</translation>
    </message>
    <message>
        <source>Lead-in</source>
        <translation>Najetí</translation>
    </message>
    <message>
        <source>Lead-out</source>
        <translation>Odjetí</translation>
    </message>
    <message>
        <source>Lead radius / length</source>
        <translation>Poloměr / délka najetí</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Zanoření</translation>
    </message>
    <message>
        <source>Plunge</source>
        <translation>Kolmo</translation>
    </message>
    <message>
        <source>Ramp</source>
        <translation>Rampa</translation>
    </message>
    <message>
        <source>Helix</source>
        <translation>Šroubovice</translation>
    </message>
    <message>
        <source>Ramp angle</source>
        <translation>Úhel rampy</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Helix diameter (0 = tool)</source>
        <translation>Ø šroubovice (0 = nástroj)</translation>
    </message>
    <message>
        <source>Helix pitch</source>
        <translation>Stoupání šroubovice</translation>
    </message>
    <message>
        <source>Tabs</source>
        <translation>Můstky</translation>
    </message>
    <message>
        <source>Tab width</source>
        <translation>Šířka můstku</translation>
    </message>
    <message>
        <source>Tab height</source>
        <translation>Výška můstku</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Výstup</translation>
    </message>
    <message>
        <source>Tool centre path</source>
        <translation>Dráha středu nástroje</translation>
    </message>
    <message>
        <source>Contour, G41/G42</source>
        <translation>Kontura, G41/G42</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
</context>
<context>
    <name>camwb::gui::CuttingDataModel</name>
    <message>
        <source>aluminium</source>
        <translation>hliník</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Materiál</translation>
    </message>
    <message>
        <source>vc (m/min)</source>
        <translation>vc (m/min)</translation>
    </message>
    <message>
        <source>Plunge (× feed)</source>
        <translation>Zanoření (× posuv)</translation>
    </message>
    <message>
        <source>Ramp (× feed)</source>
        <translation>Rampa (× posuv)</translation>
    </message>
    <message>
        <source>fz (%1/tooth)</source>
        <translation>fz (%1/zub)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::DrillPanel</name>
    <message>
        <source>Cycle</source>
        <translation>Cyklus</translation>
    </message>
    <message>
        <source>Drill</source>
        <translation>Vrtání</translation>
    </message>
    <message>
        <source>Drill with dwell</source>
        <translation>Vrtání s prodlevou</translation>
    </message>
    <message>
        <source>Peck (full retract)</source>
        <translation>Hluboké vrtání (výjezd)</translation>
    </message>
    <message>
        <source>Chip breaking</source>
        <translation>Lámání třísky</translation>
    </message>
    <message>
        <source>Peck depth</source>
        <translation>Hloubka přísuvu</translation>
    </message>
    <message>
        <source>Dwell</source>
        <translation>Prodleva</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Depths from each hole</source>
        <translation>Hloubky podle každé díry</translation>
    </message>
    <message>
        <source>Each hole from its top to its bottom; unchecked: the start and final Z of the heights</source>
        <translation>Každá díra od svého vrcholu ke dnu; nezaškrtnuto: počáteční a koncové Z z výšek</translation>
    </message>
    <message>
        <source>Retract to clearance (G98)</source>
        <translation>Výjezd na Z přejezdu (G98)</translation>
    </message>
    <message>
        <source>Between holes; unchecked: to the safe plane (R, G99)</source>
        <translation>Mezi dírami; nezaškrtnuto: do bezpečné roviny (R, G99)</translation>
    </message>
    <message>
        <source>Keep the listed order</source>
        <translation>Zachovat pořadí seznamu</translation>
    </message>
    <message>
        <source>Unchecked: the order that shortens the rapids</source>
        <translation>Nezaškrtnuto: pořadí, které zkracuje rychloposuvy</translation>
    </message>
    <message>
        <source>Depth at full diameter</source>
        <translation>Hloubka na plný průměr</translation>
    </message>
    <message>
        <source>The final depth is where the drill has its full diameter: the tip goes deeper by the point length</source>
        <translation>Konečná hloubka je tam, kde má vrták plný průměr: špička jde hlouběji o délku špičky</translation>
    </message>
    <message>
        <source>Breakthrough</source>
        <translation>Přesah průvrtu</translation>
    </message>
</context>
<context>
    <name>camwb::gui::GeometryList</name>
    <message>
        <source>Add selected faces</source>
        <translation>Přidat výběr</translation>
    </message>
    <message>
        <source>Click faces in the 3D view (Ctrl+click for several), then add them here. For holes, click the hole&apos;s wall.</source>
        <translation>Klikněte na plochy ve 3D pohledu (Ctrl+klik pro více), pak je přidejte sem. U děr klikněte na stěnu díry.</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Odebrat</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Plocha</translation>
    </message>
    <message>
        <source>Edge</source>
        <translation>Hrana</translation>
    </message>
    <message>
        <source>Hole (face)</source>
        <translation>Díra (plocha)</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Přidat</translation>
    </message>
    <message>
        <source>This operation takes no %1.</source>
        <translation>Tato operace nepřijímá %1.</translation>
    </message>
    <message>
        <source>faces</source>
        <translation>plochy</translation>
    </message>
    <message>
        <source>edges</source>
        <translation>hrany</translation>
    </message>
    <message>
        <source>holes</source>
        <translation>díry</translation>
    </message>
    <message>
        <source>The model has no face %1.</source>
        <translation>Model nemá plochu %1.</translation>
    </message>
    <message>
        <source>The model has no edge %1.</source>
        <translation>Model nemá hranu %1.</translation>
    </message>
    <message>
        <source>Face %1 is not the wall of a vertical cylindrical hole.</source>
        <translation>Plocha %1 není stěnou svislé válcové díry.</translation>
    </message>
    <message>
        <source>Already in the list.</source>
        <translation>Už je v seznamu.</translation>
    </message>
    <message>
        <source>face %1: %2</source>
        <translation>plocha %1: %2</translation>
    </message>
    <message>
        <source>Face %1 (not in the model)</source>
        <translation>Plocha %1 (není v modelu)</translation>
    </message>
    <message>
        <source>Face %1 — not planar</source>
        <translation>Plocha %1 — není rovinná</translation>
    </message>
    <message>
        <source>Edge %1 (not in the model)</source>
        <translation>Hrana %1 (není v modelu)</translation>
    </message>
    <message>
        <source>Hole %1 — Ø%2 at (%3, %4), Z %5 → %6%7</source>
        <translation>Díra %1 — Ø%2 v (%3, %4), Z %5 → %6%7</translation>
    </message>
    <message>
        <source>, through</source>
        <translation>, průchozí</translation>
    </message>
    <message>
        <source>Hole %1 (not a hole of the model)</source>
        <translation>Díra %1 (není dírou modelu)</translation>
    </message>
    <message>
        <source>Face %1 — %2, ruled, drive edge %3, %4 %5²</source>
        <translation>Plocha %1 — %2, přímková, řídicí hrana %3, %4 %5²</translation>
    </message>
    <message>
        <source>Face %1 — planar, normal (%2, %3, %4), %5 %6²</source>
        <translation>Plocha %1 — rovinná, normála (%2, %3, %4), %5 %6²</translation>
    </message>
    <message>
        <source>Face %1 — planar, Z %2, %3 %4²</source>
        <translation>Plocha %1 — rovinná, Z %2, %3 %4²</translation>
    </message>
    <message>
        <source>Edge %1 — %2, %3 %4</source>
        <translation>Hrana %1 — %2, %3 %4</translation>
    </message>
</context>
<context>
    <name>camwb::gui::GroovePanel</name>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Start point X, radius (R0)</source>
        <translation>Počáteční bod X, poloměr (R0)</translation>
    </message>
    <message>
        <source>Where the right flank meets the surface (P): its radius</source>
        <translation>Kde se pravý bok setkává s povrchem (P): jeho poloměr</translation>
    </message>
    <message>
        <source>Start point Z (R1)</source>
        <translation>Počáteční bod Z (R1)</translation>
    </message>
    <message>
        <source>Where the right flank meets the surface (P): along the spindle</source>
        <translation>Kde se pravý bok setkává s povrchem (P): podél osy vřetena</translation>
    </message>
    <message>
        <source>Cone angle (R2)</source>
        <translation>Úhel kužele (R2)</translation>
    </message>
    <message>
        <source>Angle of the shaft&apos;s surface to the Z axis, rising to the right; 0 for a cylinder</source>
        <translation>Úhel povrchu hřídele k ose Z, stoupající doprava; 0 pro válec</translation>
    </message>
    <message>
        <source>Depth (R3)</source>
        <translation>Hloubka (R3)</translation>
    </message>
    <message>
        <source>Radial depth of the groove below P</source>
        <translation>Radiální hloubka zápichu pod bodem P</translation>
    </message>
    <message>
        <source>Bottom width (R4)</source>
        <translation>Šířka dna (R4)</translation>
    </message>
    <message>
        <source>Right flank angle (R5)</source>
        <translation>Úhel pravého boku (R5)</translation>
    </message>
    <message>
        <source>From the radial direction; 0 for a square flank</source>
        <translation>Od radiálního směru; 0 pro kolmý bok</translation>
    </message>
    <message>
        <source>Left flank angle (R6)</source>
        <translation>Úhel levého boku (R6)</translation>
    </message>
    <message>
        <source>Bottom allowance (R7)</source>
        <translation>Přídavek na dně (R7)</translation>
    </message>
    <message>
        <source>Left on the bottom, in X</source>
        <translation>Ponechá se na dně, ve směru X</translation>
    </message>
    <message>
        <source>Flank allowance (R8)</source>
        <translation>Přídavek na bocích (R8)</translation>
    </message>
    <message>
        <source>Left on the flanks, normal to them</source>
        <translation>Ponechá se na bocích, kolmo k nim</translation>
    </message>
    <message>
        <source>The chosen grooving tool&apos;s width (its diameter field)</source>
        <translation>Šířka zvoleného zapichovacího nože (jeho pole průměru)</translation>
    </message>
    <message>
        <source>Insert width (R9)</source>
        <translation>Šířka destičky (R9)</translation>
    </message>
    <message>
        <source>Step factor (R10)</source>
        <translation>Součinitel kroku (R10)</translation>
    </message>
    <message>
        <source>Axial step between plunges as a share of the insert width (0 &lt; f ≤ 1)</source>
        <translation>Axiální krok mezi zápichy jako podíl šířky destičky (0 &lt; f ≤ 1)</translation>
    </message>
    <message>
        <source>Infeed (R11)</source>
        <translation>Přísuv (R11)</translation>
    </message>
    <message>
        <source>Each plunge goes this much deeper than the one before</source>
        <translation>Každý zápich jde o tolik hlouběji než předchozí</translation>
    </message>
    <message>
        <source>Safety distance (R30)</source>
        <translation>Bezpečná vzdálenost (R30)</translation>
    </message>
    <message>
        <source>Clearance of every retract over the material</source>
        <translation>Odstup každého odjezdu nad materiálem</translation>
    </message>
    <message>
        <source>Final retract</source>
        <translation>Závěrečný odjezd</translation>
    </message>
    <message>
        <source>The last rapid goes to X = R0 + this (the thesis&apos; R0 + 100)</source>
        <translation>Poslední rychloposuv jede na X = R0 + tato hodnota (v práci R0 + 100)</translation>
    </message>
    <message>
        <source>Surface speed (G96)</source>
        <translation>Řezná rychlost (G96)</translation>
    </message>
    <message>
        <source> m/min</source>
        <translation> m/min</translation>
    </message>
    <message>
        <source>Spindle limit (LIMS)</source>
        <translation>Omezení otáček (LIMS)</translation>
    </message>
    <message>
        <source> rpm</source>
        <translation> ot/min</translation>
    </message>
    <message>
        <source>Feed (G95)</source>
        <translation>Posuv (G95)</translation>
    </message>
    <message>
        <source> mm/rev</source>
        <translation> mm/ot</translation>
    </message>
    <message>
        <source>Coolant (M8)</source>
        <translation>Chlazení (M8)</translation>
    </message>
    <message>
        <source>no tool</source>
        <translation>žádný nástroj</translation>
    </message>
    <message>
        <source>not a grooving tool (%1)</source>
        <translation>není zapichovací nůž (%1)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::HeightsBox</name>
    <message>
        <source>Clearance Z</source>
        <translation>Z přejezdu</translation>
    </message>
    <message>
        <source>Safe Z</source>
        <translation>Bezpečné Z</translation>
    </message>
    <message>
        <source>Start Z</source>
        <translation>Počáteční Z</translation>
    </message>
    <message>
        <source>Final Z</source>
        <translation>Koncové Z</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>auto</translation>
    </message>
    <message>
        <source>Derived from the model and the stock; uncheck to set it</source>
        <translation>Odvozeno z modelu a polotovaru; zrušte zaškrtnutí pro ruční zadání</translation>
    </message>
</context>
<context>
    <name>camwb::gui::HelixPanel</name>
    <message>
        <source>Pitch per turn</source>
        <translation>Stoupání na otáčku</translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation>Sousledné frézování</translation>
    </message>
    <message>
        <source>Depths from each hole</source>
        <translation>Hloubky podle každé díry</translation>
    </message>
    <message>
        <source>Each hole from its top to its bottom; unchecked: the start and final Z of the heights</source>
        <translation>Každá díra od svého vrcholu ke dnu; nezaškrtnuto: počáteční a koncové Z z výšek</translation>
    </message>
    <message>
        <source>Breakthrough</source>
        <translation>Přesah průvrtu</translation>
    </message>
    <message>
        <source>Radial stock</source>
        <translation>Radiální přídavek</translation>
    </message>
    <message>
        <source>Finishing circle</source>
        <translation>Dokončovací kruh</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
</context>
<context>
    <name>camwb::gui::InspectorPanel</name>
    <message>
        <source>Automatic</source>
        <translation>Automaticky</translation>
    </message>
    <message>
        <source>SINUMERIK</source>
        <translation>SINUMERIK</translation>
    </message>
    <message>
        <source>Heidenhain Klartext</source>
        <translation>Heidenhain Klartext</translation>
    </message>
    <message>
        <source>ISO (LinuxCNC, Fanuc)</source>
        <translation>ISO (LinuxCNC, Fanuc)</translation>
    </message>
    <message>
        <source>NC program (traced)</source>
        <translation>NC program (trasovaný)</translation>
    </message>
    <message>
        <source>Operations&apos; toolpath</source>
        <translation>Dráhy nástroje operací</translation>
    </message>
    <message>
        <source>Dialect</source>
        <translation>Dialekt</translation>
    </message>
    <message>
        <source>3D shows</source>
        <translation>3D zobrazuje</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Nástroje</translation>
    </message>
    <message>
        <source>T%1</source>
        <translation>T%1</translation>
    </message>
    <message>
        <source>before the first tool</source>
        <translation>před prvním nástrojem</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>The machine the program is traced on: its limits are checked, and five-axis NC (M128, TRAORI, B and C words) is read through its kinematics</source>
        <translation>Stroj, na kterém se program trasuje: kontrolují se jeho meze a pětiosé NC (M128, TRAORI, slova B a C) se čte přes jeho kinematiku</translation>
    </message>
    <message>
        <source>None: no limits checked, three axes</source>
        <translation>Žádný: bez kontroly mezí, tři osy</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::JobSetupPanel</name>
    <message>
        <source>Job setup</source>
        <translation>Nastavení úlohy</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Model</translation>
    </message>
    <message>
        <source>Stock</source>
        <translation>Polotovar</translation>
    </message>
    <message>
        <source>Work coordinate system</source>
        <translation>Souřadný systém obrobku</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>Post</source>
        <translation>Postprocesor</translation>
    </message>
    <message>
        <source>Output</source>
        <translation>Výstup</translation>
    </message>
    <message>
        <source>No model</source>
        <translation>Žádný model</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importovat…</translation>
    </message>
    <message>
        <source>Import a STEP, IGES, BREP or STL model as the job&apos;s model</source>
        <translation>Importovat model STEP, IGES, BREP nebo STL jako model úlohy</translation>
    </message>
    <message>
        <source>Box</source>
        <translation>Kvádr</translation>
    </message>
    <message>
        <source>Cylinder (along Z)</source>
        <translation>Válec (v ose Z)</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Tvar</translation>
    </message>
    <message>
        <source>Model bounds + offsets</source>
        <translation>Obálka modelu + přídavky</translation>
    </message>
    <message>
        <source>Explicit size</source>
        <translation>Zadané rozměry</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Rozměry</translation>
    </message>
    <message>
        <source>Typed (model coordinates)</source>
        <translation>Zadaný (souřadnice modelu)</translation>
    </message>
    <message>
        <source>Stock: top front left corner</source>
        <translation>Polotovar: horní přední levý roh</translation>
    </message>
    <message>
        <source>Stock: bottom front left corner</source>
        <translation>Polotovar: spodní přední levý roh</translation>
    </message>
    <message>
        <source>Stock: top centre</source>
        <translation>Polotovar: střed horní plochy</translation>
    </message>
    <message>
        <source>Stock: centre</source>
        <translation>Polotovar: střed</translation>
    </message>
    <message>
        <source>Stock: bottom centre</source>
        <translation>Polotovar: střed spodní plochy</translation>
    </message>
    <message>
        <source>Z0 on the face picked in the view</source>
        <translation>Z0 na ploše vybrané v pohledu</translation>
    </message>
    <message>
        <source>Program zero: a point of the stock (it follows the stock), or typed</source>
        <translation>Nulový bod programu: bod polotovaru (posouvá se s polotovarem), nebo zadaný ručně</translation>
    </message>
    <message>
        <source>Origin at</source>
        <translation>Počátek v</translation>
    </message>
    <message>
        <source>Origin</source>
        <translation>Počátek</translation>
    </message>
    <message>
        <source>Work offset</source>
        <translation>Nulový bod obrobku</translation>
    </message>
    <message>
        <source>The post&apos;s default machine</source>
        <translation>Výchozí stroj postprocesoru</translation>
    </message>
    <message>
        <source>the job file&apos;s name</source>
        <translation>název souboru úlohy</translation>
    </message>
    <message>
        <source>The NC program&apos;s file name; the post&apos;s extension is added when it has none</source>
        <translation>Název souboru NC programu; přípona postprocesoru se přidá, pokud žádnou nemá</translation>
    </message>
    <message>
        <source>the job file&apos;s folder</source>
        <translation>složka souboru úlohy</translation>
    </message>
    <message>
        <source>Relative to the job file&apos;s folder, or absolute</source>
        <translation>Relativně ke složce souboru úlohy, nebo absolutně</translation>
    </message>
    <message>
        <source>File name</source>
        <translation>Název souboru</translation>
    </message>
    <message>
        <source>Folder</source>
        <translation>Složka</translation>
    </message>
    <message>
        <source>Z0 on face %1</source>
        <translation>Z0 na ploše %1</translation>
    </message>
    <message>
        <source>Pick a flat horizontal face of the model in the 3D view.</source>
        <translation>Vyberte ve 3D pohledu rovinnou vodorovnou plochu modelu.</translation>
    </message>
    <message>
        <source>%1 = %2 (%3)</source>
        <translation>%1 = %2 (%3)</translation>
    </message>
    <message>
        <source>Dropped with the change of post:
%1</source>
        <translation>Vypuštěno při změně postprocesoru:
%1</translation>
    </message>
    <message>
        <source>%1 does not post for the machine %2.</source>
        <translation>%1 nepostprocesuje pro stroj %2.</translation>
    </message>
    <message>
        <source>The stock does not fit the machine&apos;s travels:
%1</source>
        <translation>Polotovar se nevejde do pojezdů stroje:
%1</translation>
    </message>
    <message>
        <source>Below min</source>
        <translation>Pod minimem</translation>
    </message>
    <message>
        <source>Above max</source>
        <translation>Nad maximem</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>On the model vertex picked in the view</source>
        <translation>Ve vrcholu modelu vybraném v pohledu</translation>
    </message>
    <message>
        <source>Origin on the vertex at (%1, %2, %3) of the model</source>
        <translation>Počátek ve vrcholu modelu (%1, %2, %3)</translation>
    </message>
    <message>
        <source>Click the model near a vertex in the 3D view.</source>
        <translation>Klepněte ve 3D pohledu na model poblíž vrcholu.</translation>
    </message>
    <message>
        <source>Blank from file…</source>
        <translation>Tvarový polotovar ze souboru…</translation>
    </message>
    <message>
        <source>A cast or forged blank: a STEP, IGES, BREP or STL file in the model&apos;s coordinates</source>
        <translation>Odlitek nebo výkovek: soubor STEP, IGES, BREP nebo STL v souřadnicích modelu</translation>
    </message>
    <message>
        <source>Choose…</source>
        <translation>Vybrat…</translation>
    </message>
    <message>
        <source>Choose the blank&apos;s file</source>
        <translation>Vyberte soubor tvarového polotovaru</translation>
    </message>
    <message>
        <source>Blank</source>
        <translation>Tvarový polotovar</translation>
    </message>
    <message>
        <source>Blank from file</source>
        <translation>Tvarový polotovar ze souboru</translation>
    </message>
    <message>
        <source>Models (*.step *.stp *.iges *.igs *.brep *.brp *.stl)</source>
        <translation>Modely (*.step *.stp *.iges *.igs *.brep *.brp *.stl)</translation>
    </message>
    <message>
        <source>The blank cannot be used: %1</source>
        <translation>Tvarový polotovar nelze použít: %1</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Ø%1 × %2 %5, from Z %3 to %4</source>
        <translation>Ø%1 × %2 %5, od Z %3 do %4</translation>
    </message>
    <message>
        <source>Blank in a box of %1 × %2 × %3 %7, from (%4, %5, %6)</source>
        <translation>Tvarový polotovar v kvádru %1 × %2 × %3 %7, od (%4, %5, %6)</translation>
    </message>
    <message>
        <source>%1 × %2 × %3 %7, from (%4, %5, %6)</source>
        <translation>%1 × %2 × %3 %7, od (%4, %5, %6)</translation>
    </message>
    <message>
        <source>The stock cannot be used: %1</source>
        <translation>Polotovar nelze použít: %1</translation>
    </message>
</context>
<context>
    <name>camwb::gui::JobToolsModel</name>
    <message>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Flutes</source>
        <translation>Břity</translation>
    </message>
    <message>
        <source>Spindle (rpm)</source>
        <translation>Vřeteno (ot/min)</translation>
    </message>
    <message>
        <source>Cutting data for</source>
        <translation>Řezná data pro</translation>
    </message>
    <message>
        <source>D (%1)</source>
        <translation>D (%1)</translation>
    </message>
    <message>
        <source>Feed (%1/min)</source>
        <translation>Posuv (%1/min)</translation>
    </message>
    <message>
        <source>Plunge (%1/min)</source>
        <translation>Zanoření (%1/min)</translation>
    </message>
    <message>
        <source>Ramp (%1/min)</source>
        <translation>Rampa (%1/min)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::JobTree</name>
    <message>
        <source>Item</source>
        <translation>Položka</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Hodnota</translation>
    </message>
    <message>
        <source>Job</source>
        <translation>Úloha</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Model</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(žádný)</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Plochy</translation>
    </message>
    <message>
        <source>Stock</source>
        <translation>Polotovar</translation>
    </message>
    <message>
        <source>Min</source>
        <translation>Min</translation>
    </message>
    <message>
        <source>Max</source>
        <translation>Max</translation>
    </message>
    <message>
        <source>Work offset</source>
        <translation>Nulový bod obrobku</translation>
    </message>
    <message>
        <source>Post</source>
        <translation>Postprocesor</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Nástroje</translation>
    </message>
    <message>
        <source>Operations</source>
        <translation>Operace</translation>
    </message>
    <message>
        <source>faces %1</source>
        <translation>plochy %1</translation>
    </message>
    <message>
        <source>edges %1</source>
        <translation>hrany %1</translation>
    </message>
    <message>
        <source>holes %1</source>
        <translation>díry %1</translation>
    </message>
    <message>
        <source>no geometry</source>
        <translation>bez geometrie</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Chyba</translation>
    </message>
    <message>
        <source>not loaded: %1</source>
        <translation>nenačteno: %1</translation>
    </message>
    <message>
        <source>(not posted yet)</source>
        <translation>(zatím nepostprocesováno)</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>post default: %1</source>
        <translation>výchozí dle postprocesoru: %1</translation>
    </message>
    <message>
        <source>, holder %1</source>
        <translation>, držák %1</translation>
    </message>
    <message>
        <source>(disabled)</source>
        <translation>(vypnuto)</translation>
    </message>
    <message>
        <source>Posted; uncheck to leave it out of the program</source>
        <translation>Postprocesuje se; zrušením zaškrtnutí se vynechá z programu</translation>
    </message>
    <message>
        <source>Disabled: not computed and not posted</source>
        <translation>Vypnuto: nepočítá se ani nepostprocesuje</translation>
    </message>
    <message>
        <source>Disa&amp;ble Operation</source>
        <translation>Vypnou&amp;t operaci</translation>
    </message>
    <message>
        <source>D&amp;uplicate Operation</source>
        <translation>&amp;Duplikovat operaci</translation>
    </message>
    <message>
        <source>&amp;Rename Operation</source>
        <translation>Přej&amp;menovat operaci</translation>
    </message>
    <message>
        <source>Move Operation &amp;Up</source>
        <translation>Posunout operaci &amp;nahoru</translation>
    </message>
    <message>
        <source>Move Operation Do&amp;wn</source>
        <translation>Posunout operaci do&amp;lů</translation>
    </message>
    <message>
        <source>&amp;Enable Operation</source>
        <translation>Zapnou&amp;t operaci</translation>
    </message>
    <message>
        <source>the grooves&apos; shaft (revolved)</source>
        <translation>hřídel zápichů (rotační)</translation>
    </message>
    <message>
        <source>box %1 × %2 × %3 %4</source>
        <translation>kvádr %1 × %2 × %3 %4</translation>
    </message>
    <message>
        <source>%1, Ø%2</source>
        <translation>%1, Ø%2</translation>
    </message>
    <message>
        <source>depth %1, bottom width %2</source>
        <translation>hloubka %1, šířka dna %2</translation>
    </message>
    <message>
        <source>blank %1 in a %2</source>
        <translation>tvarový polotovar %1, %2</translation>
    </message>
    <message>
        <source>cylinder Ø%1 × %2 %3</source>
        <translation>válec Ø%1 × %2 %3</translation>
    </message>
    <message>
        <source>T%1 %2, Ø%3</source>
        <translation>T%1 %2, Ø%3</translation>
    </message>
    <message>
        <source>S%1, F%2 %3/min</source>
        <translation>S%1, F%2 %3/min</translation>
    </message>
</context>
<context>
    <name>camwb::gui::MainWindow</name>
    <message>
        <source>Job</source>
        <translation>Úloha</translation>
    </message>
    <message>
        <source>NC program</source>
        <translation>NC program</translation>
    </message>
    <message>
        <source>Report</source>
        <translation>Protokol</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Hlavní</translation>
    </message>
    <message>
        <source>3D view unavailable: %1</source>
        <translation>3D pohled není k dispozici: %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Soubor</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>Úpr&amp;avy</translation>
    </message>
    <message>
        <source>&amp;Operation</source>
        <translation>&amp;Operace</translation>
    </message>
    <message>
        <source>&amp;Job</source>
        <translation>Ú&amp;loha</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Zobrazit</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Nápo&amp;věda</translation>
    </message>
    <message>
        <source>&amp;Open Job…</source>
        <translation>&amp;Otevřít úlohu…</translation>
    </message>
    <message>
        <source>Open job</source>
        <translation>Otevřít úlohu</translation>
    </message>
    <message>
        <source>CAM Workbench jobs (*.camwb)</source>
        <translation>Úlohy CAM Workbench (*.camwb)</translation>
    </message>
    <message>
        <source>&amp;Save Job</source>
        <translation>&amp;Uložit úlohu</translation>
    </message>
    <message>
        <source>Save Job &amp;As…</source>
        <translation>Uložit úlohu &amp;jako…</translation>
    </message>
    <message>
        <source>Save job</source>
        <translation>Uložit úlohu</translation>
    </message>
    <message>
        <source>&amp;Import Model…</source>
        <translation>&amp;Importovat model…</translation>
    </message>
    <message>
        <source>Import model</source>
        <translation>Importovat model</translation>
    </message>
    <message>
        <source>Models (*.step *.stp *.iges *.igs *.brep *.brp *.stl);;All files (*)</source>
        <translation>Modely (*.step *.stp *.iges *.igs *.brep *.brp *.stl);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Konec</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Zpět</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>Z&amp;novu</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>&amp;Zpět: %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>Z&amp;novu: %1</translation>
    </message>
    <message>
        <source>New &amp;Profile</source>
        <translation>Nový &amp;profil</translation>
    </message>
    <message>
        <source>&amp;Edit Operation…</source>
        <translation>&amp;Upravit operaci…</translation>
    </message>
    <message>
        <source>&amp;Delete Operation</source>
        <translation>&amp;Smazat operaci</translation>
    </message>
    <message>
        <source>&amp;Post</source>
        <translation>&amp;Postprocesovat</translation>
    </message>
    <message>
        <source>&amp;Save NC Program…</source>
        <translation>&amp;Uložit NC program…</translation>
    </message>
    <message>
        <source>Save NC program</source>
        <translation>Uložit NC program</translation>
    </message>
    <message>
        <source>NC programs (*.%1);;All files (*)</source>
        <translation>NC programy (*.%1);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>&amp;Isometric</source>
        <translation>&amp;Izometrie</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>&amp;Shora</translation>
    </message>
    <message>
        <source>&amp;Front</source>
        <translation>&amp;Zepředu</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>Z&amp;prava</translation>
    </message>
    <message>
        <source>Fit &amp;All</source>
        <translation>Zobrazit &amp;vše</translation>
    </message>
    <message>
        <source>&amp;About CAM Workbench</source>
        <translation>&amp;O aplikaci CAM Workbench</translation>
    </message>
    <message>
        <source>About CAM Workbench</source>
        <translation>O aplikaci CAM Workbench</translation>
    </message>
    <message>
        <source>CAM Workbench %1
CAM and post-processor workbench.</source>
        <translation>CAM Workbench %1
Pracoviště pro CAM a postprocesory.</translation>
    </message>
    <message>
        <source>Working…</source>
        <translation>Pracuje se…</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Připraveno</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Bez názvu</translation>
    </message>
    <message>
        <source>%1%2 — CAM Workbench</source>
        <translation>%1%2 — CAM Workbench</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Neuložené změny</translation>
    </message>
    <message>
        <source>NC inspector</source>
        <translation>NC inspektor</translation>
    </message>
    <message>
        <source>Opened NC program %1</source>
        <translation>Otevřen NC program %1</translation>
    </message>
    <message>
        <source>&amp;NC</source>
        <translation>&amp;NC</translation>
    </message>
    <message>
        <source>&amp;Open NC Program…</source>
        <translation>&amp;Otevřít NC program…</translation>
    </message>
    <message>
        <source>Open NC program</source>
        <translation>Otevřít NC program</translation>
    </message>
    <message>
        <source>&amp;Trace NC Program</source>
        <translation>&amp;Trasovat NC program</translation>
    </message>
    <message>
        <source>posted</source>
        <translation>postprocesováno</translation>
    </message>
    <message>
        <source>Tracing the NC program…</source>
        <translation>Trasuje se NC program…</translation>
    </message>
    <message>
        <source>Segment from the called program %1; the editor shows its call.</source>
        <translation>Úsek z volaného programu %1; editor ukazuje jeho volání.</translation>
    </message>
    <message>
        <source>Task</source>
        <translation>Úkol</translation>
    </message>
    <message>
        <source>New &amp;Contour…</source>
        <translation>Nová &amp;kontura…</translation>
    </message>
    <message>
        <source>New P&amp;ocket…</source>
        <translation>Nová ka&amp;psa…</translation>
    </message>
    <message>
        <source>New &amp;Helix…</source>
        <translation>Nová šroubovi&amp;ce…</translation>
    </message>
    <message>
        <source>New &amp;Drilling…</source>
        <translation>Nové &amp;vrtání…</translation>
    </message>
    <message>
        <source>Task: %1</source>
        <translation>Úkol: %1</translation>
    </message>
    <message>
        <source>Select an operation in the job tree first.</source>
        <translation>Nejprve vyberte operaci ve stromu úlohy.</translation>
    </message>
    <message>
        <source>The job&apos;s model is not loaded: %1</source>
        <translation>Model úlohy není načten: %1</translation>
    </message>
    <message>
        <source>New operation</source>
        <translation>Nová operace</translation>
    </message>
    <message>
        <source>Unapplied changes</source>
        <translation>Nepoužité změny</translation>
    </message>
    <message>
        <source>The task panel of &quot;%1&quot; has changes that are not applied.</source>
        <translation>Panel úkolu „%1“ má změny, které nebyly použity.</translation>
    </message>
    <message>
        <source>Apply</source>
        <translation>Použít</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodit</translation>
    </message>
    <message>
        <source>The job has changes that are not saved. Save them?</source>
        <translation>Úloha má neuložené změny. Uložit je?</translation>
    </message>
    <message>
        <source>No NC program: %1</source>
        <translation>Žádný NC program: %1</translation>
    </message>
    <message>
        <source>Out of date — the last post failed; this is the previous program and it cannot be saved:
%1</source>
        <translation>Zastaralé — poslední postprocesování selhalo; toto je předchozí program a nelze jej uložit:
%1</translation>
    </message>
    <message numerus="yes">
        <source> (and %n more, see the job tree)</source>
        <translation>
            <numerusform> (a %n další, viz strom úlohy)</numerusform>
            <numerusform> (a %n další, viz strom úlohy)</numerusform>
            <numerusform> (a %n dalších, viz strom úlohy)</numerusform>
        </translation>
    </message>
    <message>
        <source>Opening the job %1 replaces them with its program.</source>
        <translation>Otevření úlohy %1 je nahradí jejím programem.</translation>
    </message>
    <message>
        <source>Opening %1 replaces them.</source>
        <translation>Otevření %1 je nahradí.</translation>
    </message>
    <message>
        <source>Opening another job replaces them with its program.</source>
        <translation>Otevření jiné úlohy je nahradí jejím programem.</translation>
    </message>
    <message>
        <source>Posting the job replaces them with its program.</source>
        <translation>Postprocesování úlohy je nahradí jejím programem.</translation>
    </message>
    <message>
        <source>&amp;Save NC File</source>
        <translation>&amp;Uložit NC soubor</translation>
    </message>
    <message>
        <source>The job&apos;s program, posted again, replaces them.</source>
        <translation>Program úlohy, znovu postprocesovaný, je nahradí.</translation>
    </message>
    <message>
        <source>The editor keeps the unsaved edits of %1; the job&apos;s new program is not shown (Post shows it).</source>
        <translation>Editor ponechává neuložené úpravy %1; nový program úlohy se nezobrazí (zobrazí jej Postprocesovat).</translation>
    </message>
    <message>
        <source>NC program — %1</source>
        <translation>NC program — %1</translation>
    </message>
    <message>
        <source> (out of date)</source>
        <translation> (zastaralý)</translation>
    </message>
    <message>
        <source>Closing the window loses them.</source>
        <translation>Zavřením okna se ztratí.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Stroj</translation>
    </message>
    <message>
        <source>The NC program is traced without a machine</source>
        <translation>NC program se trasuje bez stroje</translation>
    </message>
    <message>
        <source>The NC program is traced on the machine %1</source>
        <translation>NC program se trasuje na stroji %1</translation>
    </message>
    <message>
        <source>New &amp;Swarf (five-axis)…</source>
        <translation>Nové obrábění &amp;bokem (5osé)…</translation>
    </message>
    <message>
        <source>Simulator</source>
        <translation>Simulátor</translation>
    </message>
    <message>
        <source>Task: Job setup</source>
        <translation>Úkol: Nastavení úlohy</translation>
    </message>
    <message>
        <source>The job setup panel has changes that are not applied.</source>
        <translation>Panel nastavení úlohy obsahuje změny, které nebyly použity.</translation>
    </message>
    <message>
        <source>New 3D P&amp;ocket…</source>
        <translation>Nová 3D kaps&amp;a…</translation>
    </message>
    <message>
        <source>New &amp;Waterline…</source>
        <translation>Nové dokončení po v&amp;rstevnicích…</translation>
    </message>
    <message>
        <source>New P&amp;arallel…</source>
        <translation>Nové para&amp;lelní dokončení…</translation>
    </message>
    <message>
        <source>New &amp;Groove Roughing…</source>
        <translation>Nové &amp;hrubování zápichu…</translation>
    </message>
    <message>
        <source>&amp;XZ (lathe)</source>
        <translation>&amp;XZ (soustruh)</translation>
    </message>
    <message>
        <source>Opened CL file %1</source>
        <translation>Otevřen soubor CL %1</translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;CL files (*.apt *.aptsource *.cl *.cls *.dump *.trace);;All files (*)</source>
        <translation>NC programy (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;Soubory CL (*.apt *.aptsource *.cl *.cls *.dump *.trace);;Všechny soubory (*)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::MeasuredImportDialog</name>
    <message>
        <source>none</source>
        <translation>žádný</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>µm</source>
        <translation>µm</translation>
    </message>
    <message>
        <source>inch</source>
        <translation>palce</translation>
    </message>
    <message>
        <source>degrees</source>
        <translation>stupně</translation>
    </message>
    <message>
        <source>radians</source>
        <translation>radiány</translation>
    </message>
    <message>
        <source>Import a Measured Trace</source>
        <translation>Import naměřeného záznamu</translation>
    </message>
    <message>
        <source>%1: which column holds each channel (the first column is 1). The nominal and actual positions are carried through the simulation&apos;s machine onto the workpiece.</source>
        <translation>%1: ve kterém sloupci je který kanál (první sloupec je 1). Požadované a skutečné polohy se přepočtou kinematikou stroje simulace na obrobek.</translation>
    </message>
    <message>
        <source>Nominal</source>
        <translation>Požadovaná</translation>
    </message>
    <message>
        <source>Actual</source>
        <translation>Skutečná</translation>
    </message>
    <message>
        <source>Deviation</source>
        <translation>Odchylka</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>1st rotary (A/B)</source>
        <translation>1. rotační (A/B)</translation>
    </message>
    <message>
        <source>2nd rotary (C)</source>
        <translation>2. rotační (C)</translation>
    </message>
    <message>
        <source>Time column</source>
        <translation>Sloupec času</translation>
    </message>
    <message>
        <source>Header lines</source>
        <translation>Řádky záhlaví</translation>
    </message>
    <message>
        <source>Time in</source>
        <translation>Čas v</translation>
    </message>
    <message>
        <source>Linear axes in</source>
        <translation>Lineární osy v</translation>
    </message>
    <message>
        <source>Rotary axes in</source>
        <translation>Rotační osy v</translation>
    </message>
    <message>
        <source>Automatic (; then tab then ,)</source>
        <translation>Automaticky (; potom tabulátor, potom ,)</translation>
    </message>
    <message>
        <source>Semicolon (decimal comma allowed)</source>
        <translation>Středník (desetinná čárka povolena)</translation>
    </message>
    <message>
        <source>Tab (decimal comma allowed)</source>
        <translation>Tabulátor (desetinná čárka povolena)</translation>
    </message>
    <message>
        <source>Comma</source>
        <translation>Čárka</translation>
    </message>
    <message>
        <source>Separator</source>
        <translation>Oddělovač</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Subtracted from the recorded Z: the tool length where the control recorded the spindle face, 0 where it recorded the tool tip</source>
        <translation>Odečte se od zaznamenaného Z: délka nástroje, pokud systém zaznamenal čelo vřetena, 0, pokud zaznamenal špičku nástroje</translation>
    </message>
    <message>
        <source>Z above the tool tip</source>
        <translation>Z nad špičkou nástroje</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importovat</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ModalStatePanel</name>
    <message>
        <source>unknown (no move yet)</source>
        <translation>neznámý (zatím bez pohybu)</translation>
    </message>
    <message>
        <source>%1 m/min constant surface speed, %2</source>
        <translation>%1 m/min konstantní řezná rychlost, %2</translation>
    </message>
    <message>
        <source>%1 rpm %2</source>
        <translation>%1 ot/min %2</translation>
    </message>
    <message>
        <source>through tool</source>
        <translation>středem nástroje</translation>
    </message>
    <message>
        <source>Block</source>
        <translation>Blok</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Pohyb</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Nástroj</translation>
    </message>
    <message>
        <source>Feed</source>
        <translation>Posuv</translation>
    </message>
    <message>
        <source>Spindle</source>
        <translation>Vřeteno</translation>
    </message>
    <message>
        <source>Coolant</source>
        <translation>Chlazení</translation>
    </message>
    <message>
        <source>Work offset</source>
        <translation>Nulový bod</translation>
    </message>
    <message>
        <source>Compensation</source>
        <translation>Korekce</translation>
    </message>
    <message>
        <source>Plane</source>
        <translation>Rovina</translation>
    </message>
    <message>
        <source>Units</source>
        <translation>Jednotky</translation>
    </message>
    <message>
        <source>Abs/inc</source>
        <translation>Abs/přír</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Před</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Po</translation>
    </message>
    <message>
        <source>No NC program traced yet.</source>
        <translation>Zatím nebyl trasován žádný NC program.</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>řádek %1</translation>
    </message>
    <message>
        <source>, runs %1 times (first run shown)</source>
        <translation>, provede se %1krát (zobrazeno první provedení)</translation>
    </message>
    <message>
        <source>no motion</source>
        <translation>bez pohybu</translation>
    </message>
    <message>
        <source>none called yet</source>
        <translation>zatím žádný nevolán</translation>
    </message>
    <message>
        <source>%1 (G%2)</source>
        <translation>%1 (G%2)</translation>
    </message>
    <message>
        <source>none in the trace (control default)</source>
        <translation>není v trase (výchozí řízení)</translation>
    </message>
    <message>
        <source>%1, from the last arc</source>
        <translation>%1, z posledního oblouku</translation>
    </message>
    <message>
        <source>no arc yet (not in the trace)</source>
        <translation>zatím žádný oblouk (není v trase)</translation>
    </message>
    <message>
        <source>mm (inch programs converted)</source>
        <translation>mm (palcové programy převedeny)</translation>
    </message>
    <message>
        <source>not in the trace; positions absolute</source>
        <translation>není v trase; polohy absolutně</translation>
    </message>
    <message numerus="yes">
        <source>%n diagnostic(s) in this program.</source>
        <translation>
            <numerusform>%n hlášení v tomto programu.</numerusform>
            <numerusform>%n hlášení v tomto programu.</numerusform>
            <numerusform>%n hlášení v tomto programu.</numerusform>
        </translation>
    </message>
    <message>
        <source>off</source>
        <translation>vypnuto</translation>
    </message>
    <message>
        <source>left of the contour</source>
        <translation>vlevo od kontury</translation>
    </message>
    <message>
        <source>right of the contour</source>
        <translation>vpravo od kontury</translation>
    </message>
    <message>
        <source>%1 (absolute)</source>
        <translation>%1 (absolutně)</translation>
    </message>
    <message>
        <source>%1 (incremental)</source>
        <translation>%1 (přírůstkově)</translation>
    </message>
    <message>
        <source>%1 (absolute and incremental words)</source>
        <translation>%1 (absolutní i přírůstková slova)</translation>
    </message>
    <message>
        <source>%1 (absolute or incremental per coordinate)</source>
        <translation>%1 (absolutně nebo přírůstkově podle souřadnice)</translation>
    </message>
    <message>
        <source>%1 (inch; positions shown in mm)</source>
        <translation>%1 (palce; polohy zobrazeny v mm)</translation>
    </message>
    <message>
        <source>%1 (mm)</source>
        <translation>%1 (mm)</translation>
    </message>
    <message>
        <source>none programmed (control default)</source>
        <translation>neprogramováno (výchozí řízení)</translation>
    </message>
    <message>
        <source>%1 (five-axis move)</source>
        <translation>%1 (5osý pohyb)</translation>
    </message>
    <message>
        <source>%1 (3-axis move)</source>
        <translation>%1 (3osý pohyb)</translation>
    </message>
    <message>
        <source>none known (trace with a five-axis machine)</source>
        <translation>neznámé (trasujte s 5osým strojem)</translation>
    </message>
    <message>
        <source>Tool axis</source>
        <translation>Osa nástroje</translation>
    </message>
    <message>
        <source>Rotary axes</source>
        <translation>Rotační osy</translation>
    </message>
    <message>
        <source>%1 mm/min</source>
        <translation>%1 mm/min</translation>
    </message>
    <message>
        <source>%1 mm/rev</source>
        <translation>%1 mm/ot</translation>
    </message>
    <message>
        <source>%1 1/min</source>
        <translation>%1 1/min</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>stojí</translation>
    </message>
    <message>
        <source>CW</source>
        <translation>vpravo</translation>
    </message>
    <message>
        <source>CCW</source>
        <translation>vlevo</translation>
    </message>
    <message>
        <source>flood</source>
        <translation>kapalina</translation>
    </message>
    <message>
        <source>mist</source>
        <translation>mlha</translation>
    </message>
    <message>
        <source>mm (an inch CL file converted)</source>
        <translation>mm (palcový soubor CL převeden)</translation>
    </message>
    <message>
        <source>absolute (CL positions)</source>
        <translation>absolutně (polohy CL)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcDocument</name>
    <message>
        <source>Save NC program</source>
        <translation>Uložit NC program</translation>
    </message>
    <message>
        <source>NC programs (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;All files (*)</source>
        <translation>NC programy (*.mpf *.spf *.nc *.ngc *.tap *.h *.iso *.cnc *.txt);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Saved NC program %1</source>
        <translation>Uložen NC program %1</translation>
    </message>
    <message>
        <source>The NC program</source>
        <translation>NC program</translation>
    </message>
    <message>
        <source>Unsaved NC edits</source>
        <translation>Neuložené úpravy NC</translation>
    </message>
    <message>
        <source>%1 has edits that are not saved. %2

Save them first?</source>
        <translation>%1 má neuložené úpravy. %2

Nejprve je uložit?</translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcEditor</name>
    <message>
        <source>column %1: </source>
        <translation>sloupec %1: </translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcFindBar</name>
    <message>
        <source>Find:</source>
        <translation>Najít:</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>Předchozí</translation>
    </message>
    <message>
        <source>Find the previous match (Shift+Enter)</source>
        <translation>Najít předchozí výskyt (Shift+Enter)</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>Další</translation>
    </message>
    <message>
        <source>Find the next match (Enter)</source>
        <translation>Najít další výskyt (Enter)</translation>
    </message>
    <message>
        <source>Match case</source>
        <translation>Rozlišovat velikost písmen</translation>
    </message>
    <message>
        <source>Whole words</source>
        <translation>Celá slova</translation>
    </message>
    <message>
        <source>Close the find bar (Escape)</source>
        <translation>Zavřít panel hledání (Escape)</translation>
    </message>
    <message>
        <source>Not found</source>
        <translation>Nenalezeno</translation>
    </message>
</context>
<context>
    <name>camwb::gui::NcInspector</name>
    <message>
        <source>Tracing the NC program…</source>
        <translation>Trasuje se NC program…</translation>
    </message>
    <message>
        <source>NC program</source>
        <translation>NC program</translation>
    </message>
    <message>
        <source>%1: %2 more diagnostics not listed</source>
        <translation>%1: dalších %2 hlášení neuvedeno</translation>
    </message>
    <message>
        <source> (guessed)</source>
        <translation> (odhadnuto)</translation>
    </message>
    <message>
        <source>, %1 five-axis moves</source>
        <translation>, pětiosé pohyby: %1</translation>
    </message>
    <message>
        <source>Traced %1 as %2%3: %4 blocks, %5 lines, %6 arcs, %7 rapids, %8 cycles%9 in %10 ms</source>
        <translation>Trasováno %1 jako %2%3: bloky %4, přímky %5, oblouky %6, rychloposuvy %7, cykly %8%9 za %10 ms</translation>
    </message>
    <message>
        <source>a CL file (%1)</source>
        <translation>soubor CL (%1)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::OperationPanel</name>
    <message>
        <source>Contour</source>
        <translation>Kontura</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Kapsa</translation>
    </message>
    <message>
        <source>Helix</source>
        <translation>Šroubovice</translation>
    </message>
    <message>
        <source>Drilling</source>
        <translation>Vrtání</translation>
    </message>
    <message>
        <source>new operation</source>
        <translation>nová operace</translation>
    </message>
    <message>
        <source>operation %1</source>
        <translation>operace %1</translation>
    </message>
    <message>
        <source>Preview pending…</source>
        <translation>Náhled čeká…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Zrušit</translation>
    </message>
    <message>
        <source>Stop computing the preview (the operation stays as edited)</source>
        <translation>Zastavit výpočet náhledu (operace zůstane, jak byla upravena)</translation>
    </message>
    <message>
        <source>Preview</source>
        <translation>Náhled</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>T%1 %2 (Ø%3 mm)</source>
        <translation>T%1 %2 (Ø%3 mm)</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Nástroj</translation>
    </message>
    <message>
        <source>Operation</source>
        <translation>Operace</translation>
    </message>
    <message>
        <source>Geometry</source>
        <translation>Geometrie</translation>
    </message>
    <message>
        <source>Parameters</source>
        <translation>Parametry</translation>
    </message>
    <message>
        <source>Heights</source>
        <translation>Výšky</translation>
    </message>
    <message>
        <source>Preview cancelled; change a parameter to compute it again.</source>
        <translation>Náhled zrušen; pro nový výpočet změňte parametr.</translation>
    </message>
    <message>
        <source>Computing…</source>
        <translation>Počítá se…</translation>
    </message>
    <message>
        <source>%1 lines, %2 arcs, %3 helices, %4 cycles</source>
        <translation>přímky %1, oblouky %2, šroubovice %3, cykly %4</translation>
    </message>
    <message>
        <source> (%1 rapids; %2 ms)</source>
        <translation> (rychloposuvy %1; %2 ms)</translation>
    </message>
    <message>
        <source>Warning: %1</source>
        <translation>Varování: %1</translation>
    </message>
    <message>
        <source>Not applied: this operation cannot be made. Change it, or Cancel.
%1</source>
        <translation>Nepoužito: tuto operaci nelze vytvořit. Změňte ji, nebo zvolte Zrušit.
%1</translation>
    </message>
    <message>
        <source>Working plane (3+2)</source>
        <translation>Pracovní rovina (3+2)</translation>
    </message>
    <message>
        <source>Swarf (simultaneous five-axis)</source>
        <translation>Obrábění bokem (simultánní 5osé)</translation>
    </message>
    <message>
        <source>3D Pocket</source>
        <translation>3D kapsa</translation>
    </message>
    <message>
        <source>Waterline</source>
        <translation>Dokončení po vrstevnicích</translation>
    </message>
    <message>
        <source>Parallel</source>
        <translation>Paralelní dokončení</translation>
    </message>
    <message>
        <source>Groove roughing (turning)</source>
        <translation>Hrubování zápichu (soustružení)</translation>
    </message>
    <message>
        <source>T%1 %2 (width %3 mm)</source>
        <translation>T%1 %2 (šířka %3 mm)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ParallelPanel</name>
    <message>
        <source>Stepover</source>
        <translation>Boční krok</translation>
    </message>
    <message>
        <source>Angle</source>
        <translation>Úhel</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Of the lines to the X axis</source>
        <translation>Řádků k ose X</translation>
    </message>
    <message>
        <source>Up to slope</source>
        <translation>Do sklonu</translation>
    </message>
    <message>
        <source>Lines only where the model is at most this steep; waterline takes the steeper walls</source>
        <translation>Řádky jen tam, kde model není strmější; strmější stěny dokončí vrstevnice</translation>
    </message>
    <message>
        <source>Stock to leave</source>
        <translation>Přídavek</translation>
    </message>
    <message>
        <source>Zig-zag</source>
        <translation>Cik-cak</translation>
    </message>
    <message>
        <source>Cut both ways; unticked, every line the same way</source>
        <translation>Řezat oběma směry; nezaškrtnuto: každý řádek stejným směrem</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
</context>
<context>
    <name>camwb::gui::Pocket3dPanel</name>
    <message>
        <source>Pattern</source>
        <translation>Strategie</translation>
    </message>
    <message>
        <source>Offset (spiral inward)</source>
        <translation>Ekvidistanta (spirála dovnitř)</translation>
    </message>
    <message>
        <source>Zig-zag</source>
        <translation>Cik-cak</translation>
    </message>
    <message>
        <source>Zig-zag angle</source>
        <translation>Úhel cik-cak</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Stepover</source>
        <translation>Boční krok</translation>
    </message>
    <message>
        <source> % of Ø</source>
        <translation> % z Ø</translation>
    </message>
    <message>
        <source>Stepover (mm, 0 = use %)</source>
        <translation>Boční krok (mm, 0 = v %)</translation>
    </message>
    <message>
        <source>Step-down</source>
        <translation>Přísuv Z</translation>
    </message>
    <message>
        <source>Levels also land on every flat floor of the model</source>
        <translation>Hladiny padnou i na každé rovné dno modelu</translation>
    </message>
    <message>
        <source>Side stock</source>
        <translation>Boční přídavek</translation>
    </message>
    <message>
        <source>Left on walls, measured across the tool axis</source>
        <translation>Zůstane na stěnách, měřeno kolmo k ose nástroje</translation>
    </message>
    <message>
        <source>Bottom stock</source>
        <translation>Přídavek na dně</translation>
    </message>
    <message>
        <source>Left on floors and shallow surfaces, measured along the tool axis</source>
        <translation>Zůstane na dnech a mírných plochách, měřeno podél osy nástroje</translation>
    </message>
    <message>
        <source>Rest machining</source>
        <translation>Obrábění zbytkového materiálu</translation>
    </message>
    <message>
        <source>Cut only the material the operations before this one left</source>
        <translation>Obrábět jen materiál, který zanechaly předchozí operace</translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation>Sousledné frézování</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Zanoření</translation>
    </message>
    <message>
        <source>Helix</source>
        <translation>Šroubovice</translation>
    </message>
    <message>
        <source>Ramp</source>
        <translation>Rampa</translation>
    </message>
    <message>
        <source>Plunge</source>
        <translation>Kolmo</translation>
    </message>
    <message>
        <source>Helix diameter (0 = 90 % Ø)</source>
        <translation>Ø šroubovice (0 = 90 % Ø)</translation>
    </message>
    <message>
        <source>Helix pitch</source>
        <translation>Stoupání šroubovice</translation>
    </message>
    <message>
        <source>Ramp angle</source>
        <translation>Úhel rampy</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
</context>
<context>
    <name>camwb::gui::PocketPanel</name>
    <message>
        <source>Pattern</source>
        <translation>Strategie</translation>
    </message>
    <message>
        <source>Offset (spiral inward)</source>
        <translation>Ekvidistanta (spirála dovnitř)</translation>
    </message>
    <message>
        <source>Zig-zag</source>
        <translation>Cik-cak</translation>
    </message>
    <message>
        <source>Zig-zag angle</source>
        <translation>Úhel cik-cak</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Stepover</source>
        <translation>Boční krok</translation>
    </message>
    <message>
        <source> % of Ø</source>
        <translation> % z Ø</translation>
    </message>
    <message>
        <source>Stepover (mm, 0 = use %)</source>
        <translation>Boční krok (mm, 0 = v %)</translation>
    </message>
    <message>
        <source>Step-down (0 = one level)</source>
        <translation>Přísuv Z (0 = najednou)</translation>
    </message>
    <message>
        <source>Wall stock</source>
        <translation>Přídavek na stěnách</translation>
    </message>
    <message>
        <source>Floor stock</source>
        <translation>Přídavek na dně</translation>
    </message>
    <message>
        <source>Finish walls</source>
        <translation>Dokončit stěny</translation>
    </message>
    <message>
        <source>Finish floor</source>
        <translation>Dokončit dno</translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation>Sousledné frézování</translation>
    </message>
    <message>
        <source>Entry</source>
        <translation>Zanoření</translation>
    </message>
    <message>
        <source>Helix</source>
        <translation>Šroubovice</translation>
    </message>
    <message>
        <source>Ramp</source>
        <translation>Rampa</translation>
    </message>
    <message>
        <source>Plunge</source>
        <translation>Kolmo</translation>
    </message>
    <message>
        <source>Helix diameter (0 = 90 % Ø)</source>
        <translation>Ø šroubovice (0 = 90 % Ø)</translation>
    </message>
    <message>
        <source>Helix pitch</source>
        <translation>Stoupání šroubovice</translation>
    </message>
    <message>
        <source>Ramp angle</source>
        <translation>Úhel rampy</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
</context>
<context>
    <name>camwb::gui::PostPropertiesForm</name>
    <message>
        <source>This post has no properties.</source>
        <translation>Tento postprocesor nemá žádné vlastnosti.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Defaults for operations&lt;/b&gt; (an operation may set its own)</source>
        <translation>&lt;b&gt;Výchozí hodnoty pro operace&lt;/b&gt; (operace může nastavit vlastní)</translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation>(prázdné)</translation>
    </message>
    <message>
        <source>(default: %1)</source>
        <translation>(výchozí: %1)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Obnovit</translation>
    </message>
    <message>
        <source>Reset %1 to its default, %2</source>
        <translation>Vrátit %1 na výchozí hodnotu, %2</translation>
    </message>
</context>
<context>
    <name>camwb::gui::PostSettingsPanel</name>
    <message>
        <source>Post and Properties</source>
        <translation>Postprocesor a vlastnosti</translation>
    </message>
    <message>
        <source>Machine:</source>
        <translation>Stroj:</translation>
    </message>
    <message>
        <source>&amp;Post:</source>
        <translation>&amp;Postprocesor:</translation>
    </message>
    <message>
        <source>Show &amp;all posts, not only those for the job&apos;s machine</source>
        <translation>Zobrazit &amp;všechny postprocesory, nejen ty pro stroj úlohy</translation>
    </message>
    <message>
        <source>The job&apos;s post %1 cannot be loaded: choose another.</source>
        <translation>Postprocesor úlohy %1 nelze načíst: zvolte jiný.</translation>
    </message>
    <message>
        <source> (not for this machine)</source>
        <translation> (ne pro tento stroj)</translation>
    </message>
    <message>
        <source>%1 = %2 is dropped: %3</source>
        <translation>%1 = %2 je vypuštěno: %3</translation>
    </message>
    <message>
        <source>none (the post&apos;s machine limits are not checked)</source>
        <translation>žádný (limity stroje postprocesoru se nekontrolují)</translation>
    </message>
    <message>
        <source> (control %1)</source>
        <translation> (řídicí systém %1)</translation>
    </message>
    <message>
        <source> (the post&apos;s default machine)</source>
        <translation> (výchozí stroj postprocesoru)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::PreferencesDialog</name>
    <message>
        <source>The language changes when CAM Workbench is started again.</source>
        <translation>Jazyk se změní po novém spuštění CAM Workbench.</translation>
    </message>
    <message>
        <source>Preferences</source>
        <translation>Předvolby</translation>
    </message>
    <message>
        <source>Millimetres (mm)</source>
        <translation>Milimetry (mm)</translation>
    </message>
    <message>
        <source>Inches (in)</source>
        <translation>Palce (in)</translation>
    </message>
    <message>
        <source>How lengths are shown. Jobs and NC programs keep their own units.</source>
        <translation>Jak se zobrazují délky. Úlohy a NC programy si ponechávají vlastní jednotky.</translation>
    </message>
    <message>
        <source>The library in the user&apos;s data folder</source>
        <translation>Knihovna ve složce uživatelských dat</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Systém</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>How often unsaved changes are written to a side file for recovery after a crash.</source>
        <translation>Jak často se neuložené změny zapisují do vedlejšího souboru pro obnovu po pádu.</translation>
    </message>
    <message>
        <source>&amp;Display units:</source>
        <translation>&amp;Jednotky zobrazení:</translation>
    </message>
    <message>
        <source>Default &amp;post:</source>
        <translation>Výchozí &amp;postprocesor:</translation>
    </message>
    <message>
        <source>Default &amp;machine:</source>
        <translation>Výchozí &amp;stroj:</translation>
    </message>
    <message>
        <source>&amp;Tool library:</source>
        <translation>&amp;Knihovna nástrojů:</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>Ja&amp;zyk:</translation>
    </message>
    <message>
        <source>&amp;Autosave every:</source>
        <translation>&amp;Automaticky ukládat každých:</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>Pro&amp;cházet…</translation>
    </message>
    <message>
        <source>Tool library</source>
        <translation>Knihovna nástrojů</translation>
    </message>
    <message>
        <source>Tool libraries (*.json);;All files (*)</source>
        <translation>Knihovny nástrojů (*.json);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>(the built-in default)</source>
        <translation>(vestavěná výchozí)</translation>
    </message>
    <message>
        <source>(the post&apos;s default machine)</source>
        <translation>(výchozí stroj postprocesoru)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ProgramInfoDialog</name>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Program Information</source>
        <translation>Informace o programu</translation>
    </message>
    <message>
        <source> mm/min</source>
        <translation> mm/min</translation>
    </message>
    <message>
        <source>Rapid rate the time estimate assumes (the machine&apos;s, when it says)</source>
        <translation>Rychloposuv, se kterým počítá odhad času (strojový, pokud jej stroj uvádí)</translation>
    </message>
    <message>
        <source>Rapid rate:</source>
        <translation>Rychloposuv:</translation>
    </message>
    <message>
        <source>Interpreting the program…</source>
        <translation>Interpretuje se program…</translation>
    </message>
    <message>
        <source>%1 blocks interpreted, %2 diagnostic(s).</source>
        <translation>Interpretováno bloků: %1, hlášení: %2.</translation>
    </message>
    <message>
        <source>Extents (mm)</source>
        <translation>Rozměry (mm)</translation>
    </message>
    <message>
        <source>Cutting</source>
        <translation>Řezání</translation>
    </message>
    <message>
        <source>Rapid</source>
        <translation>Rychloposuv</translation>
    </message>
    <message>
        <source>All</source>
        <translation>Vše</translation>
    </message>
    <message>
        <source>Motion</source>
        <translation>Pohyb</translation>
    </message>
    <message>
        <source>Feed length</source>
        <translation>Délka posuvu</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Rapid length</source>
        <translation>Délka rychloposuvu</translation>
    </message>
    <message>
        <source>Feed time</source>
        <translation>Čas posuvu</translation>
    </message>
    <message>
        <source>Rapid time (at %1 mm/min)</source>
        <translation>Čas rychloposuvu (při %1 mm/min)</translation>
    </message>
    <message>
        <source>Dwell time</source>
        <translation>Čas prodlev</translation>
    </message>
    <message>
        <source>Rapids / feed moves / arcs</source>
        <translation>Rychloposuvy / posuvy / oblouky</translation>
    </message>
    <message>
        <source>Cycle holes</source>
        <translation>Díry cyklů</translation>
    </message>
    <message>
        <source>Tool changes</source>
        <translation>Výměny nástroje</translation>
    </message>
    <message>
        <source>Feed moves without a usable feed (not timed)</source>
        <translation>Pohyby bez použitelného posuvu (nečasováno)</translation>
    </message>
    <message>
        <source>Per tool</source>
        <translation>Podle nástroje</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Nástroj</translation>
    </message>
    <message>
        <source>Feed length (mm)</source>
        <translation>Délka posuvu (mm)</translation>
    </message>
    <message>
        <source>Rapid length (mm)</source>
        <translation>Délka rychloposuvu (mm)</translation>
    </message>
    <message>
        <source>Z min (cutting)</source>
        <translation>Z min (řezání)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(žádný)</translation>
    </message>
    <message>
        <source>Diagnostics</source>
        <translation>Hlášení</translation>
    </message>
    <message>
        <source>… and %1 more</source>
        <translation>… a dalších %1</translation>
    </message>
    <message>
        <source>%1 blocks interpreted; %2 error(s), %3 other diagnostic(s): the figures cover what could be interpreted; %4 move(s) of blocks with an error are left out.</source>
        <translation>Interpretováno bloků: %1; chyby: %2, jiná hlášení: %3: údaje pokrývají, co šlo interpretovat; vynechané pohyby bloků s chybou: %4.</translation>
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
    <name>camwb::gui::RecentFiles</name>
    <message>
        <source>%1 (missing)</source>
        <translation>%1 (chybí)</translation>
    </message>
    <message>
        <source>No recent files</source>
        <translation>Žádné nedávné soubory</translation>
    </message>
    <message>
        <source>&amp;Clear Recent Files</source>
        <translation>&amp;Vymazat nedávné soubory</translation>
    </message>
</context>
<context>
    <name>camwb::gui::RenumberDialog</name>
    <message>
        <source>Renumber Blocks</source>
        <translation>Přečíslovat bloky</translation>
    </message>
    <message>
        <source>&amp;Start at:</source>
        <translation>&amp;Začít od:</translation>
    </message>
    <message>
        <source>S&amp;tep:</source>
        <translation>Kr&amp;ok:</translation>
    </message>
    <message>
        <source>Number &amp;comment-only lines</source>
        <translation>Číslovat řádky jen s &amp;komentářem</translation>
    </message>
    <message>
        <source>Number &amp;empty lines</source>
        <translation>Číslovat &amp;prázdné řádky</translation>
    </message>
    <message>
        <source>&amp;Keep existing numbers, number only blocks without one</source>
        <translation>Po&amp;nechat stávající čísla, číslovat jen bloky bez čísla</translation>
    </message>
    <message>
        <source>Renumber &amp;only blocks that have a number</source>
        <translation>Přečíslovat &amp;jen bloky, které mají číslo</translation>
    </message>
    <message>
        <source>Heidenhain Klartext blocks are always numbered 0, 1, 2, … on every line (continuation lines excepted).</source>
        <translation>Bloky Heidenhain Klartext se vždy číslují 0, 1, 2, … na každém řádku (kromě pokračovacích řádků).</translation>
    </message>
    <message>
        <source>Jump targets (GOTOF N100, GOTO 100) follow their blocks. Labels, comments and strings are left as they are.</source>
        <translation>Cíle skoků (GOTOF N100, GOTO 100) následují své bloky. Návěští, komentáře a řetězce zůstávají beze změny.</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ReportView</name>
    <message>
        <source>warning: </source>
        <translation>varování: </translation>
    </message>
    <message>
        <source>error: </source>
        <translation>chyba: </translation>
    </message>
</context>
<context>
    <name>camwb::gui::Session</name>
    <message>
        <source>&amp;New Job</source>
        <translation>&amp;Nová úloha</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>Otevřít ne&amp;dávné</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Předvolby…</translation>
    </message>
    <message>
        <source>An untitled job has changes that were autosaved on %1 and never saved: CAM Workbench may have stopped. Recover them?</source>
        <translation>Nepojmenovaná úloha má změny, které byly automaticky uloženy %1 a nikdy nebyly uloženy: CAM Workbench se mohl neočekávaně ukončit. Obnovit je?</translation>
    </message>
    <message>
        <source>The job %1 has changes that were autosaved on %2 and not saved: CAM Workbench may have stopped. Recover them?</source>
        <translation>Úloha %1 má změny, které byly automaticky uloženy %2 a nebyly uloženy: CAM Workbench se mohl neočekávaně ukončit. Obnovit je?</translation>
    </message>
    <message>
        <source>Recover unsaved changes</source>
        <translation>Obnovit neuložené změny</translation>
    </message>
    <message>
        <source>Recover</source>
        <translation>Obnovit</translation>
    </message>
    <message>
        <source>Discard</source>
        <translation>Zahodit</translation>
    </message>
    <message>
        <source>Discarded the autosaved changes %1</source>
        <translation>Zahozeny automaticky uložené změny %1</translation>
    </message>
    <message>
        <source>The autosaved changes cannot be read: %1
The file is kept as %2.</source>
        <translation>Automaticky uložené změny nelze načíst: %1
Soubor je ponechán jako %2.</translation>
    </message>
    <message>
        <source>
The job %1 is opened as it was saved.</source>
        <translation>
Úloha %1 je otevřena tak, jak byla uložena.</translation>
    </message>
    <message>
        <source>Recover Autosaved Changes</source>
        <translation>Obnovit automaticky uložené změny</translation>
    </message>
    <message>
        <source>Recovered the autosaved changes %1</source>
        <translation>Obnoveny automaticky uložené změny %1</translation>
    </message>
    <message>
        <source>A new job replaces them with its program.</source>
        <translation>Nová úloha je nahradí svým programem.</translation>
    </message>
    <message>
        <source>New job</source>
        <translation>Nová úloha</translation>
    </message>
    <message>
        <source>Open Recent</source>
        <translation>Otevřít nedávné</translation>
    </message>
    <message>
        <source>%1 does not exist any more; it is removed from the recent files.</source>
        <translation>%1 již neexistuje; je odstraněn ze seznamu nedávných souborů.</translation>
    </message>
    <message>
        <source>The language changes when CAM Workbench is started again.</source>
        <translation>Jazyk se změní po novém spuštění CAM Workbench.</translation>
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
    <message>
        <source>The measured trace was recorded for the program as it was before the change: import a trace of this program, or clear it.</source>
        <translation>Naměřený záznam patří k programu před změnou: importujte záznam tohoto programu, nebo ho odstraňte.</translation>
    </message>
    <message>
        <source>Import a Measured Trace</source>
        <translation>Import naměřeného záznamu</translation>
    </message>
    <message>
        <source>Simulate the program first: a measured trace is carried onto the workpiece through the simulation&apos;s machine and compared with its path.</source>
        <translation>Nejprve program simulujte: naměřený záznam se přepočte kinematikou stroje simulace na obrobek a porovná s její dráhou.</translation>
    </message>
    <message>
        <source>Measured traces (*.csv *.txt);;All files (*)</source>
        <translation>Naměřené záznamy (*.csv *.txt);;Všechny soubory (*)</translation>
    </message>
    <message>
        <source>Measured %1: %2 samples, %3 s; actual to nominal up to %4 mm</source>
        <translation>Naměřeno %1: %2 vzorků, %3 s; skutečná od požadované až %4 mm</translation>
    </message>
    <message>
        <source>, to the program up to %1 mm</source>
        <translation>, od programu až %1 mm</translation>
    </message>
</context>
<context>
    <name>camwb::gui::SimPlayer</name>
    <message>
        <source>Simulation cancelled</source>
        <translation>Simulace zrušena</translation>
    </message>
    <message>
        <source>Simulated %1: cycle time %2 s, errors: %3, warnings: %4</source>
        <translation>Simulováno %1: čas cyklu %2 s, chyby: %3, varování: %4</translation>
    </message>
    <message>
        <source>Simulate the program first: a measured trace is carried onto the workpiece through the simulation&apos;s machine and compared with its path.</source>
        <translation>Nejprve program simulujte: naměřený záznam se přepočte kinematikou stroje simulace na obrobek a porovná s její dráhou.</translation>
    </message>
    <message>
        <source>Measured trace %1: %2 samples</source>
        <translation>Naměřený záznam %1: %2 vzorků</translation>
    </message>
</context>
<context>
    <name>camwb::gui::SwarfPanel</name>
    <message>
        <source>Climb milling</source>
        <translation>Sousledné frézování</translation>
    </message>
    <message>
        <source>Axial offset</source>
        <translation>Axiální posunutí</translation>
    </message>
    <message>
        <source>The tool tip above (+) or below (−) the face&apos;s bottom edge, along the tool axis</source>
        <translation>Špička nástroje nad (+) nebo pod (−) spodní hranou plochy, ve směru osy nástroje</translation>
    </message>
    <message>
        <source>Radial stock</source>
        <translation>Radiální přídavek</translation>
    </message>
    <message>
        <source>Radial passes</source>
        <translation>Radiální průchody</translation>
    </message>
    <message>
        <source>Radial stepover</source>
        <translation>Radiální krok</translation>
    </message>
    <message>
        <source>Chord tolerance</source>
        <translation>Tolerance tětivy</translation>
    </message>
    <message>
        <source>Angle tolerance</source>
        <translation>Úhlová tolerance</translation>
    </message>
    <message>
        <source>The most the tool axis turns from one point to the next</source>
        <translation>Největší pootočení osy nástroje mezi dvěma body</translation>
    </message>
    <message>
        <source>Gouge tolerance</source>
        <translation>Tolerance podříznutí</translation>
    </message>
    <message>
        <source>How deep the tool may enter the model before the operation fails</source>
        <translation>Jak hluboko smí nástroj vniknout do modelu, než operace selže</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ToolLibraryDialog</name>
    <message>
        <source>Tool Library</source>
        <translation>Knihovna nástrojů</translation>
    </message>
    <message>
        <source>Tool library</source>
        <translation>Knihovna nástrojů</translation>
    </message>
    <message>
        <source>The tool library cannot be read, so it is shown empty and will not be saved over (the file is left as it is; use Export to save tools elsewhere):
%1</source>
        <translation>Knihovnu nástrojů nelze načíst, proto se zobrazí prázdná a nebude přepsána (soubor zůstane beze změny; k uložení nástrojů jinam použijte Exportovat):
%1</translation>
    </message>
    <message>
        <source>The default tool library cannot be read:
%1</source>
        <translation>Výchozí knihovnu nástrojů nelze načíst:
%1</translation>
    </message>
    <message>
        <source>Filter tools by name, kind or holder</source>
        <translation>Filtrovat nástroje podle názvu, druhu nebo držáku</translation>
    </message>
    <message>
        <source>Cutting data of the current library tool</source>
        <translation>Řezná data aktuálního nástroje knihovny</translation>
    </message>
    <message>
        <source>Add Material</source>
        <translation>Přidat materiál</translation>
    </message>
    <message>
        <source>Remove Material</source>
        <translation>Odebrat materiál</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Knihovna</translation>
    </message>
    <message>
        <source>Job Tools</source>
        <translation>Nástroje úlohy</translation>
    </message>
    <message>
        <source>&amp;Add</source>
        <translation>&amp;Přidat</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Duplikovat</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Smazat</translation>
    </message>
    <message>
        <source>&amp;Import…</source>
        <translation>&amp;Importovat…</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportovat…</translation>
    </message>
    <message>
        <source>Add to &amp;Job</source>
        <translation>Přidat do ú&amp;lohy</translation>
    </message>
    <message>
        <source>Copy the selected tools into the job (a taken number gets the next free one)</source>
        <translation>Zkopírovat vybrané nástroje do úlohy (obsazené číslo dostane další volné)</translation>
    </message>
    <message>
        <source>Job stock material:</source>
        <translation>Materiál polotovaru úlohy:</translation>
    </message>
    <message>
        <source>The material the job&apos;s tools&apos; feeds and speeds are computed for</source>
        <translation>Materiál, pro který se počítají posuvy a otáčky nástrojů úlohy</translation>
    </message>
    <message>
        <source>&amp;Compute Feeds and Speeds</source>
        <translation>&amp;Vypočítat řezné podmínky</translation>
    </message>
    <message>
        <source>Set the job&apos;s tools&apos; spindle speed and feeds from their cutting data</source>
        <translation>Nastavit otáčky vřetena a posuvy nástrojů úlohy podle jejich řezných dat</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Uložit</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Zavřít</translation>
    </message>
    <message>
        <source>Library: %1</source>
        <translation>Knihovna: %1</translation>
    </message>
    <message>
        <source>Import tools</source>
        <translation>Importovat nástroje</translation>
    </message>
    <message>
        <source>Tool libraries (*.fctl *.tools *.json);;FreeCAD ToolBit libraries (*.fctl);;Fusion 360 tool libraries (*.tools *.json)</source>
        <translation>Knihovny nástrojů (*.fctl *.tools *.json);;Knihovny ToolBit FreeCAD (*.fctl);;Knihovny nástrojů Fusion 360 (*.tools *.json)</translation>
    </message>
    <message>
        <source>Export tools</source>
        <translation>Exportovat nástroje</translation>
    </message>
    <message>
        <source>CAM Workbench tool libraries (*.json)</source>
        <translation>Knihovny nástrojů CAM Workbench (*.json)</translation>
    </message>
    <message>
        <source>New end mill D6</source>
        <translation>Nová stopková fréza D6</translation>
    </message>
    <message>
        <source> (copy)</source>
        <translation> (kopie)</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n tool(s) from %1.</source>
        <translation>
            <numerusform>Importován %n nástroj z %1.</numerusform>
            <numerusform>Importovány %n nástroje z %1.</numerusform>
            <numerusform>Importováno %n nástrojů z %1.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Exported %n tool(s) to %1.</source>
        <translation>
            <numerusform>Exportován %n nástroj do %1.</numerusform>
            <numerusform>Exportovány %n nástroje do %1.</numerusform>
            <numerusform>Exportováno %n nástrojů do %1.</numerusform>
        </translation>
    </message>
    <message>
        <source>Select the tools to add to the job.</source>
        <translation>Vyberte nástroje, které se mají přidat do úlohy.</translation>
    </message>
    <message numerus="yes">
        <source>Added %n tool(s) to the job.</source>
        <translation>
            <numerusform>Do úlohy přidán %n nástroj.</numerusform>
            <numerusform>Do úlohy přidány %n nástroje.</numerusform>
            <numerusform>Do úlohy přidáno %n nástrojů.</numerusform>
        </translation>
    </message>
    <message>
        <source>Save tool library</source>
        <translation>Uložit knihovnu nástrojů</translation>
    </message>
    <message>
        <source>Saved %1.</source>
        <translation>Uloženo %1.</translation>
    </message>
    <message>
        <source>Save the changes to the tool library?</source>
        <translation>Uložit změny v knihovně nástrojů?</translation>
    </message>
</context>
<context>
    <name>camwb::gui::ToolTableModel</name>
    <message>
        <source>T</source>
        <translation>T</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Název</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Druh</translation>
    </message>
    <message>
        <source>Flutes</source>
        <translation>Břity</translation>
    </message>
    <message>
        <source>Point (°)</source>
        <translation>Úhel špičky (°)</translation>
    </message>
    <message>
        <source>Holder</source>
        <translation>Držák</translation>
    </message>
    <message>
        <source>D (%1)</source>
        <translation>D (%1)</translation>
    </message>
    <message>
        <source>R (%1)</source>
        <translation>R (%1)</translation>
    </message>
    <message>
        <source>Flute (%1)</source>
        <translation>Délka břitu (%1)</translation>
    </message>
    <message>
        <source>Length (%1)</source>
        <translation>Délka (%1)</translation>
    </message>
</context>
<context>
    <name>camwb::gui::View3D</name>
    <message>
        <source>3D view unavailable: %1</source>
        <translation>3D pohled není k dispozici: %1</translation>
    </message>
    <message>
        <source>OpenGL is disabled (CAMWB_NO_OPENGL=1)</source>
        <translation>OpenGL je vypnuto (CAMWB_NO_OPENGL=1)</translation>
    </message>
    <message>
        <source>no GUI application</source>
        <translation>žádná GUI aplikace</translation>
    </message>
    <message>
        <source>the &apos;%1&apos; platform has no OpenGL display</source>
        <translation>platforma &apos;%1&apos; nemá displej OpenGL</translation>
    </message>
    <message>
        <source>cannot create an offscreen OpenGL surface</source>
        <translation>nelze vytvořit offscreen plochu OpenGL</translation>
    </message>
    <message>
        <source>cannot create an OpenGL 3.2 core context</source>
        <translation>nelze vytvořit kontext OpenGL 3.2 core</translation>
    </message>
    <message>
        <source>cannot make an OpenGL 3.2 core context current</source>
        <translation>nelze aktivovat kontext OpenGL 3.2 core</translation>
    </message>
    <message>
        <source>only OpenGL ES is available</source>
        <translation>k dispozici je jen OpenGL ES</translation>
    </message>
    <message>
        <source>OpenGL %1.%2 found, 3.2 needed</source>
        <translation>nalezeno OpenGL %1.%2, potřeba 3.2</translation>
    </message>
</context>
<context>
    <name>camwb::gui::WaterlinePanel</name>
    <message>
        <source>Scallop height</source>
        <translation>Výška hřebínku</translation>
    </message>
    <message>
        <source>The highest ridge left between two contours; sets the step-down</source>
        <translation>Nejvyšší hřebínek mezi dvěma vrstevnicemi; určuje přísuv Z</translation>
    </message>
    <message>
        <source>Maximum step-down</source>
        <translation>Největší přísuv Z</translation>
    </message>
    <message>
        <source>Steeper than</source>
        <translation>Strmější než</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>Contours only where the model is steeper than this; parallel finishing takes the rest</source>
        <translation>Vrstevnice jen tam, kde je model strmější; zbytek dokončí paralelní řádky</translation>
    </message>
    <message>
        <source>Stock to leave</source>
        <translation>Přídavek</translation>
    </message>
    <message>
        <source>Climb milling</source>
        <translation>Sousledné frézování</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerance</translation>
    </message>
</context>
<context>
    <name>camwb::gui::Workbench</name>
    <message>
        <source>Opened job %1</source>
        <translation>Otevřena úloha %1</translation>
    </message>
    <message>
        <source>Saved job %1</source>
        <translation>Uložena úloha %1</translation>
    </message>
    <message>
        <source>There is no NC program to save; post the job first.</source>
        <translation>Není žádný NC program k uložení; nejprve úlohu postprocesujte.</translation>
    </message>
    <message>
        <source>Wrote NC program %1</source>
        <translation>Zapsán NC program %1</translation>
    </message>
    <message>
        <source>Busy; import the model again when the current work has finished.</source>
        <translation>Zaneprázdněno; importujte model znovu, až současná práce skončí.</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>Importuje se %1</translation>
    </message>
    <message>
        <source>Imported %1 (%2 faces)</source>
        <translation>Importováno %1 (ploch: %2)</translation>
    </message>
    <message>
        <source>Loading model</source>
        <translation>Načítá se model</translation>
    </message>
    <message>
        <source>Toolpath: %1 lines, %2 arcs, %3 rapids</source>
        <translation>Dráha nástroje: přímky %1, oblouky %2, rychloposuvy %3</translation>
    </message>
    <message>
        <source>Posted %1 lines with %2</source>
        <translation>Postprocesováno řádků: %1 pomocí %2</translation>
    </message>
    <message>
        <source>Open job</source>
        <translation>Otevřít úlohu</translation>
    </message>
    <message>
        <source>Save job</source>
        <translation>Uložit úlohu</translation>
    </message>
    <message>
        <source>Save NC program</source>
        <translation>Uložit NC program</translation>
    </message>
    <message>
        <source>The NC program is out of date and was not saved: %1
Fix the job and post it again.</source>
        <translation>NC program je zastaralý a nebyl uložen: %1
Opravte úlohu a znovu ji postprocesujte.</translation>
    </message>
    <message>
        <source>Import model</source>
        <translation>Importovat model</translation>
    </message>
    <message numerus="yes">
        <source>The previous model is not loaded, so the references of the %n operation(s) cannot be checked against %1. Keep them with their face, edge and hole numbers (check each operation), or delete them?</source>
        <translation>
            <numerusform>Předchozí model není načten, takže odkazy %n operace nelze ověřit vůči %1. Ponechat je s čísly ploch, hran a děr (zkontrolujte každou operaci), nebo je smazat?</numerusform>
            <numerusform>Předchozí model není načten, takže odkazy %n operací nelze ověřit vůči %1. Ponechat je s čísly ploch, hran a děr (zkontrolujte každou operaci), nebo je smazat?</numerusform>
            <numerusform>Předchozí model není načten, takže odkazy %n operací nelze ověřit vůči %1. Ponechat je s čísly ploch, hran a děr (zkontrolujte každou operaci), nebo je smazat?</numerusform>
        </translation>
    </message>
    <message>
        <source>Keep the operations</source>
        <translation>Ponechat operace</translation>
    </message>
    <message>
        <source>Delete the operations</source>
        <translation>Smazat operace</translation>
    </message>
    <message>
        <source>These references of the operations are not in %1:
%2

Keep the operations without them (they are marked until you choose new geometry in their task panels), or delete the operations that lost references?</source>
        <translation>Tyto odkazy operací nejsou v %1:
%2

Ponechat operace bez nich (zůstanou označené, dokud v jejich panelech úkolu nezvolíte novou geometrii), nebo smazat operace, které odkazy ztratily?</translation>
    </message>
    <message>
        <source>Delete those operations</source>
        <translation>Smazat tyto operace</translation>
    </message>
    <message>
        <source>Import of %1 cancelled; the job is unchanged.</source>
        <translation>Import %1 zrušen; úloha je beze změny.</translation>
    </message>
    <message numerus="yes">
        <source>Deleted %n operation(s) that lost references.</source>
        <translation>
            <numerusform>Smazána %n operace, která ztratila odkazy.</numerusform>
            <numerusform>Smazány %n operace, které ztratily odkazy.</numerusform>
            <numerusform>Smazáno %n operací, které ztratily odkazy.</numerusform>
        </translation>
    </message>
    <message>
        <source>Kept the operations; these references are not in the new model:
%1</source>
        <translation>Operace ponechány; tyto odkazy nejsou v novém modelu:
%1</translation>
    </message>
    <message>
        <source>Post</source>
        <translation>Postprocesor</translation>
    </message>
    <message>
        <source>unresolved: the model is not loaded (%1)</source>
        <translation>nevyřešeno: model není načten (%1)</translation>
    </message>
    <message>
        <source>The job is being computed; save the NC program when the post has finished.</source>
        <translation>Úloha se počítá; NC program uložte, až postprocesování skončí.</translation>
    </message>
    <message>
        <source>The post %1 cannot be used: %2</source>
        <translation>Postprocesor %1 nelze použít: %2</translation>
    </message>
    <message>
        <source>Post %1 does not keep property %2 = %3: %4</source>
        <translation>Postprocesor %1 neponechá vlastnost %2 = %3: %4</translation>
    </message>
    <message>
        <source>Operation %1 loses its property %2 = %3: %4</source>
        <translation>Operace %1 ztrácí vlastnost %2 = %3: %4</translation>
    </message>
    <message>
        <source>Post %1 does not drive machine %2: the job now uses the post&apos;s default machine%3</source>
        <translation>Postprocesor %1 neovládá stroj %2: úloha nyní používá výchozí stroj postprocesoru%3</translation>
    </message>
    <message>
        <source>Compute feeds and speeds</source>
        <translation>Vypočítat řezné podmínky</translation>
    </message>
    <message>
        <source>%1 × %2 × %3 mm from (%4, %5, %6)</source>
        <translation>%1 × %2 × %3 mm od (%4, %5, %6)</translation>
    </message>
    <message>
        <source>The stock stored in the job (%1) is not what its %2 gives now (%3): the file changed since the job was saved. The job now uses the new stock.</source>
        <translation>Polotovar uložený v úloze (%1) neodpovídá tomu, co nyní dává %2 (%3): soubor se od uložení úlohy změnil. Úloha nyní používá nový polotovar.</translation>
    </message>
    <message>
        <source>blank file</source>
        <translation>soubor tvarového polotovaru</translation>
    </message>
    <message>
        <source>model</source>
        <translation>model</translation>
    </message>
</context>
<context>
    <name>camwb::gui::WorkingPlaneBox</name>
    <message>
        <source>Flat (tool along Z)</source>
        <translation>Vodorovná (osa Z)</translation>
    </message>
    <message>
        <source>Along a face&apos;s normal</source>
        <translation>Podle normály plochy</translation>
    </message>
    <message>
        <source>Spatial angles</source>
        <translation>Prostorové úhly</translation>
    </message>
    <message>
        <source>3+2: the plane the operation is computed in; the post tilts the machine to it. Flat drilling turns to each hole&apos;s own axis.</source>
        <translation>3+2: rovina, ve které se operace počítá; postprocesor do ní natočí stroj. Při volbě Vodorovná se vrtání natáčí do vlastní osy každé díry.</translation>
    </message>
    <message>
        <source>Plane</source>
        <translation>Rovina</translation>
    </message>
    <message>
        <source>The planar face whose outward normal the tool follows</source>
        <translation>Rovinná plocha, jejíž vnější normálu nástroj sleduje</translation>
    </message>
    <message>
        <source>Face</source>
        <translation>Plocha</translation>
    </message>
    <message>
        <source>A (about X)</source>
        <translation>A (kolem X)</translation>
    </message>
    <message>
        <source>B (about Y)</source>
        <translation>B (kolem Y)</translation>
    </message>
    <message>
        <source>C (about Z)</source>
        <translation>C (kolem Z)</translation>
    </message>
</context>
</TS>
