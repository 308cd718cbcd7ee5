// POV-Ray's trace() and inside() of julia fractals, printed for test_julia.ml
#version 3.7;
#declare J1 = julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }
#declare J2 = julia_fractal { <-0.2, 0.6, 0.2, 0.0> cube max_iteration 6 precision 30 slice <0,0,1,1>, 0.1 }
#declare J3 = julia_fractal { <-0.4, 0.4, 0.1, 0> hypercomplex sqr max_iteration 6 precision 30 rotate <10,20,30> scale <1,1.5,0.8> }
#declare J4 = julia_fractal { <0.3, 0.2, 0.1, 0.1> hypercomplex reciprocal max_iteration 5 precision 30 }
#macro T(J, O, D)
  #local N = <0,0,0>;
  #local P = trace(J, O, D, N);
  #debug concat(vstr(3, P, ", ", 0, 17), "\n")
  #debug concat(vstr(3, N, ", ", 0, 17), "\n")
#end
T(J1, <0, 1.2, -3.2>, <0.05, -0.3, 1>)
T(J1, <-3, 0.2, 0.1>, <1, 0, 0.02>)
T(J2, <0.1, 0.2, -3>, <0, 0, 1>)
T(J3, <0.3, 5, -0.2>, <0, -1, 0.1>)
T(J4, <-4, 0.05, 0.1>, <1, 0.01, 0>)
#macro I(J, P) #debug concat(str(inside(J, P), 0, 0), "\n") #end
I(J1, <0, 0, 0>) I(J1, <0.5, 0.2, 0.1>) I(J1, <0.2, 0.5, -0.3>) I(J1, <1.9, 0, 0>)
I(J3, <0, 0, 0>) I(J3, <0.8, 0.2, 0>)
// a function map: its normal comes from the stack as the march left it
#declare J5 = julia_fractal { <0.5, 0.2, 0.1, 0.0> hypercomplex sin max_iteration 5 precision 30 }
T(J5, <-0.2, 0.1, -5>, <0, 0, 1>)
T(J5, <0.3, -0.2, -5>, <0.01, 0.02, 1>)
