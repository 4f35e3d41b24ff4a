%1101
; Fagor 8070: a plate with two rows of holes, then counterbores (K = dwell at the bottom, seconds)
N10 G71 G90 G17 G54
N20 T1 M06
N30 S1500 M03
N40 G00 X0 Y0 Z50
; G81: Z = reference plane, I = depth, G99 back to the reference plane between holes
N50 G81 G99 X20 Y20 Z2 I-15 F180
N60 X40
N70 X60
N80 G98 X80
N90 G80
; the second row in incremental: Z from the start level, I from the reference plane
N100 G91 G99 G81 X-60 Y30 Z-48 I-17
N110 X20
N120 G98 X20
N130 G90 G80
N140 G00 Z50
N150 T2 M06
N160 S800 M03
; counterbores: G81 with a dwell, then G89 (dwell, feed out) with G159=2, the second zero offset
N170 G159=2
N180 G00 X20 Y20 Z50
N190 G81 G98 Z3 I-5 K0.5 F90
N200 G89 X40 Z3 I-6 K1.2 F60
N210 G80
N220 G00 Z50
N230 M05
N240 M30
