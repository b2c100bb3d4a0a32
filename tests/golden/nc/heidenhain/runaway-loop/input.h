0 BEGIN PGM RUNAWAY MM
1 ; a loop whose exit condition can never hold (Q1 steps over 10): stopped by the block budget
2 TOOL CALL 1 Z S1000
3 L X+0 Y+0 Z+5 R0 FMAX M3
4 Q1 = 0
5 LBL "LOOP"
6 Q1 = Q1 + 3
7 L X+Q1 F500
8 FN 10: IF +Q1 NE +10 GOTO LBL "LOOP"
9 L M30
10 END PGM RUNAWAY MM
