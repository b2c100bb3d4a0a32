// Style ids of the NC editor's Sinumerik highlighter, public so that tests and the inspector can
// ask what a position is (NcEditor::styleAt) without seeing QScintilla.
#pragma once

namespace camwb::gui {

enum class NcStyle : int {
    Default = 0,
    Comment,        // ; to end of line
    BlockNumber,    // N10, :10 at the start of a block
    GWord,          // G0, G17, G641
    MWord,          // M3, M30
    AxisWord,       // X Y Z A B C I J K with their value (X10.5, Z=-2)
    FeedSpeedTool,  // F S T D with their value
    Keyword,        // cycles (CYCLE81, POCKET3), control flow, frames, DEF, MCALL, MSG, AC/IC, CR/AR ...
    Number,
    String,     // "..."
    Parameter,  // R parameters (R1) and system variables ($P_...)
    Count
};

}  // namespace camwb::gui
