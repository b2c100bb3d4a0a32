0 BEGIN PGM M126 MM
1 ; M126 turns the endless C of the MAS MCVL 1000 the shorter way (iTNC 530 User's Manual, M126):
2 ; C355 -> C5 is +10 degrees, traced as C365, and back to C355 is -10; M127 ends it, and C5 is
3 ; then reached the long way (-350 degrees). B+0: the tool stays on +Z, the tip where it is.
4 TOOL CALL 1 Z S3000
5 L X+0 Y+0 Z+50 R0 B+0 C+355 FMAX M3 M128
6 L C+5 FMAX M126
7 L C+355 FMAX
8 L C+5 FMAX M127
9 L M30
10 END PGM M126 MM
