%1301
; G163: six holes on a circle of radius 20 around X50 Y50 (the first at X70 Y50), point 3 skipped
G71 G90 G17
G00 X0 Y0 Z30
M03 S1000
G00 X70 Y50
G81 G98 Z2 I-10 F150
G163 X-20 Y0 K6 P3
G80
; the same circle by its step, clockwise, back to the reference plane between the holes
G81 G99 X70 Y50 Z2 I-10 F150
G163 X-20 Y0 I-60 Q4 R5
G80
G00 Z30
M05
M30
