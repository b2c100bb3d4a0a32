0 BEGIN PGM COMP MM
1 ; radius compensation on a TNC: R from TOOL DEF plus DR of TOOL CALL, the tool square to the
2 ; first contour element, transition arcs around outside corners, inside corners trimmed,
3 ; RND roundings and circles offset like any element; tool 2's radius from tools.tbl
4 TOOL DEF 1 L+40 R+3
5 TOOL CALL 1 Z S3000 DR-0.1
6 L X-20 Y-20 Z+5 R0 FMAX M3
7 L Z-2 F100
8 L X+0 Y-10 RR F400
9 L Y+40
10 CR X+10 Y+50 R+10 DR-
11 L X+60
12 RND R5
13 L Y+0
14 L X+30
15 CR X+20 Y-10 R+10 DR+
16 L X+0
17 L X-20 Y-20 R0
18 L Z+20 FMAX
19 TOOL CALL 2 Z S2500
20 L X+100 Y+20 R0 FMAX
21 L Z-3 F80
22 L X+100 Y+0 RL F300
23 L X+130
24 L Y+30
25 CC X+120 Y+30
26 C X+120 Y+40 DR+
27 L X+90
28 L Y+0
29 L X+100
30 L Y+20 R0
31 L Z+20 FMAX M30
32 END PGM COMP MM
