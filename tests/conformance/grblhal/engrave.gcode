; grblHAL router: a frame with rounded corners, lower-case words, a block skipped by the operator's switch
g21 g90 g17
t3 m6
g43.1 z30
m3 s18000
g0 x0 y0 z5
g1 z-1 f300
g1 x50 f800
g3 x60 y10 i0 j10
g1 y40
g3 x50 y50 i-10 j0
g1 x10
g2 x0 y40 i0 j-10 (clockwise corner)
g1 y0
/g4 p0.5
g0 z5
g28 g91 z0
g90
m5
m2
