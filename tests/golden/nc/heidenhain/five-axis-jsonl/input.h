0 BEGIN PGM JSONL MM
1 ; the JSONL trace of five-axis moves: tip "to", tool vector "i" "j" "k", machine axes "b" "c"
2 TOOL CALL 1 Z S3000
3 L X+10 Y+20 Z+50 R0 B+30 C+40 FMAX M3 M128
4 L Z+5 F300
5 L Z+50 B+0 C+0 FMAX M129
6 L M30
7 END PGM JSONL MM
