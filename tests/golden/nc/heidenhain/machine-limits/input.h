0 BEGIN PGM LIMITS MM
1 ; what the test mill of tests/golden/machines cannot do
2 ; 9000 rpm on an 8000 rpm spindle, 320 mm of X, 3500 mm/min, cutting after TOOL CALL 0
3 BLK FORM 0.1 Z X+0 Y+0 Z-20
4 BLK FORM 0.2 X+320 Y+100 Z+0
5 TOOL CALL 3 Z S9000
6 L Z+5 R0 FMAX M3
7 L X+0 Y+0 R0 FMAX
8 L Z-2 R0 F300
9 L X+320 R0 F3500
10 L Y+50 R0 F800
11 L Z+50 R0 FMAX
12 TOOL CALL 0
13 L X+10 R0 F100
14 END PGM LIMITS MM
