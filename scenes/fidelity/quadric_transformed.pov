// povml fidelity scene: quadric_transformed
// Rule: a quadric's modifiers transform its coefficients (Quadric::Transform, quadrics.cpp): the
//       4×4 matrix Q of the coefficients becomes I·Q·Iᵀ (I the inverse of the modifier's
//       matrix), the mixed and linear terms the sums of the symmetric entries; the ray is never
//       moved, the depth is the world depth. Rotate, non-uniform and negative scale, a shearing
//       matrix and translate, one after the other, each changing the coefficients again; clip
//       objects written before the modifiers move with them (§14.4).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 3, -6.5> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-5, 8, -4>, rgb 1 }
light_source { <4, 4, -6>, rgb 0.35 }
// the unit sphere, squashed, turned and moved
quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1
  pigment { rgb <0.9, 0.35, 0.2> } finish { phong 0.6 }
  scale <0.7, 0.35, 0.45> rotate <20, 30, 10> translate <-2.2, 0.8, 0.3> }
// a cylinder along z, clipped to a slice, then turned and sheared
quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -0.16
  clipped_by { box { <-1, -1, -0.8>, <1, 1, 0.8> } }
  pigment { rgb <0.3, 0.7, 0.9> } finish { specular 0.6 roughness 0.02 }
  rotate <0, 50, 0> matrix <1, 0.3, 0, 0, 1, 0, 0.4, 0, 1, 0, 0, 0> translate <-0.3, 0.5, -0.6> }
// a cone x² + z² = y², mirrored by a negative scale, cut to its lower nappe's first unit
intersection {
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, 0 }
  box { <-2, 0, -2>, <2, 1, 2> }
  pigment { rgb <0.5, 0.9, 0.3> } finish { phong 0.3 }
  scale <-0.6, 1.2, 0.8> rotate z*15 translate <1.2, 0, 0.2> }
// a paraboloid y = x² + z², sheared by a matrix, cut by a box
intersection {
  quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0
    matrix <1, 0, 0, 0.5, 1, 0.2, 0, 0, 1, 0, 0, 0> scale <0.6, 0.8, 0.6> }
  box { <-1, 0, -1>, <1, 1.2, 1> }
  pigment { rgb <0.95, 0.8, 0.2> }
  translate <2.6, 0.01, 1> }
plane { y, 0 pigment { rgb <0.85, 0.85, 0.8> } }
