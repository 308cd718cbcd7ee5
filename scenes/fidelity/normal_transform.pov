// povml fidelity scene: normal_transform
// Rule: a normal's transforms move its pattern (the point taken through their inverse) and turn
//       the bend with it (Warp_Normal: the normal times the matrix's transpose; UnWarp_Normal:
//       times the inverse's, normalised both ways); an object's transforms move its normal too.
//       Floor: a rotated, non-uniformly scaled gradient; sphere: quilted scaled and translated,
//       then the sphere moved; box: rotated with its quilted normal, and a matrix shear.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> } normal { gradient x 0.8 triangle_wave scale <0.3, 1, 2> rotate y*35 } finish { phong 0.4 } }
sphere { 0, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { quilted 1 scale <0.4, 0.2, 0.3> translate <0.1, 0.05, 0> } finish { phong 0.8 phong_size 40 }
         scale <1, 1.1, 1> translate <-1.2, 1, 0.5> }
box { <-0.7, -0.6, -0.7>, <0.7, 0.6, 0.7> pigment { rgb <0.3, 0.6, 0.9> }
      normal { quilted 0.8 scale 0.3 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> }
      finish { specular 0.6 roughness 0.02 } rotate <10, -30, 5> translate <1.1, 0.6, 0.2> }
