<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="cs_CZ">
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
        <source>profile, face %1, Z%2, T%3</source>
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
        <source>Discard the unsaved changes of this job?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>camwb::gui::ProfileDialog</name>
    <message>
        <source>Profile: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 at Z %2 (%3 mm²)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boundary of face</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Climb</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Conventional</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Final depth (Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safe height (Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clearance height (Z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heights must satisfy clearance ≥ safe height &gt; final depth.</source>
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
    <name>camwb::gui::SinumerikLexer</name>
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
        <source>A profile needs a solid model (STEP, IGES or BREP); import one first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Face %1 is not a planar face of the model.</source>
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
</context>
</TS>
