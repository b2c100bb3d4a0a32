// DEF variables and PROC parameters (local slots of the program), and the matching of IF/ELSE/
// ENDIF, WHILE, REPEAT/UNTIL, FOR and LOOP into jump targets once the whole file is read.
#include "nc/sinumerik/ParserImpl.h"

#include <algorithm>

namespace camwb::nc::sinumerik {

bool Parser::parseDef(Block& block)
{
    ++m_pos;
    if (!peekIs(Tok::Name))
        return error(here(), "DEF needs a type (REAL, INT, BOOL)");
    const std::string type = upper(peek()->text);
    const Pos typePos = here();
    std::uint8_t typeCode = 0;
    if (type == "REAL")
        typeCode = 0;
    else if (type == "INT" || type == "CHAR")
        typeCode = 1;
    else if (type == "BOOL")
        typeCode = 2;
    else if (type == "STRING" || type == "AXIS" || type == "FRAME")
        return warning(typePos, "DEF " + type + " variables are not traced: the block is left out"),
               block.kind = BlockKind::Empty, m_pos = m_end, true;
    else
        return error(typePos, "unknown type " + std::string(peek()->text) + " in DEF");
    ++m_pos;
    for (;;) {
        if (!peekIs(Tok::Name))
            return error(here(), "a variable name is expected");
        const Token& name = *peek();
        const std::string u = upper(name.text);
        std::string_view l, d;
        if (isAddressLetter(u) || (splitAddress(u, l, d) && (l == "R" || isAddressLetter(l))) || u == "CR" ||
            u == "AR" || u == "TURN" || u == "LIMS")
            return error(posOf(name), u + " is an address of the control, not a variable name");
        if (m_locals.count(u))
            return error(posOf(name), "variable " + std::string(name.text) + " is defined twice");
        ++m_pos;
        LocalVar var;
        var.type = typeCode;
        if (peekIs(Tok::LBracket)) {
            ++m_pos;
            std::int64_t dims[2] = {0, 0};
            int count = 0;
            while (count < 2 && peekIs(Tok::Number)) {
                dims[count++] = static_cast<std::int64_t>(peek()->number);
                ++m_pos;
                if (peekIs(Tok::Comma))
                    ++m_pos;
            }
            if (!peekIs(Tok::RBracket) || count == 0 || dims[0] < 1 || (count == 2 && dims[1] < 1))
                return error(here(), "array sizes as numbers in [ ] expected");
            ++m_pos;
            const std::int64_t size = count == 2 ? dims[0] * dims[1] : dims[0];
            if (size > 100000 || m_p.localSlots + size > 100'000)
                return error(posOf(name), "array too large");
            var.size = static_cast<std::int32_t>(size);
            var.dim2 = count == 2 ? static_cast<std::int32_t>(dims[1]) : 0;
        }
        if (m_p.localSlots + var.size > 100'000)
            return error(posOf(name), "too many variables");
        var.slot = m_p.localSlots;
        m_p.localSlots += var.size;
        m_p.slotType.insert(m_p.slotType.end(), static_cast<std::size_t>(var.size), typeCode);
        m_locals.emplace(u, var);
        if (peekIs(Tok::Assign)) {
            ++m_pos;
            if (var.size > 1)
                return error(here(), "array initial values are not supported");
            Word w;
            w.kind = WordKind::Assign;
            w.target = AssignTarget::Local;
            w.code = var.slot;
            w.pos = posOf(name);
            w.expr = parseExpr();
            if (w.expr < 0)
                return false;
            addWord(block, WordKind::Assign, w.pos) = w;
        }
        if (peekIs(Tok::Comma)) {
            ++m_pos;
            continue;
        }
        return expectEnd(block);
    }
}

bool Parser::parseProc(Block& block)
{
    block.kind = BlockKind::Proc;
    const Pos pos = here();
    ++m_pos;
    if (!peekIs(Tok::Name))
        return error(here(), "PROC needs a name");
    if (!m_p.procName.empty())
        return error(pos, "a second PROC in one file (one program per file)");
    if (m_sawProc)
        warning(pos, "PROC is not the first block of the program");
    m_p.procName = upper(peek()->text);
    m_p.procPos = posOf(*peek());
    ++m_pos;
    if (peekIs(Tok::LParen)) {
        ++m_pos;
        while (!atEnd() && !peekIs(Tok::RParen)) {
            if (!peekIs(Tok::Name))
                return error(here(), "a parameter type is expected");
            std::string type = upper(peek()->text);
            ++m_pos;
            if (type == "VAR" && peekIs(Tok::Name)) {
                type = upper(peek()->text);
                ++m_pos;
            }
            if (!peekIs(Tok::Name))
                return error(here(), "a parameter name is expected");
            const std::string name = upper(peek()->text);
            if (m_locals.count(name))
                return error(here(), "parameter " + name + " is declared twice");
            LocalVar var;
            var.type = type == "INT" || type == "CHAR" ? 1 : type == "BOOL" ? 2 : 0;
            var.slot = m_p.localSlots++;
            m_p.slotType.push_back(var.type);
            m_locals.emplace(name, var);
            m_p.procParams.push_back(var.slot);
            ++m_pos;
            if (peekIs(Tok::Comma))
                ++m_pos;
        }
        if (!peekIs(Tok::RParen))
            return error(here(), "unbalanced parentheses in the PROC parameters");
        ++m_pos;
    }
    m_pos = m_end;  // SAVE, DISPLOF, SBLOF ...: attributes the trace does not need
    return true;
}

void Parser::matchFlow()
{
    struct Open {
        BlockKind kind;
        std::int32_t index;
    };
    std::vector<Open> stack;
    auto opener = [](BlockKind closer) {
        switch (closer) {
        case BlockKind::Else:
        case BlockKind::EndIf:
            return BlockKind::If;
        case BlockKind::EndWhile:
            return BlockKind::While;
        case BlockKind::Until:
            return BlockKind::Repeat;
        case BlockKind::EndFor:
            return BlockKind::For;
        case BlockKind::EndLoop:
            return BlockKind::Loop;
        default:
            return BlockKind::Empty;
        }
    };
    auto name = [](BlockKind k) -> std::string {
        switch (k) {
        case BlockKind::If:
            return "IF";
        case BlockKind::Else:
            return "ELSE";
        case BlockKind::EndIf:
            return "ENDIF";
        case BlockKind::While:
            return "WHILE";
        case BlockKind::EndWhile:
            return "ENDWHILE";
        case BlockKind::Repeat:
            return "REPEAT";
        case BlockKind::Until:
            return "UNTIL";
        case BlockKind::For:
            return "FOR";
        case BlockKind::EndFor:
            return "ENDFOR";
        case BlockKind::Loop:
            return "LOOP";
        case BlockKind::EndLoop:
            return "ENDLOOP";
        default:
            return "?";
        }
    };
    auto closerOf = [](BlockKind open) {
        switch (open) {
        case BlockKind::If:
        case BlockKind::Else:
            return "ENDIF";
        case BlockKind::While:
            return "ENDWHILE";
        case BlockKind::Repeat:
            return "UNTIL";
        case BlockKind::For:
            return "ENDFOR";
        default:
            return "ENDLOOP";
        }
    };
    for (std::int32_t i = 0; i < static_cast<std::int32_t>(m_p.blocks.size()); ++i) {
        Block& b = m_p.blocks[i];
        switch (b.kind) {
        case BlockKind::If:
        case BlockKind::While:
        case BlockKind::Repeat:
        case BlockKind::For:
        case BlockKind::Loop:
            if (stack.size() >= 10000) {
                addDiagnostic({Severity::Error, m_p.path, b.line, 0, "control structures nested too deeply"});
                b.kind = BlockKind::Bad;
                break;
            }
            stack.push_back({b.kind, i});
            break;
        case BlockKind::Else:
        case BlockKind::EndIf:
        case BlockKind::EndWhile:
        case BlockKind::Until:
        case BlockKind::EndFor:
        case BlockKind::EndLoop: {
            const BlockKind want = opener(b.kind);
            auto match = std::find_if(stack.rbegin(), stack.rend(), [&](const Open& o) {
                return o.kind == want || (want == BlockKind::If && o.kind == BlockKind::Else);
            });
            if (match == stack.rend()) {
                addDiagnostic({Severity::Error, m_p.path, b.line, 0, name(b.kind) + " without " + name(want)});
                b.kind = BlockKind::Bad;
                break;
            }
            while (&stack.back() != &*match) {
                const Block& open = m_p.blocks[stack.back().index];
                addDiagnostic({Severity::Error, m_p.path, open.line, 0,
                               name(open.kind) + " without " + closerOf(stack.back().kind)});
                m_p.blocks[stack.back().index].kind = BlockKind::Bad;
                stack.pop_back();
            }
            Block& open = m_p.blocks[stack.back().index];
            const std::int32_t openIndex = stack.back().index;
            stack.pop_back();
            if (b.kind == BlockKind::Else) {
                if (open.kind == BlockKind::Else) {
                    addDiagnostic({Severity::Error, m_p.path, b.line, 0, "a second ELSE for one IF"});
                    b.kind = BlockKind::Bad;
                    stack.push_back({BlockKind::Else, openIndex});
                    break;
                }
                open.jump = i;  // IF false: continue after ELSE
                stack.push_back({BlockKind::Else, i});
            } else {
                open.jump = i;
                b.jump = openIndex;
            }
            break;
        }
        default:
            break;
        }
    }
    for (const Open& o : stack) {
        Block& open = m_p.blocks[o.index];
        addDiagnostic({Severity::Error, m_p.path, open.line, 0, name(open.kind) + " without " + closerOf(o.kind)});
        open.kind = BlockKind::Bad;
    }
}

}  // namespace camwb::nc::sinumerik
