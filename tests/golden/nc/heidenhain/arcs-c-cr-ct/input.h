0 BEGIN PGM ARCS MM
1 TOOL CALL 1 Z S3000
2 L X+0 Y+0 Z+2 R0 FMAX M3
3 L Z-2 F100
4 ; C about CC: a quarter counter-clockwise, then clockwise back
5 CC X+0 Y+20
6 L Y+0 F300
7 C X+20 Y+20 DR+
8 C X+0 Y+0 DR-
9 ; CR: short and long arcs of radius 25 over a chord of 40
10 CR X+40 Y+0 R+25 DR+
11 CR X+0 Y+0 R-25 DR+
12 ; CT: tangent to the line before it, then to the arc
13 L X+20 Y+0
14 CT X+40 Y+20
15 CT X+60 Y+40
16 ; full circle with C
17 CC X+50 Y+40
18 C X+60 Y+40 DR-
19 L Z+50 FMAX
20 L M30
21 END PGM ARCS MM
