// POV-Ray 3.7.0.10's own hits for test_superq.ml: trace() gives the nearest hit point and its
// normal, inside() the inside test. Run: povray +Isuperq_trace.pov +W8 +H8 -D 2>&1 | grep '^[RNI] '
#declare Objs = array[6] {
  superellipsoid { <3, 3> scale 0.9 translate <2.2, 1, 0> },
  superellipsoid { <0.25, 0.6> rotate <20, 35, 10> },
  ovus { 1, 0.6 },
  ovus { 0.6, 1 scale <1, 1.3, 0.8> rotate 20*z },
  sphere_sweep { linear_spline 3, <-1, 0, 0>, 0.3, <0, 1, 0>, 0.5, <1, 0, 0.5>, 0.2 },
  sphere_sweep { cubic_spline 5, <-1.5, 0, 0>, 0.2, <-0.5, 0.5, 0>, 0.3, <0.5, -0.3, 0>, 0.4, <1.5, 0.5, 0>, 0.3, <2, 0, 0>, 0.2 }
}
#declare Rays = array[4][2] {
  { <0, 0, -6>, <0.37572848608453923713, 0.17078567549297241079, 0.91085693596251959825> },
  { <0.3, 0.4, -5>, <0, 0, 1> },
  { <-4, 0.2, -3>, <0.8, 0.05, 0.6> },
  { <0.1, 3, 0.05>, <0, -1, 0.01> }
}
#declare Points = array[3] { <0, 0.3, 0>, <0.5, 0.5, 0.1>, <0.9, 0.2, 0.3> }
#for (I, 0, 5)
  #for (J, 0, 3)
    #declare N = <0, 0, 0>;
    #declare P = trace(Objs[I], Rays[J][0], vnormalize(Rays[J][1]), N);
    #debug concat("R ", str(I, 0, 0), " ", str(J, 0, 0), " ", vstr(3, P, " ", 0, 20), "\n")
    #debug concat("N ", str(I, 0, 0), " ", str(J, 0, 0), " ", vstr(3, N, " ", 0, 20), "\n")
  #end
  #for (K, 0, 2)
    #debug concat("I ", str(I, 0, 0), " ", str(K, 0, 0), " ", str(inside(Objs[I], Points[K]), 0, 0), "\n")
  #end
#end
