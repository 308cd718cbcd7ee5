// povml fidelity scene: quadric_alone
// Rule: quadric { <A,B,C>, <D,E,F>, <G,H,I>, J } is A x² + B y² + C z² + D xy + E xz + F yz
//       + G x + H y + I z + J = 0 in world space (quadrics.cpp, Quadric::Intersect): a = D·(Q D),
//       b and c as POV-Ray groups them, roots (−b ± √(b² − ac))/a kept within 1e-6 < t < 1e7;
//       with a = 0 the one root −c/2b (the floor here is the plane y = 0 written as a quadric,
//       so every ray takes that branch, and a shadow ray leaving it finds its root at 0); the
//       normal is the gradient, normalised. Unbounded quadrics (the floor, the cylinder along x,
//       the hyperboloid, the paraboloid) are tested by every ray.
// An ellipsoid moved by linear terms, an ellipsoid turned by a mixed term, an infinite cylinder
// along x behind them, a hyperboloid of one sheet far right, a paraboloid bowl.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
// 4(x + 1.5)² + 9(y − 0.7)² + 4z² = 1: radii 0.5, 1/3, 0.5 about <−1.5, 0.7, 0>
quadric { <4, 9, 4>, <0, 0, 0>, <12, -12.6, 0>, 9 + 4.41 - 1
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
// x² + y² + z² + 1.2 xy = 0.36, moved up by 0.8 (y → y − 0.8)
quadric { <1, 1, 1>, <1.2, 0, 0>, <-0.96, -1.6, 0>, 0.64 - 0.36
  pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
// (y − 0.2)² + (z − 2.5)² = 0.09: a cylinder along x at height 0.2, radius 0.3
quadric { <0, 1, 1>, <0, 0, 0>, <0, -0.4, -5>, 0.04 + 6.25 - 0.09
  pigment { rgb <0.3, 0.5, 0.9> } }
// (x − 3.5)² − y² + z² = 0.2: a one-sheet hyperboloid about the vertical through x = 3.5
quadric { <1, -1, 1>, <0, 0, 0>, <-7, 0, 0>, 12.25 - 0.2
  pigment { rgb <0.9, 0.8, 0.3> } }
// 4(x − 1.2)² + 4(z − 1.5)² = y − 0.1: a paraboloid bowl opening up
quadric { <4, 0, 4>, <0, 0, 0>, <-9.6, -1, -12>, 5.76 + 9 + 0.1
  pigment { rgb <0.8, 0.5, 0.9> } finish { phong 0.4 } }
// the plane y = 0 as a quadric
quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
