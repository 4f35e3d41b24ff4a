(P parameters, $FOR, $IF/$ELSE, $WHILE, a %L subroutine called with LL, N[expr] block numbers)
%L STEP
N[100+P10] G01 X[P1] Y[P2] F[200+P10]
$IF P1 >= 15
N[200+P10] G01 Z-2
$ELSE
N[300+P10] G01 Z-1
$ENDIF
M17
%1
N10 G71 G90 G17
N20 G00 X0 Y0 Z5
P20=2.5
$FOR P10 = 1, 5, 2
  P1 = P10 * 5
  P2 = P20 * P10
  LL STEP
$ENDFOR
P3 = 0
$WHILE P3 < 3
  N[40+P3] G01 X[P3*4-10] Y[-P3] Z[-P3/2]
  P3 = P3 + 1
$ENDWHILE
G00 Z5
M30
