// The block parser's internals, shared by its translation units: the token cursor of one logical
// block, expression parsing (ExprParser.cpp), words and statements (Parser.cpp).
#pragma once

#include "nc/sinumerik/Lexer.h"
#include "nc/sinumerik/Program.h"

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

namespace camwb::nc::sinumerik {

struct LocalVar {
    std::int32_t slot = 0;
    std::int32_t size = 1;  // array elements, 1 for a scalar
    std::int32_t dim2 = 0;  // second dimension of a 2-D array (0: 1-D)
    std::uint8_t type = 0;
};

class Parser {
public:
    Parser(Program& program) : m_p(program) {}
    void run();

private:
    // Cursor over the current logical block.
    const Token* peek(std::size_t ahead = 0) const
    {
        return m_pos + ahead < m_end ? &m_tokens[m_pos + ahead] : nullptr;
    }
    bool atEnd() const { return m_pos >= m_end; }
    bool peekIs(Tok kind, std::size_t ahead = 0) const
    {
        const Token* t = peek(ahead);
        return t && t->kind == kind;
    }
    bool peekName(std::string_view upperName, std::size_t ahead = 0) const;
    Pos posOf(const Token& t) const { return {t.line, t.column}; }
    Pos here() const;

    // Diagnostics: error() marks the block bad and returns false so callers can `return error(..)`.
    bool error(Pos pos, std::string message);
    void warning(Pos pos, std::string message);
    void addDiagnostic(Diagnostic d);

    // Logical blocks.
    void parseBlock();
    bool parseStatement(Block& block, const std::string& keyword);
    bool parseWords(Block& block);
    bool parseWord(Block& block);
    bool badToken(const Token& t);
    std::optional<bool> parseNumberWord(Block& block, const Token& t);
    bool parseAssignment(Block& block, const Token& t, const std::string& upperName);
    bool parseRAssignment(Block& block, const Token& t, const std::string& upperName);
    std::optional<bool> parseIndexedAssignment(Block& block, const Token& t, const std::string& upperName);
    bool parseToolDataAssignment(Block& block, const Token& t, const std::string& upperName);
    bool finishIndexedAssignment(Block& block, Word& w);
    bool parseCallWord(Block& block, const Token& t, const std::string& upperName);
    bool parseMsg(Block& block, Pos pos);
    bool parseRepetitions(Block& block);
    std::optional<bool> parseKeyword(Block& block, const Token& t, const std::string& upperName);
    std::optional<bool> parseAddress(Block& block, const Token& t, const std::string& upperName,
                                     std::string_view letters, std::string_view digits);
    bool parseNameCall(Block& block, const Token& t, const std::string& upperName);
    bool parseSpacedAddress(Block& block, const Token& name);
    bool parseGlued(Block& block, const Token& name, const std::string& upperName);
    bool parseAddressValue(Block& block, WordKind kind, std::uint8_t index, const Token& name, bool allowMode);
    bool parseCallArgs(Block& block);
    bool parseDef(Block& block);
    bool parseProc(Block& block);
    bool parseFor(Block& block);
    bool parseGoto(Block& block, const std::string& keyword);
    bool expectEnd(const Block& block);
    void matchFlow();
    std::int32_t addText(std::string_view text);
    Word& addWord(Block& block, WordKind kind, Pos pos);

    // Expressions (ExprParser.cpp): node index, -1 after an error (already reported).
    std::int32_t parseExpr(int depth = 0);
    std::int32_t parseLevel(int level, int depth);
    std::int32_t parseUnary(int depth);
    std::int32_t parsePrimary(int depth);
    std::int32_t parseNameOperand(const Token& name, int depth);
    std::int32_t node(Op op, Pos pos, std::int32_t a = -1, std::int32_t b = -1);
    std::int32_t constant(double value, Pos pos);
    const LocalVar* findLocal(std::string_view upperName) const;
    // Element index of local array `var` from `[i]` / `[i,j]` after the name, -1 on error.
    std::int32_t parseElement(const LocalVar& var, int depth);

    Program& m_p;
    std::vector<Token> m_tokens;
    std::size_t m_pos = 0, m_end = 0;
    Block* m_block = nullptr;
    std::unordered_map<std::string, LocalVar> m_locals;
    std::string m_upper;  // scratch for upper-casing names
    bool m_sawProc = false;
    std::vector<std::pair<std::int32_t, std::string>> m_gotos;  // block index, label: checked at the end
};

// Word classes shared by the word parsers (Words.cpp, Assignments.cpp); names in upper case.
int axisIndex(std::string_view upperName);    // X Y Z A B C: 0..5, else -1
int centreIndex(std::string_view upperName);  // I J K: 0..2, else -1
bool isAddressLetter(std::string_view upperName);
bool isPassiveKeyword(std::string_view upperName);  // recognised, nothing to trace
bool isFrameKeyword(std::string_view upperName);
double numberOf(std::string_view digits);  // out of range: 1e300, which the range check reports

// Splits "X10.5" into "X" and "10.5"; false when the name is not letters followed by a number.
bool splitAddress(std::string_view upperName, std::string_view& letters, std::string_view& digits);

}  // namespace camwb::nc::sinumerik
