0 BEGIN PGM M128 MM
1 ; M128 on the MAS MCVL 1000 (B/C table: B about +Y, C about +Z, both through MRZP, the datum):
2 ; X Y Z are the tool tip in the workpiece frame, B and C the machine's. Seed 000 eq. 14:
3 ; K = (-cos C * sin B, sin C * sin B, cos B); B+30 C+40 gives (-0.3830, 0.3214, 0.8660),
4 ; C+130 gives (0.3214, 0.3830, 0.8660); B+0 gives +Z whatever C is
5 TOOL CALL 1 Z S3000
6 L X+0 Y+0 Z+100 R0 FMAX M3
7 L X+10 Y+20 Z+50 B+30 C+40 FMAX M128
8 L Z+5 F300
9 L X+30 F900
10 L C+130 F900
11 L Z+50 B+0 C+0 FMAX
12 L Z+100 FMAX M129
13 L M30
14 END PGM M128 MM
