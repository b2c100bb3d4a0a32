0 BEGIN PGM MALFORMED MM
1 ; every block with a word the control cannot read is left out: no axis moves on a guess
2 TOOL CALL 1 Z S3000
3 L X+0 Y+0 Z+5 R0 F200 M3
4 L X+ZZ Y+10
5 L X+1.2.3 Y+20
6 L X+-3 Y+30
7 L X+7 Y
8 L X+40 QQ+5
9 L X+50 Y+50 DR+
10 L X+60 Y+60 M
11 L X+70 Y+70
12 L Z+50 FMAX M30
13 END PGM MALFORMED MM
