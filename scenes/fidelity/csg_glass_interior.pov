// povml fidelity scene: csg_glass_interior
// Rule: a CSG's members without an interior SHARE the CSG's interior: a ray leaving through
//       another member's surface leaves the medium (§16.5, pitfall 12). Left: the interior on the
//       difference; right: on the box only, so the cut surface has ior 1 and is a second medium
//       (§6.2). Shadows through both filter at every crossing (§4).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 7, -5>, rgb 1 }
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.4, 0.8> }
  sphere { <0, 1.4, -0.8>, 0.7 }
  pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.6 }
  interior { ior 1.5 }
  translate <-1.2, 0, 0>
}
difference {
  box { <-0.8, 0, -0.8>, <0.8, 1.4, 0.8> interior { ior 1.5 } }
  sphere { <0, 1.4, -0.8>, 0.7 }
  pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { ambient 0 diffuse 0.1 phong 0.6 }
  translate <1.2, 0, 0>
}
box { <-3, 0, 2>, <3, 2.5, 2.2> pigment { rgb <0.9, 0.4, 0.2> } }
sphere { <0, 0.3, 3>, 0.3 pigment { rgb <0.2, 0.9, 0.2> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
