// povml fidelity scene: normal_reflection
// Rule: the reflected ray leaves by the bent normal, but when that sends it below the surface
//       (by the raw normal) it is mirrored again in the raw normal's plane, or reflected off the
//       raw normal when it is below the bent normal's plane too (trace.cpp, ComputeReflection,
//       "Reflection bugfix"); the reflectivity's angle (fresnel, falloff) and the metallic tint
//       use the bent normal. A rippled mirror floor seen at a grazing angle, a mirrored sphere
//       with strong bumps, a fresnel box.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 1.2, -6> look_at <0, 0.7, 0> right x*image_width/image_height }
background { rgb <0.2, 0.3, 0.5> }
light_source { <-3, 6, -4>, rgb 1 }
plane { y, 0 pigment { rgb <0.3, 0.3, 0.35> } normal { gradient x 3 triangle_wave scale 0.3 rotate y*20 }
        finish { reflection 0.7 phong 0.3 } }
sphere { <-1.2, 0.9, 0.5>, 0.9 pigment { rgb <0.9, 0.8, 0.3> }
         normal { quilted 4 scale 0.3 } finish { reflection { 0.8 metallic } ambient 0 diffuse 0.2 } }
box { <0.4, 0, -0.5>, <1.8, 1.2, 0.9> pigment { rgb <0.3, 0.6, 0.9> }
      normal { gradient <1, 1, 0> 1.5 sine_wave scale 0.2 }
      finish { reflection { 0.05, 1 falloff 2 } conserve_energy } }
sphere { <0, 3, 6>, 1.5 pigment { checker rgb <1, 0.2, 0.2> rgb 1 scale 0.5 } }
sphere { <3, 1, 3>, 1 pigment { rgb <0.2, 1, 0.3> } }
