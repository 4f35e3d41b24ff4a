%1403
; Fagor 8070: a perforated plate, a grid of 4 x 3 holes 15 mm apart with G162, two of them left out
N10 G71 G90 G17 G54
N20 T3 M06
N30 S2000 M03
N40 G00 X10 Y10 Z20
N50 G81 G98 Z2 I-6 F250
; along X: 4 holes 15 apart (I15 K4); along Y: 3 rows 15 apart (J15 D3); holes 6 and 11 left out
N60 G162 A0 B90 I15 K4 J15 D3 P6 Q11
N70 G80
N80 G00 Z20
N90 M05
N100 M30
