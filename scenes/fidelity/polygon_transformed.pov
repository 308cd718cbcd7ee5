// povml fidelity scene: polygon_transformed
// Rule: a polygon's modifiers compose into its transform after its frame (Polygon::Transform,
//       docs/povray-rules.md §14.4, §15.7): rotate, non-uniform and negative scale, a shearing matrix;
//       the ray is moved into polygon space with its direction renormalised and the depth divided
//       by the length (§14.5 (b)); the normal is (0,0,1) by the inverse transpose, normalised
//       (§14.6). A checker attached before the transforms moves with the polygon (§14.7). The
//       points of the first polygon lie in a tilted plane, so its frame is not the identity.
//       Collinear or non-coplanar points make a polygon degenerate: POV-Ray never hits it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-5, 8, -4>, rgb 1 }
light_source { <4, 4, -6>, rgb 0.35 }
polygon { 5, <0, 0, 0>, <1, 0.3, 0.2>, <1.2, 1.5, 0.7>, <0.2, 1.2, 0.5>, <0, 0, 0>
  pigment { checker rgb <0.9, 0.3, 0.2> rgb <1, 0.9, 0.7> scale 0.25 } finish { phong 0.5 }
  rotate <10, 40, 15> scale <1.2, 0.9, 1> translate <-2.3, 0.5, 0.3> }
polygon { 10,
  <-0.8, -0.8>, <0.8, -0.8>, <0.8, 0.8>, <-0.8, 0.8>, <-0.8, -0.8>,
  <-0.4, -0.4>, <0.4, -0.4>, <0, 0.4>, <-0.4, -0.4>, <-0.4, -0.4>
  pigment { checker rgb <0.2, 0.6, 0.9> rgb <0.9, 0.9, 0.9> scale 0.3 }
  matrix <1, 0.25, 0, 0.4, 1, 0, 0, 0, 1, 0, 0, 0>
  scale <1, 1.3, -1> rotate <-25, -20, 0> translate <0, 1.1, 0.6> }
polygon { 4, <0, 0>, <1.4, 0>, <0.7, 1.1>, <0, 0>
  pigment { rgb <0.4, 0.85, 0.3> } finish { specular 0.6 roughness 0.01 }
  rotate x*90 scale <1, 1, 0.6> rotate y*-30 translate <1.2, 0.01, -1.2> }
polygon { 4, <0, 0, 0>, <0, 1, 0>, <0, 0.5, 1>, <0, 0, 0>
  pigment { rgb <0.95, 0.8, 0.2> }
  scale 0.9 transform { rotate z*-20 translate <2, 0.6, 0.5> } }
// collinear points (and below, points off one plane): degenerate, never seen, without a word
polygon { 4, <-1, 2>, <0, 2.2>, <1, 2.4>, <-1, 2> pigment { rgb 1 } }
polygon { 5, <-1, 2.6, 0>, <1, 2.6, 0>, <1, 3, 0>, <-1, 3, 0.01>, <-1, 2.6, 0> pigment { rgb 1 } }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
