0 BEGIN PGM RNDARC MM
1 ; roundings next to circles: a line into a circle (left turn) and the circle into a line (right turn)
2 TOOL CALL 2 Z S5000
3 L X+0 Y+0 Z-2 R0 FMAX M3
4 L X+10 Y+0 F300
5 RND R2
6 CC X+20 Y+0
7 C X+20 Y+10 DR-
8 RND R1 F120
9 L X+30 Y+0
10 L Z+50 FMAX
11 L M30
12 END PGM RNDARC MM
