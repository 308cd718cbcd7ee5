// Rule: isosurfaces share one cache, the last segment on which one found no root, so which isosurface
// is searched after which decides what the cache answers: with isosurfaces in two or more top-level
// objects povml searches them in POV-Ray's order, through its bounding tree, nearest box first.
// (max_gradient is too low on purpose: the cache then hides roots, and the order shows.)
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location <0, 1.5, -9> look_at <0, 0.5, 0> angle 40 }
light_source { <-4, 8, -6>, rgb 1 }
light_source { <5, 3, -8>, rgb 0.4 }
background { rgb <0.2, 0.3, 0.5> }
#declare Lumpy = isosurface {
  function { f_sphere(x, y, z, 0.8) - f_noise3d(x * 4, y * 4, z * 4) * 0.5 }
  contained_by { box { -1.2, 1.2 } } max_gradient 0.3 }
#declare I = 0;
#while (I < 9)
  object { Lumpy pigment { rgb <0.4 + 0.06 * I, 0.7, 0.9 - 0.08 * I> } finish { reflection 0.3 }
           translate <mod(I, 3) * 1.3 - 1.3, 0.5 + div(I, 3) * 0.25, div(I, 3) * 1.4> }
  #declare I = I + 1;
#end
plane { y, -0.8 pigment { checker rgb 1, rgb 0.4 } finish { reflection 0.2 } }
