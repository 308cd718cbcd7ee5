// povml fidelity scene: polygon_alone
// Rule: polygon { N, P1, … } (docs/povray-rules.md §15.7): the points, 2-D or 3-D, are projected onto
//       the frame u, v, w of the first points; a point equal to the current outline's first point
//       closes it and the next one starts another outline (holes and islands by the even-odd
//       rule); an unclosed last outline is closed with its first point (a warning). The ray meets
//       the plane at 1e-8 ≤ s ≤ 1e7 (§14.5 (b)); the normal is flipped toward the viewer (§3.1).
// A pentagon, a square with a square hole and an island in the hole, a star drawn as one outline
// (its points cross: the even-odd rule leaves the centre out), a tilted triangle given in 3-D
// without its closing point, over a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -6> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -3>, rgb 0.3 }
#declare R = 0.7;
polygon { 6,
  <R*cos(radians(90)), R*sin(radians(90))>, <R*cos(radians(162)), R*sin(radians(162))>,
  <R*cos(radians(234)), R*sin(radians(234))>, <R*cos(radians(306)), R*sin(radians(306))>,
  <R*cos(radians(18)), R*sin(radians(18))>, <R*cos(radians(90)), R*sin(radians(90))>
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 }
  translate <-2, 1.4, 0.5> }
polygon { 15,
  <-0.8, -0.8>, <0.8, -0.8>, <0.8, 0.8>, <-0.8, 0.8>, <-0.8, -0.8>,
  <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>,
  <-0.2, -0.2>, <0.2, -0.2>, <0.2, 0.2>, <-0.2, 0.2>, <-0.2, -0.2>
  pigment { rgb <0.2, 0.7, 0.3> } finish { specular 0.5 roughness 0.02 }
  translate <0, 1.2, 0.8> }
polygon { 6,
  <0, 0.8>, <0.47, -0.65>, <-0.76, 0.25>, <0.76, 0.25>, <-0.47, -0.65>, <0, 0.8>
  pigment { rgb <0.95, 0.85, 0.2> }
  translate <2, 1.4, 0.3> }
polygon { 3, <-0.6, 0.05, -1.8>, <0.7, 0.05, -1.4>, <0.1, 0.9, -1.2>
  pigment { rgb <0.3, 0.5, 0.95> } }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
