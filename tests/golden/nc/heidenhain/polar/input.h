0 BEGIN PGM POLAR MM
1 ; a hexagon with polar lines about the pole CC
2 TOOL CALL 5 Z S4000
3 CC X+30 Y+30
4 LP PR+20 PA+0 R0 FMAX M3
5 L Z-2 F100
6 LP PA+60 F300
7 LP IPA+60
8 LP IPA+60
9 LP IPA+60
10 LP IPA+60
11 LP IPA+60
12 ; then outwards by 5 along the same angle and back
13 LP IPR+5
14 LP PR+20 PA+0
15 L Z+50 FMAX
16 L M30
17 END PGM POLAR MM
