// povml fidelity scene: normal_turbulence
// Rule: a normal's turbulence and warps move the point before its pattern sees it (Warp_EPoint),
//       the tetrahedron's corners are taken around the moved point, and only the transforms
//       among the warps turn the normal (Warp_Normal). A turbulent gradient on the floor (the
//       classic turbulence with octaves, omega, lambda), quilted behind a warp { turbulence }
//       then a scale on the sphere, bumps after a repeat warp on the box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -5> look_at <0, 0.6, 0> right x*image_width/image_height }
background { rgb <0.1, 0.1, 0.2> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.7> }
        normal { gradient x 0.8 triangle_wave turbulence 0.6 octaves 4 omega 0.6 lambda 2.5 scale 0.5 } finish { phong 0.4 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.3, 0.2> }
         normal { quilted 1 warp { turbulence <0.3, 0.1, 0.3> } scale 0.25 } finish { phong 0.8 phong_size 40 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { bumps 1 scale 0.1 warp { repeat x*0.3 flip x } } finish { specular 0.6 roughness 0.02 } }
