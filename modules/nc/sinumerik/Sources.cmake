# Sources of the sinumerik interpreter, relative to this folder.
set(NC_PART_SOURCES
    SinumerikInterpreter.cpp
    Lexer.cpp
    Parser.cpp
    ExprParser.cpp
    Words.cpp
    Assignments.cpp
    Declarations.cpp
    Machine.cpp
    Evaluate.cpp
    Execute.cpp
    ExecuteWords.cpp
    Arcs.cpp
    Cycles.cpp
    Rotary.cpp
    Swivel.cpp)
