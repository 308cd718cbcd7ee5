// povml fidelity scene: torus_mirror
// Rule: a reflective torus reflects the scene with the reflected ray starting on its surface;
//       the 1e-4 world depth limit and the solver's root elimination keep it from hitting the
//       torus again at once (docs/povray-rules.md §15.5, §15.6, §5.3). The mirrored ring reflects
//       itself through its hole.
// A chrome-like torus tilted over a floor, with spheres and a box around it.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2.5, -5> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.3, 0.45, 0.7> }
light_source { <-5, 7, -4>, rgb 1 }
light_source { <4, 3, -5>, rgb 0.3 }
torus { 1.1, 0.35 rotate x*-35 translate <0, 1.1, 0.3>
        pigment { rgb <0.8, 0.8, 0.85> } finish { ambient 0.05 diffuse 0.2 reflection 0.7 phong 0.9 phong_size 60 } }
sphere { <-1.8, 0.5, -0.6>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <1.7, 0.4, -0.9>, 0.4 pigment { rgb <0.2, 0.8, 0.3> } }
box { <-0.4, 0, -1.6>, <0.4, 0.5, -0.9> rotate y*25 pigment { rgb <0.9, 0.8, 0.2> } }
plane { y, 0 pigment { rgb <0.7, 0.7, 0.65> } finish { reflection 0.1 } }
