(* Polygonal tube transformation, square tube, segmentation at circumference, *)
(* Absolute programming *)
(* Open profile *)
%L SUB_CONT
N[10+P30] G00 G90 X0 Z100 U0
N[20+P30] G162
P1=20  (* inner circle radius     *)
P2=50  (* outer circle radius     *)
P3=22.5
P4=2*P3
G261
$FOR P10=0, 8 , 1
          P6=P10*P4
          P7=SIN[P6]
          P8=COS[P6]
N[40+P10] G01 X[P2*P8] U[P2*P7] F5000
          P20=SIN[P3 + P6]
          P21=COS[P3 + P6]
N[50+P10] G01 X[P1*P21] U[P1*P20] F5000
$ENDFOR
G260
M29
%prof_open_close_.nc
N10 #SLOPE [TYPE=STEP]
N20 G00 X0 Y0 Z100 U0
N25 #CONTOUR MODE[DEV PATH_DEV 2]
N65 G00 G90 Y0 U0
N70 #CYL[EDGES=4 ROUNDING=5 LENGTH1=20 LENGTH2=20 OPEN=2 CLOSE=3]
P30=2000
N80 LL SUB_CONT
N90 #CYL OFF
M30
