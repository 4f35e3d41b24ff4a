%1402
; Fagor 8070: spot-facing a bolt circle with a dwell, the tool following the circle between the holes
N10 G71 G90 G17 G54
N20 T2 M06
N30 S900 M03
N40 G00 X90 Y50 Z30
; G99: back to the reference plane Z2 after each hole; K0.5: half a second at the bottom
N50 G81 G99 Z2 I-3 K0.5 F90
; I60: a hole every 60 degrees from the first (the steps close 360); C3: counter-clockwise arcs at
; F800 between the holes (at Z2, where G99 leaves the tool); P4: no spot face at hole 4 (X10 Y50)
N60 G163 X-40 Y0 I60 C3 F800 P4
N70 G80
N80 G00 Z30
N90 M05
N100 M30
