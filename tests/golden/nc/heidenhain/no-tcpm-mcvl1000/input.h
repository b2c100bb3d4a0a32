0 BEGIN PGM NOTCPM MM
1 ; Without TCPM on the MAS MCVL 1000: X Y Z B C are the machine's axes about MRZP (the datum),
2 ; and the tip in the workpiece frame is Q = X.P (seed 000 eq. 20), for B+30 C+40:
3 ; P = (10, 0, 0) -> Q = (cC.cB.10, -sC.cB.10, sB.10) = (6.6341, -5.5667, 5.0000)
4 ; P = (0, 10, 0) -> Q = (sC.10, cC.10, 0) = (6.4279, 7.6604, 0.0000)
5 ; P = (0, 0, 10) -> Q = (-cC.sB.10, sC.sB.10, cB.10) = (-3.8302, 3.2139, 8.6603) = 10 K
6 ; C+90 turns the part -90 degrees about Z: the machine's circle from (10, 0) to (0, 10) about
7 ; the origin is the part's from (0, -10) to (10, 0)
8 TOOL CALL 1 Z S3000
9 L X+10 Y+0 Z+0 R0 B+30 C+40 FMAX M3
10 L X+0 Y+10 Z+0 F500
11 L X+0 Y+0 Z+10
12 L X+0 Y+0 Z+100 B+0 C+0 FMAX
13 L X+10 Y+0 Z+0 C+90 FMAX
14 CC X+0 Y+0
15 C X+0 Y+10 DR+ F500
16 L Z+100 C+0 FMAX
17 L X+50 FMAX
18 L M30
19 END PGM NOTCPM MM
