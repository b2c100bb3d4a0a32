#include "NcBenchPrograms.h"

#include "BenchProgram.h"

#include "base/NumberFormat.h"

#include <variant>

namespace camwb::bench {

namespace {

using namespace camwb::toolpath;

// Words the way posts/linuxcnc.js and posts/sinumerik828d-emco.js write them: 3 decimals, axes and
// F only when they change, the motion word when it changes, I and J always. SINUMERIK numbers
// every block N10, N20, ... and writes the feed without decimals.
class GWordWriter {
public:
    explicit GWordWriter(bool sinumerik) : m_numbered(sinumerik), m_feedFormat{sinumerik ? 0 : 3, !sinumerik} {}

    std::string take() { return std::move(m_out); }

    void line(const std::string& text)
    {
        if (m_numbered) {
            m_out += 'N';
            m_out += std::to_string(m_blockNumber);
            m_out += ' ';
            m_blockNumber += 10;
        }
        m_out += text;
        m_out += '\n';
    }
    void move(const char* motion, const Vec3& to, double feed, const std::string& centre = {})
    {
        std::string block;
        if (m_motion != motion) {
            block += motion;
            m_motion = motion;
        }
        axis(block, 'X', to.x, m_at.x);
        axis(block, 'Y', to.y, m_at.y);
        axis(block, 'Z', to.z, m_at.z);
        block += centre;
        if (feed > 0) {
            const std::string f = m_feedFormat.format(feed);
            if (f != m_feed) {
                append(block, "F" + f);
                m_feed = f;
            }
        }
        m_at = to;
        m_started = true;
        line(block);
    }
    const Vec3& at() const { return m_at; }

private:
    static void append(std::string& block, const std::string& word)
    {
        if (!block.empty())
            block += ' ';
        block += word;
    }
    void axis(std::string& block, char letter, double value, double before)
    {
        const std::string text = base::formatFixed(value, 3);
        if (!m_started || text != base::formatFixed(before, 3))
            append(block, letter + text);
    }

    bool m_numbered;
    base::NumberFormat m_feedFormat;
    long long m_blockNumber = 10;
    bool m_started = false;
    std::string m_out;
    std::string m_motion;
    std::string m_feed;
    Vec3 m_at;
};

// The benchmark's moves through a G-word writer: rapids, lines and XY arcs by centre (I, J).
void writeMoves(GWordWriter& w, std::size_t moves)
{
    const Toolpath path = benchProgram(moves);
    for (const Record& record : path.records()) {
        if (const auto* r = std::get_if<Rapid>(&record)) {
            w.move("G0", r->to, 0);
        } else if (const auto* l = std::get_if<Linear>(&record)) {
            w.move("G1", l->to, l->feedMmPerMin);
        } else if (const auto* a = std::get_if<Arc>(&record)) {
            const std::string centre = " I" + base::formatFixed(a->center.x - w.at().x, 3) + " J" +
                                       base::formatFixed(a->center.y - w.at().y, 3);
            w.move(a->clockwise ? "G2" : "G3", a->to, a->feedMmPerMin, centre);
        }
    }
}

std::string isoProgram(std::size_t moves)
{
    GWordWriter w(false);
    w.line("%");
    w.line("(benchmark)");
    w.line("G21 G90 G94 G17 G40 G49 G80 G91.1");
    w.line("G54");
    w.line("T1 M6");
    w.line("G43 H1");
    w.line("M3 S4000");
    writeMoves(w, moves);
    w.line("M5 M9");
    w.line("M2");
    w.line("%");
    return w.take();
}

std::string sinumerikProgram(std::size_t moves)
{
    GWordWriter w(true);
    w.line(";benchmark");
    w.line("G17 G40");
    w.line("G710");
    w.line("G54 G90");
    w.line("M6 T1 D1");
    w.line("M3 S4000");
    writeMoves(w, moves);
    w.line("M5 M9");
    w.line("M30");
    return w.take();
}

// Klartext as an iTNC 530 program from CAM reads: every block numbered from 0, L with the axes
// that change (signed, 3 decimals), FMAX for rapids, F when it changes, an arc as CC (its centre)
// and C (its end, DR- clockwise).
class KlartextWriter {
public:
    std::string take() { return std::move(m_out); }

    void line(const std::string& text)
    {
        m_out += std::to_string(m_blockNumber++);
        m_out += ' ';
        m_out += text;
        m_out += '\n';
    }
    void linear(const Vec3& to, double feed)
    {
        std::string block = "L";
        axis(block, 'X', to.x, m_at.x);
        axis(block, 'Y', to.y, m_at.y);
        axis(block, 'Z', to.z, m_at.z);
        if (feed <= 0) {
            block += " FMAX";
        } else if (feed != m_feed) {
            block += " F" + base::formatFixed(feed, 0);
            m_feed = feed;
        }
        m_at = to;
        m_started = true;
        line(block);
    }
    void arc(const Arc& a)
    {
        line("CC X" + m_coordinate.format(a.center.x) + " Y" + m_coordinate.format(a.center.y));
        std::string block = "C X" + m_coordinate.format(a.to.x) + " Y" + m_coordinate.format(a.to.y);
        if (m_coordinate.format(a.to.z) != m_coordinate.format(m_at.z))
            block += " Z" + m_coordinate.format(a.to.z);
        block += a.clockwise ? " DR-" : " DR+";
        if (a.feedMmPerMin != m_feed) {
            block += " F" + base::formatFixed(a.feedMmPerMin, 0);
            m_feed = a.feedMmPerMin;
        }
        m_at = a.to;
        line(block);
    }

private:
    void axis(std::string& block, char letter, double value, double before)
    {
        const std::string text = m_coordinate.format(value);
        if (!m_started || text != m_coordinate.format(before)) {
            block += ' ';
            block += letter;
            block += text;
        }
    }

    base::NumberFormat m_coordinate{3, false, false, true};
    long long m_blockNumber = 0;
    bool m_started = false;
    double m_feed = 0;
    std::string m_out;
    Vec3 m_at;
};

std::string heidenhainProgram(std::size_t moves)
{
    KlartextWriter w;
    w.line("BEGIN PGM BENCH MM");
    w.line("BLK FORM 0.1 Z X-10 Y-80 Z-20");
    w.line("BLK FORM 0.2 X+160 Y+10 Z+0");
    w.line("TOOL CALL 1 Z S4000");
    w.line("L Z+5.000 R0 FMAX M3");
    const Toolpath path = benchProgram(moves);
    for (const Record& record : path.records()) {
        if (const auto* r = std::get_if<Rapid>(&record))
            w.linear(r->to, 0);
        else if (const auto* l = std::get_if<Linear>(&record))
            w.linear(l->to, l->feedMmPerMin);
        else if (const auto* a = std::get_if<Arc>(&record))
            w.arc(*a);
    }
    w.line("L M30");
    w.line("END PGM BENCH MM");
    return w.take();
}

// Rows of moves computed from R parameters: a WHILE loop of 20 lines with a sine in Y, a LOOP of
// 5 half circles left with a conditional GOTOF out of it, a GOTOB back to the next row. Each row
// executes kSinumerikBlocksPerRow blocks as the interpreter counts them (every line it runs;
// `camwb_nc_bench --write-program` prints the count).
constexpr std::size_t kSinumerikBlocksPerRow = 134;

std::string sinumerikLoopProgram(std::size_t blocks)
{
    const std::size_t rows = blocks / kSinumerikBlocksPerRow + 1;
    std::string out = "N10 ;benchmark: R-parameter loops\n"
                      "N20 G17 G40\n"
                      "N30 G710\n"
                      "N40 G54 G90\n"
                      "N50 M6 T1 D1\n"
                      "N60 M3 S4000\n"
                      "N70 G0 X0 Y0 Z5\n"
                      "N80 G1 Z2 F300\n"
                      "N90 R1=0\n"
                      "N100 ROW: R2=0 R3=R1*0.001\n"
                      "N110 WHILE R2<20\n"
                      "N120   R4=R2*0.5\n"
                      "N130   G1 X=R4 Y=R3+SIN(R2*18)*2 Z=-R3 F900\n"
                      "N140   R2=R2+1\n"
                      "N150 ENDWHILE\n"
                      "N160 G1 Y=R3\n"
                      "N170 R5=0\n"
                      "N180 LOOP\n"
                      "N190   R5=R5+1\n"
                      "N200   IF R5>5 GOTOF BACK\n"
                      "N210   G2 X=R4-2 Y=R3 I=-1 J=0\n"
                      "N220   R4=R4-2\n"
                      "N230 ENDLOOP\n"
                      "N240 BACK: R1=R1+1\n"
                      "N250 IF R1<" +
                      std::to_string(rows) +
                      " GOTOB ROW\n"
                      "N260 G0 Z5\n"
                      "N270 M5 M9\n"
                      "N280 M30\n";
    return out;
}

// The same rows in Klartext: Q parameters with formulas and FN functions, a section repeat
// (CALL LBL 2 REP 19) for 20 lines, a called label with its own repeat for 5 half circles (CC,
// C), an FN 12 jump back to the next row. Each row executes kHeidenhainBlocksPerRow blocks.
constexpr std::size_t kHeidenhainBlocksPerRow = 134;

std::string heidenhainLabelProgram(std::size_t blocks)
{
    const std::size_t rows = blocks / kHeidenhainBlocksPerRow + 1;
    return "0 BEGIN PGM BENCHQ MM\n"
           "1 ; benchmark: Q parameters, LBL repeats, a called label, FN 12 jumps\n"
           "2 BLK FORM 0.1 Z X-20 Y-10 Z-20\n"
           "3 BLK FORM 0.2 X+20 Y+100 Z+0\n"
           "4 TOOL CALL 1 Z S4000\n"
           "5 L Z+5 R0 FMAX M3\n"
           "6 L X+0 Y+0 FMAX\n"
           "7 L Z+2 F300\n"
           "8 Q1 = 0\n"
           "9 LBL 1\n"
           "10 Q2 = Q1 * 0.001\n"
           "11 Q3 = 0\n"
           "12 LBL 2\n"
           "13 Q4 = Q3 * 0.5\n"
           "14 Q5 = Q2 + SIN(Q3 * 18) * 2\n"
           "15 L X+Q4 Y+Q5 Z-Q2 F900\n"
           "16 FN 1: Q3 = +Q3 + +1\n"
           "17 CALL LBL 2 REP 19\n"
           "18 L Y+Q2\n"
           "19 CALL LBL \"ARCS\"\n"
           "20 FN 1: Q1 = +Q1 + +1\n"
           "21 FN 12: IF +Q1 LT +" +
           std::to_string(rows) +
           " GOTO LBL 1\n"
           "22 L Z+5 FMAX\n"
           "23 L M5 M9\n"
           "24 L M30\n"
           "25 LBL \"ARCS\"\n"
           "26 LBL 3\n"
           "27 Q6 = Q4 - 1\n"
           "28 Q4 = Q4 - 2\n"
           "29 CC X+Q6 Y+Q2\n"
           "30 C X+Q4 Y+Q2 DR-\n"
           "31 CALL LBL 3 REP 4\n"
           "32 LBL 0\n"
           "33 END PGM BENCHQ MM\n";
}

}  // namespace

std::optional<NcProgram> ncProgramFromName(std::string_view name)
{
    for (const NcProgram p : {NcProgram::Iso, NcProgram::Sinumerik, NcProgram::SinumerikLoops, NcProgram::Heidenhain,
                              NcProgram::HeidenhainLabels})
        if (name == ncProgramName(p))
            return p;
    return std::nullopt;
}

const char* ncProgramName(NcProgram program)
{
    switch (program) {
    case NcProgram::Iso:
        return "iso";
    case NcProgram::Sinumerik:
        return "sinumerik";
    case NcProgram::SinumerikLoops:
        return "sinumerik-loops";
    case NcProgram::Heidenhain:
        return "heidenhain";
    case NcProgram::HeidenhainLabels:
        return "heidenhain-labels";
    }
    return "";
}

nc::Dialect dialectOf(NcProgram program)
{
    switch (program) {
    case NcProgram::Iso:
        return nc::Dialect::Iso;
    case NcProgram::Sinumerik:
    case NcProgram::SinumerikLoops:
        return nc::Dialect::Sinumerik;
    case NcProgram::Heidenhain:
    case NcProgram::HeidenhainLabels:
        return nc::Dialect::Heidenhain;
    }
    return nc::Dialect::Iso;
}

std::string ncProgram(NcProgram program, std::size_t blocks)
{
    switch (program) {
    case NcProgram::Iso:
        return isoProgram(blocks);
    case NcProgram::Sinumerik:
        return sinumerikProgram(blocks);
    case NcProgram::SinumerikLoops:
        return sinumerikLoopProgram(blocks);
    case NcProgram::Heidenhain:
        return heidenhainProgram(blocks * 2 / 3);  // half the moves are arcs, two blocks each
    case NcProgram::HeidenhainLabels:
        return heidenhainLabelProgram(blocks);
    }
    return {};
}

}  // namespace camwb::bench
