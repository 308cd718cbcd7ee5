// povml fidelity scene: poly_transformed
// Rule: every modifier of a poly composes into its transform (Poly::Translate, Rotate,
//       Scale all call Transform: Compose_Transforms); rays are brought into poly space by the
//       inverse, their direction made unit (the depth divided by its length again), the normal is
//       the gradient by the inverse transpose (MTransNormal), and the hit point is the poly-space
//       point mapped back (MTransPoint). Non-uniform scales, a matrix with shear, clipped_by and
//       sturm on a cubic.
#version 3.7;
global_settings { assumed_gamma 1.0 }
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
// the quartic torus turned, then squashed (a non-uniform scale), then moved
object { Torus4 rotate <60, 0, 30> scale <1.2, 0.6, 1> translate <-2, 0.9, 0.5>
  pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.6 } }
// the rounded cube (order 6) scaled non-uniformly and turned
object { Sextic scale <0.3, 0.5, 0.4> rotate <30, 45, 0> translate <-0.3, 0.7, 0>
  pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } }
// an order 2 ball through a matrix with shear, and an order 5 poly moved
object { Ball2 scale 0.4 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> translate <1.1, 0.5, -0.8>
  pigment { rgb <0.9, 0.3, 0.2> } finish { specular 0.6 roughness 0.02 } }
object { Quint scale 0.45 rotate y*30 translate <2.4, 0.6, 0.4> pigment { rgb <0.9, 0.8, 0.3> } }
// the cubic monkey saddle, clipped to a ball, turned and moved, with sturm
object { Monkey sturm clipped_by { sphere { 0, 1 } } scale 0.6 rotate x*-90 translate <0.9, 1.6, 1.5>
  pigment { rgb <0.8, 0.5, 0.9> } }
