0 BEGIN PGM X INCH
1 ; an inch program: coordinates in inches, F in 1/10 inch/min (F+Q601 too), a ZX circle
2 TOOL CALL 1 Z S3500
3 L X+1.5 Y-2 Z+1 R0 FMAX M3
4 Q601=100
5 L X+2 F+Q601
6 CC X+1 Z+1
7 C X+1 Z+0 DR+ F50
8 L Z+6 FMAX
9 L M30
10 END PGM X INCH
