0 BEGIN PGM MCVL MM
1 ; what the MAS MCVL 1000 (resources/machines/mas-mcvl1000.json) cannot do: 8000 rpm on its
2 ; 7500 rpm spindle, a cut at 1.5 mm/min under its 2 mm/min, 13000 mm/min over its 12000,
3 ; 1100 mm of X on its 1016 mm travel. B-30 C+355 turn its table: without TCPM X Y Z stay the machine's axes and the tip moves in the turned part
4 BLK FORM 0.1 Z X+0 Y+0 Z-20
5 BLK FORM 0.2 X+1100 Y+100 Z+0
6 TOOL CALL 1 Z S8000
7 L X+0 Y+0 R0 FMAX M3
8 L Z+5 R0 FMAX
9 L C+355 B-30 FMAX
10 L Z-2 R0 F1.5
11 L X+1100 R0 F13000
12 L Y+100 R0 F12000
13 L X+0 R0 F2
14 L Z+50 R0 FMAX
15 L M30
16 END PGM MCVL MM
