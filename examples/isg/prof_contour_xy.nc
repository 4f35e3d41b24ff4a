(* The seed's $FOR contour without #CYL: the developed U axis is programmed as Y *)
(* 8 segments of 45 deg, zigzag between an outer and an inner circle *)
N10 G71 G90 G17
N20 G00 X0 Y0 Z100
P30=2000
N[10+P30] G00 G90 X0 Z100 Y0
P1=20  (* inner circle radius     *)
P2=50  (* outer circle radius     *)
P3=22.5
P4=2*P3
$FOR P10=0, 8 , 1
          P6=P10*P4
          P7=SIN[P6]
          P8=COS[P6]
N[40+P10] G01 X[P2*P8] Y[P2*P7] F5000
          P20=SIN[P3 + P6]
          P21=COS[P3 + P6]
N[50+P10] G01 X[P1*P21] Y[P1*P20] F5000
$ENDFOR
M30
