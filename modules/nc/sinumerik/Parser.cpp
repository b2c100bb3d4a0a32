// Logical blocks of a SINUMERIK program: physical lines (an expression wrapped onto the next line
// with the operator repeated, as printed listings do, is joined with a warning), block numbers,
// labels, statements (IF/WHILE/REPEAT/FOR/LOOP/GOTO/PROC/DEF/MCALL) and control-flow matching.
#include "nc/sinumerik/ParserImpl.h"

#include <algorithm>
#include <charconv>

namespace camwb::nc::sinumerik {

namespace {

constexpr std::size_t kMaxBlockTokens = 20000;  // a wrapped block longer than this is cut

bool isArithmetic(Tok k) { return k == Tok::Plus || k == Tok::Minus || k == Tok::Star || k == Tok::Slash; }

bool isDigits(std::string_view s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos; }

bool equalsUpper(std::string_view text, std::string_view upperName)
{
    if (text.size() != upperName.size())
        return false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
        if (c != upperName[i])
            return false;
    }
    return true;
}

// The last token of a line that ends an unfinished expression: the block goes on in the next line.
bool endsUnfinished(const std::vector<Token>& tokens)
{
    std::size_t n = tokens.size();
    if (n > 0 && tokens[n - 1].kind == Tok::Comment)
        --n;
    if (n < 2)
        return false;
    const Token& last = tokens[n - 1];
    if (isArithmetic(last.kind) || last.kind == Tok::Eq || last.kind == Tok::Ne || last.kind == Tok::Lt ||
        last.kind == Tok::Gt || last.kind == Tok::Le || last.kind == Tok::Ge)
        return true;
    return last.kind == Tok::Name &&
           (equalsUpper(last.text, "AND") || equalsUpper(last.text, "OR") || equalsUpper(last.text, "XOR"));
}

bool startsContinuation(const Token& first)
{
    if (isArithmetic(first.kind) || first.kind == Tok::LParen || first.kind == Tok::Number)
        return true;
    if (first.kind != Tok::Name)
        return false;
    const std::string u = upper(first.text);
    if (u.size() > 1 && u[0] == 'R' && isDigits(std::string_view(u).substr(1)))
        return true;
    static constexpr std::string_view kOperands[] = {"SIN", "COS", "TAN",   "ASIN",    "ACOS",  "ATAN2", "SQRT",
                                                     "ABS", "POT", "ROUND", "ROUNDUP", "TRUNC", "NOT"};
    return std::find(std::begin(kOperands), std::end(kOperands), u) != std::end(kOperands);
}

}  // namespace

std::string upper(std::string_view s)
{
    std::string out(s);
    for (char& c : out)
        if (c >= 'a' && c <= 'z')
            c = static_cast<char>(c - 'a' + 'A');
    return out;
}

bool splitAddress(std::string_view u, std::string_view& letters, std::string_view& digits)
{
    std::size_t i = 0;
    while (i < u.size() && u[i] >= 'A' && u[i] <= 'Z')
        ++i;
    if (i == 0 || i == u.size())
        return false;
    const std::string_view rest = u.substr(i);
    const std::size_t dot = rest.find('.');
    if (!isDigits(rest.substr(0, dot)) && !(dot == 0 && rest.size() > 1))
        return false;
    if (dot != std::string_view::npos && dot + 1 < rest.size() && !isDigits(rest.substr(dot + 1)))
        return false;
    letters = u.substr(0, i);
    digits = rest;
    return true;
}

Program parseProgram(std::string path, std::string source)
{
    Program program;
    program.path = std::move(path);
    program.source = std::move(source);
    Parser(program).run();
    return program;
}

bool Parser::peekName(std::string_view upperName, std::size_t ahead) const
{
    const Token* t = peek(ahead);
    return t && t->kind == Tok::Name && equalsUpper(t->text, upperName);
}

Pos Parser::here() const
{
    if (m_pos < m_end)
        return posOf(m_tokens[m_pos]);
    if (m_end > 0) {
        const Token& last = m_tokens[m_end - 1];
        return {last.line, last.column + static_cast<int>(last.text.size())};
    }
    return {m_block ? m_block->line : 0, 0};
}

bool Parser::error(Pos pos, std::string message)
{
    if (m_block) {
        if (m_block->kind == BlockKind::Normal || m_block->kind == BlockKind::Empty)
            m_block->kind = BlockKind::Bad;
        if (m_block->bad)
            return false;  // one error per block: the rest of it is not read
        m_block->bad = true;
    }
    if (m_p.diagnostics.size() < kMaxParseDiagnostics)
        m_p.diagnostics.push_back({Severity::Error, m_p.path, pos.line, pos.column, std::move(message)});
    else
        ++m_p.diagnosticsDropped;
    return false;
}

void Parser::addDiagnostic(Diagnostic d)
{
    if (m_p.diagnostics.size() < kMaxParseDiagnostics)
        m_p.diagnostics.push_back(std::move(d));
    else
        ++m_p.diagnosticsDropped;
}

void Parser::warning(Pos pos, std::string message)
{
    if (m_p.diagnostics.size() >= kMaxParseDiagnostics) {
        ++m_p.diagnosticsDropped;
        return;
    }
    m_p.diagnostics.push_back({Severity::Warning, m_p.path, pos.line, pos.column, std::move(message)});
}

std::int32_t Parser::addText(std::string_view text)
{
    m_p.texts.emplace_back(text);
    return static_cast<std::int32_t>(m_p.texts.size() - 1);
}

Word& Parser::addWord(Block& block, WordKind kind, Pos pos)
{
    Word w;
    w.kind = kind;
    w.pos = pos;
    m_p.words.push_back(w);
    ++block.wordCount;
    return m_p.words.back();
}

void Parser::run()
{
    // Reserving costs no memory until used and saves the copies of growing a million blocks.
    const auto lineCount = static_cast<std::size_t>(std::count(m_p.source.begin(), m_p.source.end(), '\n')) + 1;
    m_p.blocks.reserve(lineCount);
    m_p.words.reserve(lineCount * 3);
    m_tokens.reserve(64);
    LineSplitter lines(m_p.source);
    std::string_view line;
    int lineNumber = 0;
    std::vector<Token> lineTokens;
    bool pending = false;
    auto flush = [&] {
        if (!m_tokens.empty())
            parseBlock();
        m_tokens.clear();
        pending = false;
    };
    while (lines.next(line)) {
        if (lineNumber == 100'000'000)
            break;  // larger programs are cut: diagnostics and lines stay ints
        ++lineNumber;
        lineTokens.clear();
        lexLine(line, lineNumber, lineTokens);
        if (pending) {
            if (lineTokens.empty())
                continue;  // blank lines inside a wrapped expression
            if (lineTokens[0].kind != Tok::Comment && startsContinuation(lineTokens[0]) &&
                m_tokens.size() < kMaxBlockTokens) {
                if (m_tokens.back().kind == Tok::Comment)
                    m_tokens.pop_back();
                std::size_t skip = 0;
                if (isArithmetic(lineTokens[0].kind) && lineTokens[0].kind == m_tokens.back().kind)
                    skip = 1;  // the Czech typographic convention repeats the operator at a wrap
                warning({lineTokens[0].line, lineTokens[0].column},
                        "the block of line " + std::to_string(m_tokens.front().line) +
                            " continues here (a printed line wrap" + (skip ? ", operator repeated" : "") +
                            "): the control needs one block per line");
                m_tokens.insert(m_tokens.end(), lineTokens.begin() + static_cast<std::ptrdiff_t>(skip),
                                lineTokens.end());
                pending = endsUnfinished(m_tokens);
                if (!pending)
                    flush();
                continue;
            }
            flush();
        }
        m_tokens.swap(lineTokens);
        if (endsUnfinished(m_tokens))
            pending = true;
        else
            flush();
    }
    flush();
    const auto byNumber = [](const auto& a, const auto& b) { return a.first < b.first; };
    if (!std::is_sorted(m_p.blockNumbers.begin(), m_p.blockNumbers.end(), byNumber))
        std::stable_sort(m_p.blockNumbers.begin(), m_p.blockNumbers.end(), byNumber);
    matchFlow();
    for (const auto& [blockIndex, label] : m_gotos) {
        const Block& b = m_p.blocks[blockIndex];
        if (b.gotoDir == GotoDir::BothNoAlarm)
            continue;
        const bool number = label.size() > 1 && label[0] == 'N' && isDigits(std::string_view(label).substr(1));
        bool found = m_p.labels.count(label) > 0;
        if (number) {
            std::int64_t n = 0;
            std::from_chars(label.data() + 1, label.data() + label.size(), n);
            found = found || std::binary_search(m_p.blockNumbers.begin(), m_p.blockNumbers.end(),
                                                std::pair<std::int64_t, std::int32_t>{n, 0},
                                                [](const auto& a, const auto& b) { return a.first < b.first; });
        }
        if (!found)
            addDiagnostic(
                {Severity::Error, m_p.path, b.line, 0, "undefined label " + label + " (jump target of GOTO)"});
    }
}

void Parser::parseBlock()
{
    Block block;
    block.kind = BlockKind::Normal;
    block.line = m_tokens.front().line;
    block.firstWord = static_cast<std::int32_t>(m_p.words.size());
    block.firstArg = static_cast<std::int32_t>(m_p.args.size());
    m_block = &block;
    m_pos = 0;
    m_end = m_tokens.size();
    if (m_tokens.back().kind == Tok::Comment) {
        std::string_view text = m_tokens.back().text;
        while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
            text.remove_suffix(1);
        block.comment = addText(text);
        --m_end;
    }
    const auto index = static_cast<std::int32_t>(m_p.blocks.size());
    if (peekIs(Tok::Slash))
        ++m_pos;  // skip level "/": the trace runs with skipping off
    if (peekIs(Tok::Name)) {
        const std::string u = upper(peek()->text);
        if (u.size() > 1 && u[0] == 'N' && isDigits(std::string_view(u).substr(1))) {
            std::int64_t n = 0;
            std::from_chars(u.data() + 1, u.data() + std::min<std::size_t>(u.size(), 18), n);
            m_p.blockNumbers.emplace_back(n, index);
            ++m_pos;
        }
    } else if (peekIs(Tok::Colon) && peekIs(Tok::Number, 1)) {
        m_pos += 2;  // main block number ":10"
    }
    if (peekIs(Tok::Name) && peekIs(Tok::Colon, 1)) {
        m_p.labels[upper(peek()->text)].push_back(index);
        m_pos += 2;
        if (peekIs(Tok::Name)) {  // LABEL: N20 ...
            const std::string u = upper(peek()->text);
            if (u.size() > 1 && u[0] == 'N' && isDigits(std::string_view(u).substr(1))) {
                std::int64_t n = 0;
                std::from_chars(u.data() + 1, u.data() + std::min<std::size_t>(u.size(), 18), n);
                m_p.blockNumbers.emplace_back(n, index);
                ++m_pos;
            }
        }
    }
    for (std::size_t i = m_pos; i < m_end; ++i) {
        if (m_tokens[i].kind == Tok::Ellipsis) {
            warning(posOf(m_tokens[i]), "the listing is cut here ('...'): the block is left out");
            block.kind = BlockKind::Empty;
            m_p.blocks.push_back(block);
            m_block = nullptr;
            return;
        }
    }
    if (atEnd()) {
        block.kind = BlockKind::Empty;
    } else if (peekIs(Tok::Name) && peek()->text.size() >= 2 &&
               peek()->text.find_first_of("0123456789") == std::string_view::npos) {
        // Statements start with a keyword of letters only; X10 or G1 never is one.
        const std::string keyword = upper(peek()->text);
        if (!parseStatement(block, keyword))
            parseWords(block);
    } else {
        parseWords(block);
    }
    if (block.kind != BlockKind::Proc && block.kind != BlockKind::Empty)
        m_sawProc = true;  // a PROC after this block is misplaced
    if (block.kind == BlockKind::Normal && block.wordCount == 0)
        block.kind = BlockKind::Empty;
    m_p.blocks.push_back(block);
    m_block = nullptr;
}

bool Parser::expectEnd(const Block&)
{
    if (atEnd())
        return true;
    return error(here(), "unexpected '" + std::string(peek()->text) + "' after the statement");
}

bool Parser::parseStatement(Block& block, const std::string& keyword)
{
    const Pos pos = here();
    auto simple = [&](BlockKind kind) {
        block.kind = kind;
        ++m_pos;
        expectEnd(block);
        return true;
    };
    auto condition = [&](BlockKind kind) {
        block.kind = kind;
        ++m_pos;
        if (atEnd())
            return error(pos, keyword + " needs a condition"), true;
        block.expr = parseExpr();
        if (block.expr >= 0)
            expectEnd(block);
        return true;
    };
    if (keyword == "IF") {
        block.kind = BlockKind::If;
        ++m_pos;
        if (atEnd())
            return error(pos, "IF needs a condition"), true;
        block.expr = parseExpr();
        if (block.expr < 0)
            return true;
        if (peekIs(Tok::Name)) {
            const std::string next = upper(peek()->text);
            if (next == "GOTOF" || next == "GOTOB" || next == "GOTO" || next == "GOTOC") {
                const std::int32_t cond = block.expr;
                parseGoto(block, next);
                block.expr = cond;
                return true;
            }
        }
        expectEnd(block);
        return true;
    }
    if (keyword == "ELSE")
        return simple(BlockKind::Else);
    if (keyword == "ENDIF")
        return simple(BlockKind::EndIf);
    if (keyword == "WHILE")
        return condition(BlockKind::While);
    if (keyword == "ENDWHILE")
        return simple(BlockKind::EndWhile);
    if (keyword == "REPEAT")
        return simple(BlockKind::Repeat);
    if (keyword == "UNTIL")
        return condition(BlockKind::Until);
    if (keyword == "LOOP")
        return simple(BlockKind::Loop);
    if (keyword == "ENDLOOP")
        return simple(BlockKind::EndLoop);
    if (keyword == "ENDFOR")
        return simple(BlockKind::EndFor);
    if (keyword == "FOR")
        return parseFor(block), true;
    if (keyword == "GOTOF" || keyword == "GOTOB" || keyword == "GOTO" || keyword == "GOTOC")
        return parseGoto(block, keyword), true;
    if (keyword == "PROC")
        return parseProc(block), true;
    if (keyword == "DEF")
        return parseDef(block), true;
    if (keyword == "MCALL") {
        block.kind = BlockKind::MCall;
        ++m_pos;
        if (atEnd())
            return true;  // MCALL alone ends the modal call
        if (!peekIs(Tok::Name))
            return error(here(), "a cycle or subprogram name is expected after MCALL"), true;
        const std::size_t before = m_p.words.size();
        parseWord(block);
        if (m_p.words.size() == before || block.bad)
            return true;
        const Word& w = m_p.words.back();
        if (w.kind != WordKind::Cycle && w.kind != WordKind::Call)
            return error(w.pos, "MCALL needs a cycle or a subprogram"), true;
        block.code = w.kind == WordKind::Cycle ? w.code : -1;
        expectEnd(block);
        return true;
    }
    return false;
}

bool Parser::parseFor(Block& block)
{
    block.kind = BlockKind::For;
    const Pos pos = here();
    ++m_pos;
    if (!peekIs(Tok::Name))
        return error(here(), "FOR needs a variable");
    const Token& var = *peek();
    const std::string u = upper(var.text);
    if (const LocalVar* local = findLocal(u)) {
        block.forSlot = local->slot;
    } else if (u.size() > 1 && u[0] == 'R' && isDigits(std::string_view(u).substr(1)) && u.size() <= 4) {
        std::from_chars(u.data() + 1, u.data() + u.size(), block.forSlot);
        block.forIsR = true;
    } else {
        return error(posOf(var), "unknown variable " + std::string(var.text) + " in FOR");
    }
    ++m_pos;
    if (!peekIs(Tok::Assign))
        return error(here(), "'=' expected after the FOR variable");
    ++m_pos;
    block.expr = parseExpr();
    if (block.expr < 0)
        return false;
    if (!peekName("TO"))
        return error(atEnd() ? pos : here(), "TO expected in FOR");
    ++m_pos;
    block.expr2 = parseExpr();
    if (block.expr2 < 0)
        return false;
    return expectEnd(block);
}

bool Parser::parseGoto(Block& block, const std::string& keyword)
{
    block.kind = BlockKind::Goto;
    block.gotoDir = keyword == "GOTOF"   ? GotoDir::Forward
                    : keyword == "GOTOB" ? GotoDir::Backward
                    : keyword == "GOTO"  ? GotoDir::Both
                                         : GotoDir::BothNoAlarm;
    ++m_pos;
    std::string label;
    if (peekIs(Tok::Name)) {
        label = upper(peek()->text);
        ++m_pos;
    } else if (peekIs(Tok::Number)) {
        label = "N" + std::string(peek()->text);
        ++m_pos;
    } else {
        return error(here(), keyword + " needs a label or block number");
    }
    block.text = addText(label);
    m_gotos.emplace_back(static_cast<std::int32_t>(m_p.blocks.size()), label);
    return expectEnd(block);
}

}  // namespace camwb::nc::sinumerik
