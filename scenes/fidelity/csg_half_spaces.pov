// povml fidelity scene: csg_half_spaces
// Rule: an intersection of planes is unbounded and its Inside is every half-space at once; the
//       camera inside a glass block made of six planes starts inside its interior (§6.4) and the
//       rays leave through its far faces (§6.2). A merge of a mesh (with an inside vector) and a
//       sphere drops the surfaces inside each other (§16.2, §2.6).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 1, -2.5> look_at <0, 0.8, 2> right x*image_width/image_height }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-3, 8, -5>, rgb 1 }
intersection {
  plane { y, 2 } plane { -y, -0.2 } plane { x, 1.5 } plane { -x, 1.5 } plane { z, 0 } plane { -z, 3 }
  pigment { rgbf <0.95, 1, 1, 0.95> } finish { ambient 0 diffuse 0 }
  interior { ior 1.2 }
}
merge {
  mesh {
    triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }
    triangle { <0, 0, 0>, <0, 1, 0>, <0, 0, 1> }
    triangle { <0, 0, 0>, <0, 0, 1>, <1, 0, 0> }
    triangle { <1, 0, 0>, <0, 1, 0>, <0, 0, 1> }
    inside_vector <1, 2, 3>
    scale 1.2
  }
  sphere { <0.2, 0.2, 0.2>, 0.35 }
  pigment { rgbt <0.9, 0.5, 0.3, 0.5> }
  rotate y*40
  translate <-0.2, 0, 2.5>
}
box { <-3, 0, 4>, <3, 2.5, 4.2> pigment { rgb <0.3, 0.6, 0.9> } }
sphere { <1, 0.5, 3>, 0.4 pigment { rgb <0.9, 0.9, 0.2> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
