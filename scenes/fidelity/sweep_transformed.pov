// povml fidelity scene: sweep_transformed
// Rule: without a transform, translate, rotate and a uniform scale move the modeling spheres
//       (scale multiplies their radii) and the segments are computed again; a non-uniform scale
//       or a matrix creates the sweep's Trans, into which every later modifier composes: the ray
//       enters sweep space by the inverse, its direction renormalised, depths divided by that
//       length, normals out by the inverse transpose, normalised; the box is the modeling
//       spheres' (twice their radii for cubic_spline) mapped.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.9, 0> right x*image_width/image_height }
background { rgb <0.3, 0.35, 0.5> }
light_source { <-4, 7, -6>, rgb 1 }
light_source { <5, 3, -4>, rgb 0.3 }
plane { y, 0 pigment { checker rgb <0.85, 0.85, 0.8> rgb <0.6, 0.6, 0.6> } }
sphere_sweep { linear_spline 3, <0, 0, 0>, 0.3, <1, 1, 0>, 0.2, <2, 0, 0>, 0.3
  rotate <0, 30, 20> scale 0.8 translate <-3, 0.5, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.7 } }
sphere_sweep { cubic_spline 5, <0, 0, 0>, 0.2, <0, 0.5, 0>, 0.3, <1, 1.2, 0>, 0.3, <2, 0.5, 0>, 0.3, <2, 0, 0>, 0.2
  scale <1, 1.4, 0.5> rotate 30*y translate <-0.8, 0.2, 0> pigment { rgb <0.3, 0.8, 0.4> } finish { specular 0.6 roughness 0.02 } }
sphere_sweep { b_spline 5, <0, 0, 0>, 0.3, <0.5, 1, 0>, 0.3, <1, 0, 0>, 0.3, <1.5, 1, 0>, 0.3, <2, 0, 0>, 0.3
  matrix <1, 0, 0, 0.3, 1, 0, 0, 0, 1, 0, 0, 0> translate <1.2, 0.5, 0.5> pigment { rgb <0.3, 0.5, 0.9> } }
sphere_sweep { linear_spline 2, <-1, 0, 0>, 0.3, <1, 0, 0>, 0.15 scale <1, 2, 1> rotate 60*y translate <0, 0.6, -2.2> pigment { rgb <0.9, 0.8, 0.3> } }
