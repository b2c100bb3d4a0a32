// The words of an ordinary block read into BlockWords, in the order written: assignments take
// effect at once (a later word of the block sees them), G codes are sorted into their modal
// groups, values are evaluated and range-checked; Execute.cpp then applies the groups.
#include "nc/sinumerik/Machine.h"

#include <cmath>

namespace camwb::nc::sinumerik {

using namespace camwb::toolpath;

namespace {

// Path control, limits, approach: nothing the trace shows.
bool isPassiveG(int g)
{
    return g == 9 || g == 60 || g == 64 || (g >= 641 && g <= 645) || g == 601 || g == 602 || g == 603 || g == 25 ||
           g == 26 || g == 110 || g == 111 || g == 112 || g == 140 || g == 141 || g == 142 || g == 143 || g == 340 ||
           g == 341 || g == 62 || g == 621;
}

}  // namespace

void Machine::readG(const Program& p, const Word& word, BlockWords& w)
{
    const int g = word.code;
    if (g <= 3) {
        w.motion = g;
        w.arc.pos = word.pos;
    } else if (g == 4)
        w.dwell = true;
    else if (g >= 17 && g <= 19)
        w.plane = g;
    else if (g == 90 || g == 91)
        w.absInc = g;
    else if (g == 70 || g == 71 || g == 700 || g == 710)
        w.units = g;
    else if (g >= 54 && g <= 57)
        w.workOffset = g - 53;
    else if (g == 500)
        w.workOffset = 0;
    else if (g >= 505 && g <= 599)
        w.workOffset = g - 500;
    else if (g >= 40 && g <= 42)
        w.comp = g;
    else if (g == 93 || g == 94 || g == 95)
        w.feedMode = g;
    else if (g == 96 || g == 97 || g == 961 || g == 971)
        w.css = g == 96 || g == 961 ? 1 : 0;
    else if (g == 53 || g == 153)
        w.g53 = true;
    else if (g == 74 || g == 75)
        w.approach = g;
    else if (g == 450 || g == 451)
        w.corners = g;
    else if (!isPassiveG(g))
        warning(p, word.pos, "G" + std::to_string(g) + " is not interpreted: ignored");
}

// A value with its place: false (and the block left out) when it cannot be evaluated or lies
// outside the control's range.
bool Machine::readPosition(const Program& p, const Word& word, std::optional<double>& value, ValueMode& mode)
{
    const auto v = wordValue(p, word);
    if (!v || !checkRange(p, word.pos, *v)) {
        m_evalFailed = true;
        return false;
    }
    value = v;
    mode = word.mode;
    return true;
}

// False: the block stops the program (SETAL).
bool Machine::readKeyword(const Program& p, const Block& b, const Word& word, BlockWords& w)
{
    switch (static_cast<Keyword>(word.code)) {
    case Keyword::DiamOn:
    case Keyword::DiamOf:
        // Diameter or radius programming is a turning function: the program is for a lathe,
        // whose tool works in the XZ plane through the spindle axis, where Y is 0.
        m_modal.diameter = static_cast<Keyword>(word.code) == Keyword::DiamOn;
        m_known.give(axisBit(1));
        break;
    case Keyword::TraOri:
        if (!m_five.active())
            warning(p, word.pos,
                    "TRAORI (five-axis transformation) needs a five-axis machine (--machine, or the NC inspector's "
                    "Machine) to be traced: "
                    "positions are traced as programmed");
        w.transform = 1;
        break;
    case Keyword::TraFoof:
        w.transform = 0;
        break;
    case Keyword::Supa:
        w.g53 = true;  // G53 and more (handwheel and external offsets suppressed): machine coordinates
        break;
    case Keyword::Cycle800:
        swivel(p, b, word);
        break;
    case Keyword::Frame:
        warning(p, word.pos,
                "programmable frame " + p.texts[static_cast<std::size_t>(b.text)] +
                    " is not applied: positions are traced in the programmed frame");
        setSource(b.line);
        m_sink.passThrough(PassThrough{p.texts[static_cast<std::size_t>(b.text)]});
        break;
    case Keyword::Ret:
        w.ret = true;
        break;
    case Keyword::SetAl: {
        m_evalFailed = false;
        const auto args = evalArgs(p, b);
        const int alarm = !args.empty() && args[0] ? static_cast<int>(*args[0]) : 0;
        // The control shows the message line beside the alarm: a cycle names the cause with MSG.
        error(p, word.pos,
              "the program sets alarm " + std::to_string(alarm) + " (SETAL): stopped" +
                  (m_message.empty() ? std::string() : ": " + m_message));
        m_stopped = true;
        return false;
    }
    default:
        break;
    }
    return true;
}

bool Machine::readWords(const Program& p, const Block& b, BlockWords& w)
{
    const Word* words = p.words.data() + b.firstWord;
    for (std::int32_t i = 0; i < b.wordCount; ++i) {
        const Word& word = words[i];
        switch (word.kind) {
        case WordKind::G:
            readG(p, word, w);
            break;
        case WordKind::M:
            if (w.mCount < static_cast<int>(std::size(w.m)))
                w.m[w.mCount++] = word.code;
            break;
        case WordKind::Axis:
            readPosition(p, word, w.axis[word.index], w.axisMode[word.index]);
            w.axisPos[word.index] = word.pos;
            break;
        case WordKind::MachineAxis:
            w.machineAxes.bits |= axisBit(word.index).bits;
            w.machineAxisPos = word.pos;
            break;
        case WordKind::ToolVector:
            if (const auto v = wordValue(p, word)) {
                w.toolVector[word.index] = v;
                w.toolVectorPos = word.pos;
            } else {
                m_evalFailed = true;
            }
            break;
        case WordKind::Centre:
            readPosition(p, word, w.arc.centre[word.index], w.arc.centreMode[word.index]);
            break;
        case WordKind::F:
            w.feed = wordValue(p, word);
            break;
        case WordKind::S:
            w.speed = wordValue(p, word);
            break;
        case WordKind::T:
            w.tool = wordValue(p, word);
            break;
        case WordKind::TName:
            m_toolName = p.texts[static_cast<std::size_t>(word.code)];
            w.tool = 0;
            break;
        case WordKind::D:
            w.edge = wordValue(p, word);
            break;
        case WordKind::Cr:
            w.arc.cr = wordValue(p, word);
            break;
        case WordKind::Ar:
            w.arc.ar = wordValue(p, word);
            break;
        case WordKind::Turn: {
            const auto v = wordValue(p, word);
            if (v && (*v < 0 || *v > 999 || *v != std::trunc(*v))) {
                error(p, word.pos, "TURN must be a whole number 0..999");
                m_evalFailed = true;
            } else if (v) {
                w.arc.turn = static_cast<int>(*v);
            }
            break;
        }
        case WordKind::Lims:
            w.lims = wordValue(p, word);
            break;
        case WordKind::Assign: {
            const auto v = wordValue(p, word);
            if (v)
                assign(p, word, *v);
            break;
        }
        case WordKind::Keyword:
            if (!readKeyword(p, b, word, w))
                return false;
            break;
        case WordKind::Msg:
            m_message = word.code >= 0 ? p.texts[static_cast<std::size_t>(word.code)] : std::string();
            if (word.code >= 0) {
                setSource(b.line);
                m_sink.comment(Comment{m_message});
            }
            break;
        default:
            break;
        }
    }
    return true;
}

}  // namespace camwb::nc::sinumerik
