// POV-Ray's trace() of parametric surfaces, printed for test_parametric.ml
#version 3.7;
#declare Torus = parametric {
  function { cos(u)*(1 + 0.35*cos(v)) }, function { 0.35*sin(v) }, function { sin(u)*(1 + 0.35*cos(v)) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
}
#declare Ball = parametric {
  function { cos(u)*sin(v)*0.8 }, function { cos(v)*0.8 }, function { sin(u)*sin(v)*0.8 }
  <0, 0>, <2*pi, pi>
  contained_by { sphere { 0, 0.85 } }
  accuracy 0.004
}
#declare Moved = parametric {
  function { cos(u)*(1 + 0.35*cos(v)) }, function { 0.35*sin(v) }, function { sin(u)*(1 + 0.35*cos(v)) }
  <0, 0>, <2*pi, 2*pi>
  contained_by { sphere { 0, 1.4 } }
  accuracy 0.002 max_gradient 1.5
  rotate <50, 0, 20> scale <0.8, 1.2, 0.7> translate <-0.9, 0.3, 0>
}
#declare Wave = parametric {
  function { u } function { 0.12*sin(10*u)*sin(8*v) } function { v }
  <-1, -1>, <1, 1>
  contained_by { box { <-1, -0.3, -1>, <1, 0.3, 1> } }
  accuracy 0.003 max_gradient 0.05
  precompute 16 y, z
}
#declare Wave0 = parametric {
  function { u } function { 0.12*sin(10*u)*sin(8*v) } function { v }
  <-1, -1>, <1, 1>
  contained_by { box { <-1, -0.3, -1>, <1, 0.3, 1> } }
  accuracy 0.003 max_gradient 0.05
}
#macro T(P, O, D)
  #local N = <0,0,0>;
  #local Q = trace(P, O, D, N);
  #debug concat(vstr(3, Q, ", ", 0, 17), "\n")
  #debug concat(vstr(3, N, ", ", 0, 17), "\n")
#end
T(Torus, <0.2, 0, -3>, <0, 0, 1>)
T(Torus, <0.2, 3, -0.9>, <0, -1, 0>)
T(Torus, <-3, 2, -1>, <1, -0.7, 0.35>)
T(Torus, <0, 0, 0>, <1, 0.1, 0>)
T(Torus, <0.2, 3, -0.9>, <0, -1, 0.1>)
T(Ball, <0.1, 0.2, -3>, <0, 0, 1>)
T(Ball, <0, 0, 0>, <0.3, 0.5, -1>)
T(Ball, <2, 2, 2>, <-1, -1, -1.1>)
T(Moved, <-0.3, 0.3, -4>, <0, 0, 1>)
T(Moved, <-1.5, 3, 0>, <0, -1, 0.02>)
T(Moved, <-3, 0.3, 0.1>, <1, 0.05, 0>)
T(Wave, <0.31, 2, -0.47>, <0, -1, 0.05>)
T(Wave0, <0.31, 2, -0.47>, <0, -1, 0.05>)
T(Wave, <-3, 1, 0.2>, <1, -0.35, 0>)
T(Wave, <-0.42, 2, -0.72>, <0.3, -0.5, 0.45>)
T(Wave0, <-0.42, 2, -0.72>, <0.3, -0.5, 0.45>)
