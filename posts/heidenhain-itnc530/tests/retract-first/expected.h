0 BEGIN PGM input MM
1 ;MACHINE: MAS MCVL 1000
2 ;CONTROL: HEIDENHAIN iTNC530 Dialog
3 ;POST: heidenhain-itnc530
4 ;POST VERSION: 0.1.0
5 ;PROGRAMMER: GOLDEN
6 ;PROJECT: input
7 ;DATE: 1.1.2026
8 ;TIME: 00:00:00
9 ;
10 BLK FORM 0.1 Z X+6 Y-20 Z-1.5
11 BLK FORM 0.2 X+40 Y+10 Z+20
12 M135 M126
13 ; MACHINING TIME: 000:00:24
14 ;=====
15 ;..... TOOL LIST .....
16 ;T01 - FLAT END MILL D0 R0
17 ;=====
18 ;This output produced with the dump post processor
19 ;Dump is useful for inspecting the raw commands in your paths
20 ;but is not useful for driving machines.
21 ;Consider setting a default postprocessor in your project or
22 ;exporting your paths using a specific post that matches your machine
23 ;=====
24 ; OPERATION: TC: 6mm Endmill
25 ;=====
26 ; *****
27 ; TOOL: T1 D0 R0 L0 DB0 Z2
28 ; TYPE: FLAT END MILL
29 ; *****
30 TOOL CALL 1 Z S4000
31 L M3
32 ;=====
33 ; OPERATION: Profile
34 ;=====
35 L Z+20 R0 FMAX
36 L X+6 Y-20 R0 FMAX
37 L Z+3 R0 FMAX
38 L Z-1.5 F120
39 L X+40 F360
40 L Y+10
41 L X+6
42 L Y-20
43 L Z+20 R0 FMAX
44 L M30
45 ; Xmin = 6
46 ; Xmax = 40
47 ; Ymin = -20
48 ; Ymax = 10
49 ; Zmin = -1.5
50 ; Zmax = 20
51 END PGM input MM
