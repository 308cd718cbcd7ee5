// povml stiff scene: ior_three
// Stresses: a high index of refraction. At ior 3.0 the critical angle is only 19.5 degrees, so
// inside a dense object most rays are totally reflected (§6.2: t = 1 + ior²(n² − 1) < 0) and
// every reflection costs a trace level; Heckbert's refraction formula runs with large
// ior²(n² − 1) terms, and the Fresnel reflectance (§5.2) approaches 1 at grazing angles and 0.25
// head-on. A sphere of ior 3 (with Fresnel reflection), an octahedron mesh of ior 3 with an
// inside_vector, and for comparison a sphere of ior 1.5; max_trace_level 20.
// A correct image: the ior-3 ball as a fish-eye view of the room (floor, orange wall, the blue
// ball) with a bright Fresnel rim; the octahedron broken into mirror-like facets showing
// fragments of the scene; the ior-1.5 ball a milder, inverted lens. No NaN from the square root
// in the refraction formula.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 20 }
camera { location <0, 1.4, -6> look_at <0, 0.9, 0> right x*image_width/image_height angle 55 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-4, 9, -7>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
plane { z, 6 pigment { rgb <0.9, 0.5, 0.2> } }
sphere { <2.5, 1.5, 5>, 0.6 pigment { rgb <0.2, 0.7, 0.3> } }
sphere { <-2.5, 0.5, 4>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } }
#declare Glass3 = texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 phong 0.8 phong_size 80 reflection { 0, 1 fresnel } } }
#declare Ior3 = interior { ior 3.0 }
sphere { <-1.5, 0.9, 0>, 0.9 texture { Glass3 } interior { Ior3 } }
mesh {
  #declare T = <0, 1, 0>; #declare B = <0, -1, 0>;
  #declare E = <1, 0, 0>; #declare W = <-1, 0, 0>; #declare N = <0, 0, 1>; #declare S = <0, 0, -1>;
  triangle { T, E, N } triangle { T, N, W } triangle { T, W, S } triangle { T, S, E }
  triangle { B, N, E } triangle { B, W, N } triangle { B, S, W } triangle { B, E, S }
  inside_vector <0.3, 0.2, 1>
  texture { Glass3 } interior { Ior3 }
  scale 0.8 rotate <20, 30, 0> translate <0.6, 0.9, -0.6>
}
sphere { <2, 0.7, 0.5>, 0.7
  pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 phong 0.8 reflection { 0, 1 fresnel } }
  interior { ior 1.5 } }
