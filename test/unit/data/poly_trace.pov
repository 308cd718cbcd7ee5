// POV-Ray's own crossings of polys, for test/unit/test_poly.ml: trace() returns the nearest
// intersection's IPoint (the poly-space point mapped back) and the normal there.
// povray +Itest/unit/data/poly_trace.pov -D +W8 +H8 -GA 2>&1 | grep '^T'
#version 3.7;
global_settings { assumed_gamma 1 }
#declare R2 = 0.49; #declare r2 = 0.0625; #declare K = R2 - r2;
#declare P1 = quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
  1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0, 1, 0, 2*K - 4*R2, 0, K*K > rotate <60, 0, 30> scale <1.2, 0.6, 1> translate <0.1, 0.2, 0.3> }
#declare P2 = poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1> scale <0.3, 0.5, 0.4> rotate <30, 45, 0> }
#declare P3 = cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0, -1, 0> sturm rotate x*-90 }
#declare P4 = poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -0.25> matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> }
#macro T(Name, Obj, O, D)
  #declare N = <0, 0, 0>;
  #declare P = trace(Obj, O, D, N);
  #debug concat("T ", Name, " ", vstr(3, P, " ", 0, 17), "\n")
  #debug concat("N ", Name, " ", vstr(3, N, " ", 0, 17), "\n")
#end
T("P1a", P1, <0.3, 3, -4>, <-0.05, -0.6, 1>)
T("P1b", P1, <-3, 0.1, 0.2>, <1, 0.05, 0.02>)
T("P2a", P2, <0.1, 0.2, -3>, <0, 0, 1>)
T("P2b", P2, <2, 1.5, -1>, <-1, -0.8, 0.6>)
T("P3a", P3, <0.3, 2, -0.4>, <0.1, -1, 0.2>)
T("P4a", P4, <-2, 0.1, -0.1>, <1, 0.05, 0.02>)
// a ray grazing the torus's tube, where the order of the sums in the expansion shows (POV-Ray's
// binary adds them in GCC's vectorized order, see lib/shapes/poly.ml), without and with sturm
#declare P5 = quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
  1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0, 1, 0, 2*K - 4*R2, 0, K*K > }
#declare P6 = object { P5 sturm }
T("P5a", P5, <1.6, 5.613139720814413, -1.2777568135664554>, <-0.1361893369949414, -0.9591521508170833, 0.2479508339809358>)
T("P6a", P6, <1.6, 5.613139720814413, -1.2777568135664554>, <-0.1361893369949414, -0.9591521508170833, 0.2479508339809358>)
