0 BEGIN PGM FIVECONE MM
1 ; a five-axis path for the pictures: the tip on a circle of radius 40, the tool tilted 20 degrees
2 ; outwards all the way round (B-20, C following the circle), with M128 on the MAS MCVL 1000
3 BLK FORM 0.1 Z X-50 Y-50 Z-20
4 BLK FORM 0.2 X+50 Y+50 Z+0
5 TOOL CALL 1 Z S6000
6 L X+0 Y+0 Z+100 R0 FMAX M3
7 M126
8 L X+40 Y+0 Z+20 B-20 C+0 FMAX M128
9 L Z+0 F300
10 Q1 = 0
11 LBL 1
12 Q1 = Q1 + 5
13 Q2 = 40 * COS Q1
14 Q3 = 40 * SIN Q1
15 Q4 = -Q1
16 L X+Q2 Y+Q3 Z+0 B-20 C+Q4 F1000
17 FN 12: IF +Q1 LT +360 GOTO LBL 1
18 LBL 0
19 L Z+50 FMAX
20 L B+0 C+0 FMAX M129
21 L M30
22 END PGM FIVECONE MM
