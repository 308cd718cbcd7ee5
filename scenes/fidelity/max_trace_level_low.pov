// povml fidelity scene: max_trace_level_low
// Rule: TraceRay returns BLACK (not the background) once the trace level reaches max_trace_level;
//       the primary ray is level 0, so max_trace_level 2 allows one bounce (docs/povray-rules.md §7,
//       pitfall §13.10).
// A mirror ball in front of a mirror wall: the ball reflects the room (1 bounce) but the
// wall's reflection seen IN the ball is black, and vice versa.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 2 }
camera { location <1.0, 1.8, -5> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.5, 0.7, 1.0> }
light_source { <-2, 6, -4>, rgb 1 }
plane { z, 2 pigment { rgb 0.2 } finish { ambient 0 diffuse 0.2 reflection 0.8 } }
sphere { <-0.3, 1.0, 0>, 0.9 pigment { rgb 0.2 } finish { ambient 0 diffuse 0.2 reflection 0.8 } }
sphere { <1.8, 0.58, -1.5>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
plane { y, 0 pigment { rgb <0.5, 0.8, 0.5> } }
