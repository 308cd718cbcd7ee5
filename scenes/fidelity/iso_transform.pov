// povml fidelity scene: iso_transform
// Rule: a transformed isosurface: the ray taken into its space by the inverse transform (not
//       renormalised), the normal by the inverse transpose renormalised, its box mapped; a
//       declared isosurface placed twice as copies (which POV-Ray never warns about).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
#declare Torus = isosurface {
  function { pow(sqrt(x*x + z*z) - 0.6, 2) + y*y - 0.06 }
  contained_by { box { <-1, -0.4, -1>, <1, 0.4, 1> } }
  max_gradient 1.5
}
object { Torus rotate <60, 20, 0> scale <1, 1.3, 0.8> translate <-1, 0.2, 0> pigment { rgb <0.9, 0.6, 0.3> } finish { phong 0.5 } }
object { Torus scale 0.8 rotate -40*z translate <1.1, 0, 0.3> pigment { rgb <0.4, 0.8, 0.5> } finish { phong 0.5 } }
isosurface {
  function { x*x + y*y*4 + z*z - 0.25 }
  contained_by { sphere { 0, 0.6 } }
  max_gradient 4.5
  rotate 30*z translate <0, -0.6, -1.2>
  pigment { rgb <0.6, 0.6, 0.9> }
}
plane { y, -1.2 pigment { rgb <0.8, 0.8, 0.75> } }
