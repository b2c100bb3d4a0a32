0 BEGIN PGM COMPERR MM
1 ; what compensation cannot do: the diagnostics say so, the trace follows what was programmed
2 TOOL DEF 1 L+40 R+4
3 TOOL CALL 1 Z S3000
4 L X+0 Y+0 Z+5 R0 FMAX
5 ; an inside arc smaller than the tool
6 L X+0 Y-20 F200
7 L X+10 Y-20 RL
8 CR X+10 Y-14 R+3 DR+
9 L X+0 Y-14
10 L X+0 Y-30 R0
11 ; leaving on a circle
12 L X+20 Y-30 RR
13 CR X+30 Y-20 R+10 DR+ R0
14 ; starting on a circle: the TNC takes RL/RR in a straight-line block only
15 L X+40 Y-30 F200
16 CR X+50 Y-20 R+10 DR+ RL
17 L X+60 Y-20
18 L X+60 Y-10 R0
19 ; no radius known for tool 3 (neither TOOL DEF nor the tool table)
20 TOOL CALL 3 Z S2000
21 L X+60 Y-10 RL
22 L X+70 Y+0 R0
23 L Z+20 FMAX M30
24 END PGM COMPERR MM
