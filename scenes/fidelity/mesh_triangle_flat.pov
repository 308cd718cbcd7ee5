// povml fidelity scene: mesh_triangle_flat
// Rule: a triangle is flat: its normal is the geometric normal normalize((P1-P2)x(P3-P2)) at every
//       point (docs/povray-rules.md §2.4), flipped toward the incoming ray (§3.1), so a face seen from its
//       back is lit like its front. Hits use the dominant-axis edge test, 1e-6 <= t <= 1e7 (§2.4).
// Three standalone triangles at different tilts, lit from the upper left at an angle: one faces the
// light, one is steeply inclined, one is seen from the side its normal points away from. Each face
// has a single flat diffuse level (varying only with the direction to the point light) and a
// phong highlight; they float above a floor and cast shadows on it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.37, 2.2, -6.1> look_at <0.05, 1.0, 0.3> right x*image_width/image_height angle 52 }
background { rgb <0.25, 0.3, 0.45> }
light_source { <-4.3, 6.2, -3.1>, rgb 1 }
// facing the light (normal roughly toward <-0.5, 0.6, -0.6>)
triangle { <-2.6, 0.35, 0.9>, <-0.95, 0.3, 0.05>, <-1.9, 2.05, 1.15>
  pigment { rgb <0.9, 0.25, 0.2> } finish { phong 0.6 phong_size 30 } }
// steeply inclined, almost edge-on to the light
triangle { <-0.55, 0.45, -0.4>, <1.05, 0.4, -0.15>, <0.35, 2.15, 1.6>
  pigment { rgb <0.3, 0.85, 0.35> } finish { phong 0.6 phong_size 30 } }
// normal points away from the camera: the flipped normal is used
triangle { <1.3, 0.55, 1.7>, <2.75, 0.5, 0.35>, <2.25, 1.95, 1.35>
  pigment { rgb <0.3, 0.45, 0.95> } finish { phong 0.6 phong_size 30 } }
plane { y, 0 pigment { rgb <0.85, 0.82, 0.75> } }
