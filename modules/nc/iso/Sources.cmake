# Sources of the iso interpreter, relative to this folder.
set(NC_PART_SOURCES
    IsoArcs.cpp
    IsoBlock.h
    IsoControlFlow.cpp
    IsoCycles.cpp
    IsoExpression.cpp
    IsoInterpreter.cpp
    IsoMachine.cpp
    IsoMachine.h
    IsoMotion.cpp
    IsoNumber.h
    IsoParameters.cpp
    IsoParameters.h
    IsoProgram.h
    IsoReporter.h
    IsoScanner.cpp
    IsoScanner.h)
