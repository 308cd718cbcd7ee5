// povml fidelity scene: blob_alone
// Rule: a blob is the surface where the sum of its components' fields equals the threshold
//       (shape/blob.cpp): each sphere or cylinder component adds s·(1 − d²/r²)² within its radius;
//       the ray's intervals of influence are sorted and each interval's quartic solved with
//       POV-Ray's solver; the normal is the field's gradient. Old `component` syntax, new
//       sphere and cylinder components, a negative component, the default threshold 1.
// Three blobs side by side, in one view with one light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -7> look_at <0, 0.3, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-4, 6, -6>, rgb 1 }
blob { threshold 0.6
  component 1.0, 1.0, <-2.75, 0.3, 0>
  component 1.0, 1.0, <-2.0, 0.9, 0>
  component 1.0, 1.0, <-2.2, -0.2, 0.3>
  pigment { rgb <0.8, 0.2, 0.1> } finish { phong 0.8 } }
blob {
  sphere { <-0.5, 0.3, 0>, 1.1, 2 }
  sphere { <0.5, 0.3, 0>, 1.1, strength 2 }
  sphere { <0, 1.0, -0.3>, 0.7, -1.5 }
  cylinder { <0, -0.6, 0>, <0, 1.4, 0>, 0.4, 1.5 }
  pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.5 specular 0.3 } }
blob { threshold 0.4
  cylinder { <1.7, -0.5, 0>, <3, 1.2, 0.5>, 0.6, 1 }
  cylinder { <1.7, 1.2, -0.2>, <3, -0.3, 0>, 0.6, 1 }
  sphere { <2.35, 0.35, 0>, 0.8, 0.8 }
  pigment { rgb <0.3, 0.4, 0.9> } finish { phong 0.6 } }
