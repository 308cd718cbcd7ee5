// povml fidelity scene: poly_grazing
// Rule: stiff cases of Solve_Polynomial: rays in the torus's own plane and tangent to its tube
//       (double roots: the closed-form quartic's discriminant near 0, Sturm's intervals), the
//       floor as an order 2 poly seen edge-on at the horizon (the t² and t terms near 0), and
//       the camera inside an order 6 poly (the roots behind it dropped, the inside test of the
//       camera's start).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -5> look_at <0, 0, 0> right x*image_width/image_height angle 60 }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
#declare R2 = 1; #declare r2 = 0.0625; #declare K = R2 - r2;
// the torus R = 1, r = 0.25 lying in the camera's plane y = 0: the rays at y = ±0.25 graze it
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0, 1, 0, 2*K - 4*R2, 0, K*K>
  pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.6 } translate <-1.3, 0, 0> }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 2*K - 4*R2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 2*K, 0, 0, 0, 0, 1, 0, 2*K - 4*R2, 0, K*K> sturm
  pigment { rgb <0.9, 0.8, 0.3> } finish { phong 0.6 } translate <1.3, 0, 0> }
// the floor y = −0.25 as an order 2 poly, and a ceiling y = 0.25 likewise: both tangent to the tori
poly { 2, <0, 0, 0, 0, 0, 0, 1, 0, 0, 0.25> pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
poly { 2, <0, 0, 0, 0, 0, 0, 1, 0, 0, -0.25> pigment { rgbf <0.9, 0.9, 1, 0.7> } }
// the camera inside x⁶ + y⁶ + z⁶ = 1 scaled by 7: each ray finds only the far wall, through a clear skin
poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1> scale 7 pigment { rgbf <1, 0.95, 0.9, 0.8> } }
