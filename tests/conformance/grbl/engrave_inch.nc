; engraving in inches, incremental moves
G20 G90
M3 S12000
G0 X0.5 Y0.5 Z0.1
G1 Z-0.01 F20.
G91
G1 X1. F40.
G1 Y0.5
G1 X-1.
G1 Y-0.5
G90
G0 Z0.1
M5
M30
