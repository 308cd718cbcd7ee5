// povml fidelity scene: box_glass
// Rule: a box is a closed solid: a point on or within its faces is inside (§15.1), so a ray
//       refracts in on one face and out on another with the interior list (§6.2, §6.4); shadows
//       through it are filtered, not refracted (§4). A rotated glass slab and a glass cube in
//       front of coloured boxes on a plain floor.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 2, -5.5> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.25, 0.35, 0.55> }
light_source { <-3, 6, -5>, rgb 1 }
box { <-0.7, 0, -0.7>, <0.7, 1.4, 0.7> rotate y*30 translate <-0.6, 0, 0>
      pigment { rgbf <0.95, 0.98, 1, 0.9> } finish { ambient 0 diffuse 0.05 phong 0.8 reflection 0.05 }
      interior { ior 1.5 fade_distance 2 fade_power 1 } }
box { <0.5, 0, -1.2>, <1.5, 1, -0.2> pigment { rgbt <0.9, 1, 0.9, 0.8> } finish { ambient 0 diffuse 0.1 } interior { ior 1.33 } }
box { <-2, 0, 1.5>, <-1, 2, 2> pigment { rgb <0.9, 0.2, 0.2> } }
box { <-0.5, 0, 1.5>, <0.5, 2, 2> pigment { rgb <0.2, 0.9, 0.2> } }
box { <1, 0, 1.5>, <2, 2, 2> pigment { rgb <0.2, 0.2, 0.9> } }
sphere { <0.3, 0.4, 0.8>, 0.4 pigment { rgb <1, 0.9, 0.3> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
