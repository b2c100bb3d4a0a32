0 BEGIN PGM HELIX MM
1 ; helical entry with CP: three laps of 2 mm, then a finishing circle and a half circle
2 TOOL CALL 4 Z S6000
3 CC X+50 Y+50
4 L X+60 Y+50 Z+2 R0 FMAX M3
5 CP IPA+1080 IZ-6 DR+ F250
6 CP IPA+360 DR+
7 CP PA+180 DR+
8 CP IPA-450 Z-8 DR-
9 L Z+50 FMAX
10 L M30
11 END PGM HELIX MM
