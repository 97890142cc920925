%
(flat end mill R3: a circular pocket floor in two helical turns, then a slot with arcs)
G21 G90 G17
G0 X10 Y5 Z2
G1 Z0 F200
G2 X10 Y5 Z-0.25 I-4 J0 F600
G2 X10 Y5 Z-0.5 I-4 J0
G2 X10 Y5 I-4 J0
G0 Z2
G0 X2 Y14
G1 Z-0.3
G1 X6
G3 X10 Y14 R2
G2 X14 Y14 R2
G0 Z5
M30
%
