%
o2007 (lower case addresses)
n10 g21 g17 g90
n20 g54 g00 x10. y10. s1200 m03
N30 g43 h01 Z5. m08
n40 G01 z-2. f150.
n50 g02 x20. y20. r10.
n60 g03 x10. y10. i-10. j0.
n70 G00 z5.
n80 m09
n90 g91 g28 z0. m05
n100 m30
%
