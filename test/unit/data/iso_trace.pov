// POV-Ray's trace() and inside() of isosurfaces, printed for test_isosurface.ml
// (povray +Iiso_trace.pov -F -W8 -H8 -D; the values go to /tmp/iso_trace.txt, one trace a line:
// the point, then the normal; an inside() a line)
#version 3.7;
#fopen F "/tmp/iso_trace.txt" write
#declare I1 = isosurface { function { x*x + y*y + z*z - 0.64 } max_gradient 2 }
#declare I2 = isosurface { function { y - 0.3*sin(3*x)*sin(3*z) } contained_by { box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> } } open max_gradient 1.5 }
#declare I3 = isosurface { function { x*x + y*y + z*z - 4 } contained_by { sphere { <0.1, 0, 0>, 1 } } }
#declare I4 = isosurface { function { y + 0.2*x } accuracy 0.0005 }
#declare I5 = isosurface { function { abs(x) + abs(y) + abs(z) } threshold 0.9 max_gradient 1.8 rotate <20, 30, 0> scale <1, 1.5, 0.8> translate <0.2, 0, 0> }
#declare I6 = isosurface { function { x*x + y*y + z*z - 0.5 } max_gradient 1 }
#declare I7 = isosurface { function { sqrt(x*x + z*z) - 0.5 + 0.1*sin(8*y) } contained_by { box { <-1, -1, -1>, <1, 1, 1> } } max_gradient 2 max_trace 3 }
#macro T(I, O, D)
  #local N = <0,0,0>;
  #local P = trace(I, O, D, N);
  #write (F, vstr(3, P, ", ", 0, 17), " / ", vstr(3, N, ", ", 0, 17), "\n")
#end
T(I1, <0, 0, -3>, <0, 0, 1>)
T(I1, <0.3, 0.4, -3>, <0.1, -0.2, 1>)
T(I1, <0, 0, 0>, <1, 0, 0>)
T(I1, <0.95, 0.95, -3>, <0, 0, 1>)
T(I2, <0.2, 3, -0.4>, <0, -1, 0.1>)
T(I2, <0.3, -3, 0.5>, <0.1, 1, 0>)
T(I3, <0.3, 0.2, -3>, <0, 0, 1>)
T(I3, <-3, 0.1, 0.2>, <1, 0.05, 0>)
T(I4, <0.3, -0.5, -3>, <0, 0, 1>)
T(I4, <-3, -0.3, 0.2>, <1, 0.1, 0>)
T(I4, <0.1, 3, 0.1>, <0.05, -1, 0>)
T(I5, <0.1, 0.2, -4>, <0, 0, 1>)
T(I5, <3, 2, -2>, <-1, -0.6, 0.7>)
T(I6, <0.1, 0.2, -3>, <0, 0, 1>)
T(I6, <0.9, 0.9, -3>, <0, 0, 1>)
T(I6, <0.1, 0.2, -3>, <0, 0, 1>)
T(I7, <0, 0.1, -3>, <0, 0, 1>)
T(I7, <0.05, 0.3, 0>, <0, 0, 1>)
#macro In(I, P) #write (F, str(inside(I, P), 0, 0), "\n") #end
In(I1, <0, 0, 0>) In(I1, <0.7, 0.3, 0>) In(I1, <0.5, 0.5, 0.5>)
In(I3, <0.1, 0.9, 0>) In(I3, <0.1, 1.01, 0>)
In(I4, <0.5, -0.2, 0.3>) In(I4, <0.5, -0.05, 0.3>) In(I4, <0.5, -1.5, 0>)
In(I5, <0.2, 0, 0>) In(I5, <1.1, 0, 0>)
