// Rule: POV-Ray builds its bounding tree only when the scene has at least Bounding_Threshold
// objects, light sources counted (+MBn; 1 by default, 3 in Debian's povray.ini), and with -MB
// never; without the tree it tests every object whose box the ray crosses, in scene order. The
// order shows where it decides what an object answers: here isosurfaces share the cache of the
// last segment without a root. Three objects and a light: the tree with +MB4, scene order with
// +MB5 or -MB (34 pixels differ).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
camera { location <0, 1.5, -9> look_at <0, 0.5, 0> angle 40 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
#declare Lumpy = isosurface {
  function { f_sphere(x, y, z, 0.8) - f_noise3d(x * 4, y * 4, z * 4) * 0.5 }
  contained_by { box { -1.2, 1.2 } } max_gradient 0.3 }
object { Lumpy pigment { rgb <0.4, 0.7, 0.9> } finish { reflection 0.3 } translate <-1.3, 0.5, 0> }
object { Lumpy pigment { rgb <0.46, 0.7, 0.82> } finish { reflection 0.3 } translate <0, 0.5, 0> }
object { Lumpy pigment { rgb <0.52, 0.7, 0.74> } finish { reflection 0.3 } translate <1.3, 0.5, 0> }
