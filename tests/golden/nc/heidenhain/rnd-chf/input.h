0 BEGIN PGM CORNERS MM
1 ; a 60 x 40 rectangle with a R5 rounding, a 4 mm chamfer and a R10 rounding (F only in its block)
2 TOOL CALL 2 Z S5000
3 L X-10 Y+0 Z+2 R0 FMAX M3
4 L Z-3 F150
5 L X+0 Y+0 RL F400
6 L X+60
7 RND R5
8 L Y+40
9 CHF 4
10 L X+0
11 RND R10 F100
12 L Y+0
13 L X-10 R0
14 L Z+50 FMAX
15 L M30
16 END PGM CORNERS MM
