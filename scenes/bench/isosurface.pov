// povml benchmark scene: render at +W640 +H480 -A.
// Isosurfaces: a sphere displaced by noise (functions.inc's f_noise3d), a torus rippled by a
// user function, a rounded box, three metaballs summed in a user function inside a sphere
// container, a parametric-free twisted column; every root search runs the compiled functions.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 3.2, -8> look_at <0, 0.9, 0> right x*image_width/image_height angle 50 }
background { rgb <0.3, 0.45, 0.7> }
light_source { <-6, 9, -7>, rgb 1 }
light_source { < 7, 5, -3>, rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
#declare Ripple = function(x, y, z) { f_torus(x, y, z, 0.9, 0.3) + 0.05 * sin(12 * atan2(z, x)) }
#declare Balls = function(x, y, z) {
  1.2 - exp(-4 * (pow(x + 0.45, 2) + y * y + z * z)) - exp(-4 * (pow(x - 0.45, 2) + y * y + z * z))
      - exp(-4 * (x * x + pow(y - 0.6, 2) + z * z)) }
isosurface {
  function { f_sphere(x, y, z, 1) - f_noise3d(x * 3, y * 3, z * 3) * 0.35 }
  contained_by { box { -1.4, 1.4 } } max_gradient 3.2 accuracy 0.001
  pigment { rgb <0.9, 0.55, 0.3> } finish { phong 0.5 } translate <-2.6, 1.3, 0.8> }
isosurface {
  function { Ripple(x, y, z) }
  contained_by { box { <-1.4, -0.5, -1.4>, <1.4, 0.5, 1.4> } } max_gradient 1.8
  pigment { rgb <0.4, 0.8, 0.5> } finish { specular 0.4 } rotate x * -25 translate <0, 0.9, -1.6> }
isosurface {
  function { f_rounded_box(x, y, z, 0.2, 0.7, 0.7, 0.7) }
  contained_by { box { -0.8, 0.8 } }
  pigment { rgb <0.5, 0.6, 0.95> } rotate y * 30 translate <2.6, 0.8, 0.8> }
isosurface {
  function { Balls(x, y, z) }
  contained_by { sphere { 0, 1.6 } } max_gradient 2.6
  pigment { rgb <0.95, 0.85, 0.4> } finish { reflection 0.2 phong 0.6 } translate <0, 1.2, 1.8> }
isosurface {
  function { f_helix1(x, y, z, 3, 5, 0.12, 0.45, 1, 1, 0) }
  contained_by { box { <-0.8, 0, -0.8>, <0.8, 2.6, 0.8> } } max_gradient 4
  pigment { rgb <0.85, 0.3, 0.5> } translate <-4.2, 0, 3> }
