// povml fidelity scene: poly_alone
// Rule: poly { N, <coefficients> } (cubic = order 3, quartic = order 4) is the surface where the
//       sum of the terms c·x^i y^j z^k vanishes, the terms ordered by the power of x, then of y,
//       then of z, each descending (poly.cpp). Order 2 is solved by intersect_quadratic, the
//       others by the polynomial in t from the binomial expansion of every term and
//       Solve_Polynomial (closed forms up to 4, Sturm sequences above). Roots at or below
//       DEPTH_TOLERANCE (1e-4) in poly space are dropped; the normal is the gradient (normal1
//       written out up to order 4, normal0 term by term above). A poly is unbounded: every ray
//       tests it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
// order 2: x² + y² + z² − 0.25 = 0 moved to <−2.2, 0.5, 0>
poly { 2, <1, 0, 0, 4.4, 1, 0, -1, 1, 0, 4.84 + 0.25 - 0.25>
  pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
// a quartic torus R = 0.7, r = 0.25 about y: (x² + y² + z² + R² − r²)² − 4R²(x² + z²) = 0
#declare R2 = 0.49; #declare r2 = 0.0625; #declare K = R2 - r2;
quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2,
            0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0,
            1, 0, 2*K - 4*R2, 0, K*K >
  pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } translate <-0.6, 0.3, 0> }
// order 6: x⁶ + y⁶ + z⁶ = 0.4⁶, a rounded cube (Sturm sequences, normal0)
poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -0.004096>
  pigment { rgb <0.3, 0.5, 0.9> } finish { phong 0.5 } rotate <20, 30, 0> translate <1, 0.6, 0> }
// a quartic "Piriform" (x⁴ − x³) + y² + z² = 0 as in shapesq.inc, stretched
quartic { < 4, 0, 0, -4, 0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            0, 0, 0, 0, 0, 1, 0, 0, 0, 0,  0, 0, 1, 0, 0 >
  pigment { rgb <0.9, 0.8, 0.3> } finish { phong 0.4 } rotate z*90 translate <2.3, 0.05, -0.5> }
// the floor y = 0 as an order 2 poly: only the y term
poly { 2, <0, 0, 0, 0, 0, 0, 1, 0, 0, 0> pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
