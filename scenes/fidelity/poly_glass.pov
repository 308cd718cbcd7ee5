// povml fidelity scene: poly_glass
// Rule: glass polys: the refracted ray starts on the surface, inside, and finds the far
//       side among the roots beyond 1e-4 (poly space); the normal (the gradient) bends it and the
//       shadow rays through the glass continue from each crossing's own point (the poly-space
//       point mapped back, as TracePointLightShadowRay takes the intersection's IPoint).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2.5, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
#declare R2 = 0.49; #declare r2 = 0.0625; #declare K = R2 - r2;
#declare Torus4 = quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0, 1, 0, 2*K - 4*R2, 0, K*K> }
#declare Sextic = poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1> }
#declare Ball2 = poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }
#declare Monkey = cubic { <1, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0> }
#declare Quint = poly { 5, <0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, -0.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1> }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
// glass: the refracted ray leaves through the far side, found from inside (the roots beyond
// 1e-4 in poly space), bent by the gradient normal
object { Torus4 rotate x*-60 translate <-1.6, 0.8, -0.5>
  pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { phong 0.8 reflection 0.1 } interior { ior 1.5 } }
object { Ball2 scale 0.6 translate <1.9, 0.6, -0.6>
  pigment { rgbf <1, 0.9, 0.9, 0.9> } interior { ior 1.6 } }
// what the glass shows
sphere { <-1, 0.5, 2>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
box { <0.5, 0, 1.5>, <1.5, 1.2, 2.5> pigment { rgb <0.3, 0.8, 0.4> } }
cylinder { <2.5, 0, 1.5>, <2.5, 1.5, 1.5>, 0.3 pigment { rgb <0.9, 0.8, 0.3> } }
