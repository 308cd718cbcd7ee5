// povml fidelity scene: iso_threshold
// Rule: threshold T: the surface is where the function equals T (the search and Inside use
//       f − T, the normal the function's own differences); a declared user function called
//       from the isosurface's function.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Blobby = function(a, b, c) { 1/(0.3 + (a-0.5)*(a-0.5) + b*b + c*c) + 1/(0.3 + (a+0.5)*(a+0.5) + b*b + c*c) }
camera { location <0, 1.5, -4> look_at <0, 0, 0> angle 45 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-10, 20, -15>, rgb 1 }
light_source { <10, 5, -10>, rgb 0.3 }
isosurface {
  function { -Blobby(x, y, z) }
  threshold -2.2
  contained_by { box { <-1.6, -1, -1>, <1.6, 1, 1> } }
  max_gradient 6
  pigment { rgb <0.9, 0.4, 0.4> } finish { phong 0.6 }
}
plane { y, -1.01 pigment { rgb <0.8, 0.8, 0.75> } }
