%1302
; G163 C3: counter-clockwise arcs at F600 between four holes around X20 Y20 (G99: at the reference plane)
G71 G90 G17
G00 X0 Y0 Z30
M03 S1000
G00 X40 Y20
G81 G99 Z2 I-8 F120
G163 X-20 Y0 K4 C3 F600
G80
G00 Z30
; G164 C1: an arc of 90 degrees around X0 Y0 in clockwise steps of 45, feed moves at F400 (G98: at Z30)
G00 X30 Y0
G81 G98 Z2 I-8 F120
G164 X-30 Y0 B90 I-45 C1 F400
G80
M05
M30
