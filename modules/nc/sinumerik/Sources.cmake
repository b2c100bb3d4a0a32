# Sources of the sinumerik interpreter, relative to this folder.
set(NC_PART_SOURCES
    SinumerikInterpreter.cpp
    Lexer.cpp
    Parser.cpp
    ExprParser.cpp
    Words.cpp
    Declarations.cpp
    Machine.cpp
    Evaluate.cpp
    Execute.cpp
    Arcs.cpp
    Cycles.cpp)
