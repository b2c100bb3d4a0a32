0 BEGIN PGM PLANES MM
1 ; circles in the three main planes: the axes of CC name the plane, DR+ turns by the
2 ; right-hand rule about +Z (XY), +Y (ZX) and +X (YZ); polar angles count from X, Z and Y
3 TOOL CALL 1 Z S3000
4 L X+10 Y+0 Z+0 R0 FMAX M3
5 ; ZX: a quarter DR+ from X+10 ends at Z-10, then back DR-, then three quarters DR+
6 CC X+0 Z+0
7 C X+0 Z-10 DR+ F200
8 C X+10 Z+0 DR-
9 C X+0 Z+10 DR+
10 ; ZX with CR (short and long arc) and CT tangent to the arc before it
11 CR X+10 Z+0 R+10 DR-
12 CR X+0 Z-10 R-10 DR-
13 CT X-10 Z-20
14 ; ZX helix: three laps, 3 mm along Y
15 L X+10 Y+0 Z+0 FMAX
16 CC X+0 Z+0
17 CP IPA+1080 IY-3 DR+
18 ; ZX polar line: PA 0 points along +Z
19 LP PR+5 PA+0
20 ; YZ: a quarter DR+ from Y+10 ends at Z+10, a full circle, a helix along X
21 L X+0 Y+10 Z+0 FMAX
22 CC Y+0 Z+0
23 C Y+0 Z+10 DR+
24 C Y+0 Z+10 DR-
25 CP IPA-450 IX+2 DR-
26 ; YZ CR back to Y+0 Z+10
27 CR Y+0 Z+10 R+10 DR+
28 ; XY again: a multi-turn helix ends exactly where it began in the plane
29 L X+10 Y+0 Z+0 FMAX
30 CC X+0 Y+0
31 CP IPA+1080 IZ-3 DR+
32 C X+0 Y+10 DR+
33 ; a CR whose two axes are X and Z is in ZX, whatever the last CC: a half circle up to Z+7
34 CR X+0 Z+7 R+5 DR-
35 L Z+50 FMAX
36 L M30
37 END PGM PLANES MM
