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
10 BLK FORM 0.1 Z X-63 Y-60 Z-5
11 BLK FORM 0.2 X+50 Y+29 Z+50
12 M135 M126
13 ; MACHINING TIME: 000:00:36
14 ;=====
15 ;..... TOOL LIST .....
16 ;T03 - FLAT END MILL D10 R0
17 ;=====
18 ;-----------------------------------------------------------------
19 ;Generated on Monday, April 08, 2024 09:12:33 AM
20 ;CATIA APT VERSION 1.0
21 ;-----------------------------------------------------------------
22 ;Manufacturing Program.1
23 ;Part Operation.1
24 ;*CATIA0
25 ;Manufacturing Program.1
26 ;1.00000  0.00000  0.00000  0.00000
27 ;0.00000  1.00000  0.00000  0.00000
28 ;0.00000  0.00000  1.00000  0.00000
29 ;Part Operation.1
30 L M8 ;Flood coolant
31 ;=====
32 ; OPERATION: Tool Change.1
33 ;=====
34 ;Start generation of : Tool Change.1
35 ;TOOLCHANGEBEGINNING
36 ;T3 End Mill D 10
37 ; *****
38 ; TOOL: T3 D10 R0 L0 DB35 Z2
39 ; TYPE: FLAT END MILL
40 ; *****
41 ;TOOLCHANGEEND
42 ;End of generation of : Tool Change.1
43 TOOL CALL 3 Z
44 ;=====
45 ; OPERATION: Profile Contouring.2
46 ;=====
47 ;Start generation of : Profile Contouring.2
48 TOOL CALL Z S2400
49 L X-63 Y-60 R0 FMAX M3
50 L Z+50 R0 FMAX
51 L Z+17 R0 FMAX
52 L Z+14 F300
53 L Y+8 F1000
54 CC X-42 Y+8
55 C X-42 Y+29 DR-
56 L X+40
57 CC X+40 Y+19
58 C X+50 Y+19 DR-
59 L Y-30
60 CC X+30 Y-30
61 C X+15.858 Y-44.142 DR-
62 CC X+30 Y-30
63 C X+30 Y-10 DR-
64 L X-63
65 L Y-60
66 L Z+50 R0 FMAX
67 ;End of generation of : Profile Contouring.2
68 ;=====
69 ; OPERATION: Circular Milling.1
70 ;=====
71 ;Start generation of : Circular Milling.1
72 L X+12 Y+0 Z+30 R0 FMAX
73 L Z+3 R0 FMAX
74 L Z-5 F300
75 CC X+0 Y+0
76 C X-12 Y+0 DR+ F1000
77 CC X+0 Y+0
78 C X+12 Y+0 DR+
79 L Z+30 R0 FMAX
80 ;End of generation of : Circular Milling.1
81 L M5
82 L M9
83 L Z+50 FMAX
84 L M30
85 ; Xmin = -63
86 ; Xmax = 50
87 ; Ymin = -60
88 ; Ymax = 29
89 ; Zmin = -5
90 ; Zmax = 50
91 END PGM input MM
