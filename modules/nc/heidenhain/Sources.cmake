# Sources of the heidenhain interpreter, relative to this folder.
set(NC_PART_SOURCES
    HeidenhainInterpreter.cpp
    Lexer.cpp
    Lexer.h
    Program.h
    Expression.cpp
    Expression.h
    Geometry.cpp
    Geometry.h
    Parser.cpp
    Parser.h
    ParserWords.cpp
    Machine.cpp
    Machine.h
    MachineFunctions.cpp
    Contour.cpp
    Cycles.cpp)
