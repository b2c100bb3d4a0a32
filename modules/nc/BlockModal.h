// The modal state a block ran with, in the words of the program's own dialect, for viewers such
// as the NC inspector: what the CL records cannot carry (distance mode, units, plane and work
// offset as programmed). An interpreter reports it after each executed block when
// InterpretOptions::onBlock is set; nothing is built otherwise.
#pragma once

#include "toolpath/ClRecords.h"

#include <functional>
#include <string>

namespace camwb::nc {

struct BlockModal {
    int file = 0;  // SourceRef::file of the block
    int line = 0;

    enum class Distance { Absolute, Incremental, Mixed, PerWord };
    Distance distance = Distance::Absolute;  // PerWord: no coordinate in the block (Heidenhain X / IX)
    const char* distanceWord = "";           // "G90", "G91"; Heidenhain "X", "IX", "X IX", "X / IX"

    bool inch = false;
    const char* unitsWord = "";  // "G71", "G710", "G70", "G700", "G21", "G20", "MM", "INCH"

    int plane = 17;              // 17 XY, 18 ZX, 19 YZ
    const char* planeWord = "";  // "G17" ..., Heidenhain "TOOL CALL Z" ...

    toolpath::CutterCompSide compensation = toolpath::CutterCompSide::Off;
    const char* compensationWord = "";  // "G40" "G41" "G42", "R0" "RL" "RR"

    toolpath::FeedMode feedMode = toolpath::FeedMode::PerMinute;
    const char* feedModeWord = "";  // "G94" "G95" "G93", Heidenhain "F" "FU"

    // "G54", "G500", "G505", "G59.1"; Heidenhain "datum shift X+10 Y+0 Z+0"; empty: none programmed.
    std::string workOffset;

    // The same state (file and line aside).
    bool sameState(const BlockModal& other) const;
};

using BlockObserver = std::function<void(const BlockModal&)>;

}  // namespace camwb::nc
