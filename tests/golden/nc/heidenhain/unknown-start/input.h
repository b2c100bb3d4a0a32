0 BEGIN PGM START MM
1 ; the control knows no axis at the start until a block gives it in absolute terms
2 TOOL CALL 1 Z S3000
3 L Z+20 R0 FMAX M3
4 L IX+10 FMAX
5 CC X+5 Y+0
6 C X+10 Y+0 DR- F300
7 L X+0 FMAX
8 L Y+0 FMAX
9 L Z-1 F300
10 C X+10 Y+0 DR-
11 L IZ+21 FMAX
12 END PGM START MM
