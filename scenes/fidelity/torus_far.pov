// povml fidelity scene: torus_far
// Rule: a ray starting outside the sphere of radius R + 2r around the torus first moves its
//       origin to that sphere (the "closer" shift) before the quartic is set up, which keeps the
//       roots precise from far away (docs/povray-rules.md §15.5); sturm switches the solver to Sturm
//       sequences (§15.6). A narrow camera (angle 6) 60 units away.
// Five tori: an almost edge-on ring, a thin tube (r = 0.05), a sturm torus, a spindle torus
// (R = 0.3 < r = 0.5) and a tilted plain one, over a floor, two lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 20, -60> look_at <0, 0.6, 0> angle 6 right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-30, 60, -40>, rgb 1 }
light_source { <40, 20, -50>, rgb 0.3 }
torus { 1, 0.25 rotate x*88 translate <-2.2, 1.3, 0> pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
torus { 0.9, 0.05 rotate z*20 translate <0, 1.9, 0.5> pigment { rgb <1, 0.9, 0.3> } }
torus { 0.7, 0.3 sturm rotate x*-30 translate <2.1, 1.2, 0> pigment { rgb <0.3, 0.6, 1> } finish { specular 0.6 } }
torus { 0.3, 0.5 translate <-1, 0.5, -1.2> pigment { rgb <0.8, 0.4, 0.9> } finish { phong 0.4 } }
torus { 0.8, 0.2 rotate <40, 0, 25> translate <1, 0.6, -1.3> pigment { rgb <0.3, 0.9, 0.5> } }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.75> } }
