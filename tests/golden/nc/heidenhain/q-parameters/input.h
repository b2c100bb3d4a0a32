0 BEGIN PGM QPARAM MM
1 ; a bolt circle of Q3 holes on radius Q2 about (Q10, Q11), computed with formulas and FN jumps
2 FN 0: Q2 = +25
3 FN 0: Q3 = +5
4 Q10 = 50
5 Q11 = 40
6 Q4 = 360 / Q3
7 FN 0: Q5 = +0
8 Q1 = 0
9 TOOL CALL 6 Z S2500
10 L Z+10 R0 FMAX M3
11 LBL 1
12 Q20 = Q10 + Q2 * COS Q5
13 Q21 = Q11 + Q2 * SIN(Q5)
14 L X+Q20 Y+Q21 FMAX
15 L Z-3 F100
16 L Z+2 FMAX
17 FN 1: Q5 = +Q5 + +Q4
18 FN 1: Q1 = +Q1 + +1
19 FN 12: IF +Q1 LT +Q3 GOTO LBL 1
20 ; a square root and a power for good measure: X = sqrt(9^2 + 40) = 11
21 Q30 = SQRT (9 ^ 2 + 40)
22 FN 4: Q31 = +Q30 DIV +2
23 L X+Q30 Y+Q31 FMAX
24 L M30
25 END PGM QPARAM MM
