// Reader of APT CL source (ISO 4343 style) as CATIA V5, Siemens NX (CLSF) and Creo write it.
// readAptSource() in ClImport.h is its entry point; this header documents what it accepts and what
// each statement becomes.
//
// Syntax sources checked: APT conventions for '$' continuation and '$$' remarks (NX GRIP manual);
// seed-004 §4.6 (CATIA V5 listing) and open-source CATIA APT converters for INDIRV +
// TLON,GOFWD/(CIRCLE/xc,yc,zc,r),ON[,n,INTOF],(LINE/xc,yc,zc,xe,ye,ze); Siemens' CLSF manual for
// CIRCLE/x,y,z,i,j,k,r,tol,ratio,d,cr[,TIMES,n] + end GOTO, TOOL PATH/op,TOOL,tool, TLDATA/MILL,
// d,r,length,taper,tip, LOAD/TOOL, SELECT/TOOL, MSYS, PAINT, END-OF-PATH; PTC's "CL Output for
// Holemaking Cycles" (CYCLE/DRILL|DEEP|BRKCHP|TAP|BORE, DEPTH,a, STEP,b, IPM|MMPM,f, CLEAR,c,
// RAPTO,d, RETURN,e); Autodesk's ISO 4343 APT post (FEDTO, RTRCTO, DELAY, CIRCLE + GOTO, FINI).
//
// Lexical rules: statements are case-insensitive; blanks around '/' and ',' are allowed; numbers
// are [+|-]d[.d][E[+|-]d] ("-62.00000", "1.5E+01"). A line ending in '$' continues on the next
// line; text after a single '$' on the same line is read as the continuation (and warned about:
// card-image APT ignored it, but listings reflowed for print put the next line there); a line
// ending in ',' also continues (warned: the '$' was lost). '$$' starts a remark to the end of the
// line. PPRINT, PARTNO, INSERT, REMARK and TPRINT take the rest of the line literally. A '$'
// continuation that the file never completes is an Error at the '$'.
//
// Statements and the records they give:
//  UNITS/MM|INCHES     inch files are converted: lengths x25.4, IPM -> mm/min, IPR -> mm/rev.
//  PARTNO, PPRINT, REMARK, TPRINT text -> Comment; INSERT text -> PassThrough; STOP/OPSTOP ->
//                      ProgramStop (optional for OPSTOP); '$$' remarks -> Comment (empty ones
//                      are dropped).
//  $$ OPERATION NAME : x (CATIA) and TOOL PATH/x,TOOL,t (NX) close the open section and open
//                      SectionBegin{x}; END-OF-PATH closes it (so do END, FINI, end of input).
//                      The section's toolNumber is the tool loaded in it, else the active one.
//  CUTTER/d[,r[,e,f,a,b,h]] and TLDATA/MILL,d,r,len,... give the geometry of the next tool load
//                      (r = d/2: ball, r > 0: bull, else flat; h -> flute length, len -> length;
//                      TLDATA/DRILL,d,... -> kind drill, diameter only).
//  LOADTL/n[,LENGTH,l,...] and LOAD/TOOL,n[,...] -> ToolChange{n} with the geometry read since the
//                      previous load (CATIA and NX write it first) and the tool name of the TOOL
//                      PATH. Without one it takes this tool number's earlier geometry, else it is
//                      unknown (0), never the previous tool's; a CUTTER/TLDATA that follows such a
//                      load before any motion (Creo writes it there) fills that ToolChange in.
//                      ADJUST and other qualifiers are controller registers the CL model does not
//                      carry. SELECT/TOOL (preselection) and TOOLNO are warnings.
//  SPINDL/rpm[,RPM][,CLW|CCLW] (either order) -> Spindle; SPINDL/OFF -> Spindle{0}; SPINDL/ON
//                      restores the last speed; SMM/SFM surface speed: warning, no record.
//  COOLNT/ON|FLOOD -> Flood, MIST, THRU -> ThroughTool, OFF.  CUTCOM/LEFT|RIGHT|OFF -> CutterComp.
//  FEDRAT/f[,unit] or FEDRAT/unit,f with unit MMPM|IPM|MMPR|IPR (PERMIN|PERREV: in the file's
//                      length unit); without a unit the last mode and the file's units apply. A
//                      change between per-minute and per-revolution gives FeedModeChange; feeds
//                      are written in that mode's unit.
//  DELAY/s -> Dwell.  TLAXIS/i,j,k sets the tool axis for GOTOs with three values.
//  FROM/x,y,z[,i,j,k]  declares where the tool is (APT's start point): it sets the position that
//                      the next move, arc or cycle starts from and gives no record, because it
//                      commands no motion. GOHOME -> Rapid back to the FROM point.
//  RAPID               the next motion only is a Rapid (feed moves otherwise).
//  GOTO/x,y,z[,i,j,k]  -> Rapid/Linear, or ToolAxisMove when the tool axis (given, or kept from
//                      the last GOTO/TLAXIS) is not +Z. Lines of bare "x,y,z[,i,j,k]" after a GOTO
//                      are further points of it (Creo), moved to the same way. GODLTA/dx,dy,dz
//                      [,i,j,k] (or /d along the axis) is the same, relative. Other counts of values
//                      are Errors.
//  CIRCLE/cx,cy,cz,i,j,k,r[,...][,TIMES,n] (NX, Autodesk) + the next GOTO -> Arc from the current
//                      position to that GOTO, counter-clockwise about (i,j,k) (right-hand rule: NX
//                      writes k = -1 for G2, Creo documents the right-hand rule); a helix when the
//                      GOTO leaves the plane; TIMES,n means n laps in all (turns = n - 1). Point
//                      lines after that GOTO lie on the arc and move its end (Creo's POINTS_&_ARC
//                      output), laps counted through them. The Arc carries the CIRCLE's line. A
//                      CIRCLE never followed by its GOTO, or by another motion first, is an Error.
//  INDIRV/i,j,k (or INDIRP/x,y,z) + TLON,GOFWD/(CIRCLE/cx,cy,cz[,i,j,k],r),ON[,n,INTOF],
//                      (LINE/x1,y1,z1,x2,y2,z2) (CATIA) -> Arc. APT meaning: the tool centre
//                      runs on the circle from the current position, in the direction that
//                      INDIRV gives at the start (else the direction of the previous move),
//                      until it is on the LINE (an infinite line; CATIA writes it from the centre
//                      to the end point) for the n-th time (n = 1 without INTOF); crossings at the
//                      start itself do not count, so a full circle reads ON,2,INTOF. The end point
//                      is that crossing, taken exactly from the LINE's points when one of them is
//                      it. Start points off the circle or its plane are warned about, not fixed.
//  CYCLE/DRILL|DEEP|BRKCHP|TAP|BORE (also DRILL,DEEP / DRILL,BRKCHP, RIGID -> Tap, REAM -> Bore,
//                      FACE and CSINK -> Drill) with couplets DEPTH|FEDTO,d (depth below the
//                      hole top; the sign is ignored), STEP|INCR,p, MMPM|IPM|MMPR|IPR,f, CLEAR,c,
//                      RAPTO,r, RTRCTO|RETURN,e|AUTO, DWELL,s, or positionally depth[,unit],feed
//                      [,clear] ("d,c,MMPM,f" could mean either and is an Error); then each GOTO is one hole top until
//                      CYCLE/OFF (CYCLE/ON[,...] resumes the last cycle, changed by its couplets). Consecutive holes
//                      with equal parameters and equal top Z form one Cycle record: kind DRILL -> Drill (DrillDwell
//                      with a dwell), DEEP -> Peck, BRKCHP -> ChipBreak, TAP -> Tap, BORE -> Bore. retractZ (R plane) =
//                      top + RAPTO, else top + CLEAR, else the top (when both are given RAPTO wins, as in ISO 4343 /
//                      Autodesk output); bottomZ = top - |depth|; clearanceZ = the tool Z before the CYCLE statement;
//                      after each hole the tool returns to the R plane (G99) unless RTRCTO/RETURN says otherwise: AUTO
//                      or 0 -> clearanceZ (G98), e > 0 -> a plane e above the top (G98 with clearanceZ there). The
//                      cycle's feed is its own, else the current FEDRAT; a per-revolution cycle feed is wrapped in
//                      FeedModeChange records. A Cycle carries the line of its first hole; any
//                      other record between two holes ends the run. Unsupported couplets (BACK,
//                      ORIENT, TIMES, ...) are warnings; RTRCTO,MANUAL is not documented anywhere
//                      we found and is an Error rather than a guess.
//  END                 closes the open section and cycle (no record: the post writes the program
//                      end). FINI ends the input; anything after it is one warning.
//  MACHIN, INTOL, OUTTOL, TOLER, AUTOPS, MULTAX, CLPRNT and an identity MSYS carry nothing for
//                      the CL model and are accepted silently; PAINT, other MSYS, ORIGIN and
//                      unknown statements are warnings. GOLFT/GORGT/GOFWD/GOBACK with other geometry need
//                      an APT geometry processor and are Errors, like every malformed statement.
#pragma once

#include "toolpath/AptScanner.h"
#include "toolpath/ClBuilder.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace camwb::toolpath {

class AptReader {
public:
    AptReader(base::LineReader& lines, std::string fileName);
    base::Result<ClImport> read();

private:
    using Items = std::vector<AptItem>;

    enum class CycleReturn { RPlane, Clearance, Distance };
    // One CYCLE statement's parameters, in mm (depth and distances along the tool axis).
    struct CycleDefinition {
        CycleKind kind = CycleKind::Drill;
        std::optional<double> depthMm, peckMm, clearMm, raptoMm, dwellSeconds;
        std::optional<double> feed;  // in the unit of feedMode
        FeedMode feedMode = FeedMode::PerMinute;
        CycleReturn ret = CycleReturn::RPlane;
        double returnMm = 0;
        int line = 0;
    };
    struct CycleRun {
        Cycle cycle;
        FeedMode feedMode = FeedMode::PerMinute;
        int line = 0;
    };
    struct PendingCircle {
        Vec3 center, axis;
        double radiusMm = 0;
        int turns = 0;
        int line = 0;
        TextPos pos;
    };
    // The Arc that a CIRCLE's GOTO made, while point lines may still move its end further.
    struct OpenArc {
        std::size_t record = 0;
        double radiusMm = 0;
        double sweep = 0;  // radians travelled so far
        Vec3 last;
        int line = 0;
    };

    base::Status unit(const AptUnit& unit);
    base::Status statement(const AptStatement& s);
    // The statement's arguments into m_items (reused: no allocation per statement).
    base::Status arguments(const AptStatement& s);
    // Adds a record, ending a run of cycle holes first so that records stay in file order.
    void emit(Record record, int line);
    double length(double fileValue) const { return fileValue * m_mmPerUnit; }
    Vec3 point(double x, double y, double z) const { return {length(x), length(y), length(z)}; }

    // Machine state statements (AptReader.cpp).
    base::Status units(const AptStatement& s, const Items& items);
    base::Status fedrat(const AptStatement& s, const Items& items);
    base::Status spindl(const AptStatement& s, const Items& items);
    base::Status coolnt(const AptStatement& s, const Items& items);
    base::Status cutcom(const AptStatement& s, const Items& items);
    base::Status cutter(const AptStatement& s, const Items& items, bool tldata);
    base::Status loadTool(const AptStatement& s, const Items& items, std::size_t numberIndex);
    base::Status delay(const AptStatement& s, const Items& items);
    base::Status toolPath(const AptStatement& s);
    base::Status msys(const AptStatement& s, const Items& items);
    base::Status endOfInput(int line);

    // Motion (AptMotion.cpp).
    base::Status gotoStatement(const AptStatement& s, const Items& items, bool relative);
    base::Status pointLine(const AptStatement& s);
    base::Status from(const AptStatement& s, const Items& items);
    base::Status gohome(const AptStatement& s);
    base::Status tlaxis(const AptStatement& s, const Items& items);
    base::Status circle(const AptStatement& s, const Items& items);
    base::Status indirection(const AptStatement& s, const Items& items, bool towardsPoint);
    base::Status gofwd(const AptStatement& s, const Items& items);
    base::Status moveTo(const Vec3& to, const Vec3& axis, const AptStatement& s);
    base::Status finishCircle(const Vec3& to, const AptStatement& s);
    void checkArc(const Vec3& start, const Arc& arc, std::optional<double> radiusMm, int line);

    // Canned cycles (AptCycle.cpp).
    base::Status cycle(const AptStatement& s, const Items& items);
    base::Status cycleCouplets(const Items& items, std::size_t first, CycleDefinition& def);
    base::Status hole(const Vec3& top, const Vec3& axis, const AptStatement& s);
    void flushCycleRun();
    void endCycle(int line, bool warnIfActive);

    ClBuilder m_out;
    AptScanner m_scanner;
    AptUnit m_unit;            // the unit being read, its storage reused for the next
    AptStatement m_statement;  // likewise
    Items m_items;
    double m_mmPerUnit = 1;
    std::optional<Vec3> m_position;
    Vec3 m_toolAxis{0, 0, 1};
    std::optional<Vec3> m_from;
    std::optional<Vec3> m_lastDirection;   // of the last move, at its end
    std::optional<Vec3> m_startDirection;  // INDIRV for the next GOFWD
    bool m_rapidNext = false;
    double m_feed = 0;  // mm/min or mm/rev (m_feedMode)
    bool m_feedSet = false;
    bool m_warnedNoFeed = false;
    FeedMode m_feedMode = FeedMode::PerMinute;
    Spindle m_spindle{0, true};
    bool m_spindleSet = false;
    Tool m_cutter;
    bool m_cutterFresh = false;  // a CUTTER/TLDATA was read since the last load
    std::string m_nextToolName;
    std::map<int, Tool> m_knownTools;               // the last geometry loaded under each tool number
    std::optional<std::size_t> m_toolChangeRecord;  // a load without geometry, while no motion followed it
    std::optional<PendingCircle> m_circle;
    std::optional<OpenArc> m_openArc;
    std::optional<bool> m_pointsFollow;  // after a GOTO: whether its further point lines are rapids
    bool m_cycleActive = false;
    std::optional<CycleDefinition> m_cycleDef;
    std::optional<double> m_cycleStartZ;
    std::optional<CycleRun> m_run;
    bool m_finished = false;
};

}  // namespace camwb::toolpath
