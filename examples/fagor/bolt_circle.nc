%1401
; Fagor 8070: a flange with a bolt circle of six holes, G81 + G163 (multiple machining in a full circle)
N10 G71 G90 G17 G54
N20 T1 M06
N30 S1400 M03
; the first hole at X90 Y50: the circle's centre is 40 to its left (X50 Y50), radius 40
N40 G00 X90 Y50 Z30
N50 G81 G98 Z2 I-12 F160
; K6: six holes with the first, 60 degrees apart, counter-clockwise, in rapid between them (C0)
N60 G163 X-40 Y0 K6
N70 G80
N80 G00 Z30
N90 M05
N100 M30
