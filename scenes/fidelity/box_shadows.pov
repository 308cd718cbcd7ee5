// povml fidelity scene: box_shadows
// Rule: box { A, B } with its corners sorted per axis; Box::Intersect's slabs, the side hit
//       gives the normal, edges and corners decided by the 1e-6 tie rule (docs/povray-rules.md §15.1);
//       translate and scale move the corners (§14.4). Boxes cast shadows on the floor and on
//       each other (§4).
// Three axis-aligned boxes, one given with its corners swapped, one flat (zero height) box on
// the floor, one scaled and translated, lit from the upper left.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <1.5, 3.5, -6> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.3, 0.4, 0.6> }
light_source { <-4, 8, -3>, rgb 1 }
light_source { <5, 4, -6>, rgb 0.3 }
box { <-1.5, 0, -0.5>, <-0.3, 1.2, 0.7> pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.6 } }
box { <1.2, 1.6, 1.0>, <0.2, 0, 0.2> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.4 } }
box { <-1, -1, -1>, <1, 1, 1> scale <0.4, 0.25, 0.3> translate <0.7, 1.85, 0.6> pigment { rgb <0.4, 0.5, 0.9> } }
box { <-2.5, 0, -2>, <2.5, 0, -1.2> pigment { rgb <0.8, 0.2, 0.3> } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
