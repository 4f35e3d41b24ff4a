(grblHAL with NGC_EXPRESSIONS_ENABLE, run from its SD card: a square pocket cut in passes by an o-word loop)
G21 G17 G90 G94
#<depth> = 0
#<step> = 1.5
#<half> = 12
T1 M6
S12000 M3
G0 X0 Y0 Z5
o100 while [#<depth> GT -4.5]
  #<depth> = [#<depth> - #<step>]
  G1 Z#<depth> F200
  G1 X[-#<half>] Y[-#<half>] F600
  G1 X#<half>
  G1 Y#<half>
  G1 X[-#<half>]
  G1 Y[-#<half>]
  o101 if [#<depth> LE -4.5]
    G0 Z5
  o101 else
    G0 Z[#<depth> + 1]
  o101 endif
  G0 X0 Y0
o100 endwhile
M5
M30
