// povml fidelity scene: csg_intersection
// Rule: an intersection keeps a member's hit only inside every other member; each visible
//       surface shows the texture of the primitive hit (§16.2, §16.5). A box ∩ sphere with
//       different textures, and intersection { plane, sphere inverse }: the plane's half-space
//       outside the sphere, a hole in the floor (§16.3).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 8, -5>, rgb 1 }
intersection {
  box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8> pigment { rgb <0.9, 0.3, 0.1> } }
  sphere { <0, 0.8, 0>, 1.05 pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.8 } }
  rotate y*30 translate <-1.2, 0, 0.5>
}
intersection {
  plane { y, 0 }
  sphere { <1.5, 0, -0.5>, 0.9 inverse }
  pigment { rgb <0.8, 0.8, 0.7> }
}
sphere { <1.5, -1.2, -0.5>, 0.5 pigment { rgb <0.3, 0.9, 0.3> } }
