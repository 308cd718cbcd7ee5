// povml course scene 05 -- slides "Recursive Ray-Tracing", "Pseudo Code" and "Result of Recursion".
// Shows: recursion with a termination depth ("We must obviously choose a termination depth to cope
// with multiple reflections"). Scenes 05, 06 and 07 are identical except for max_trace_level.
// This one: max_trace_level 1: only the primary ray is traced; every reflected ray is cut off and
// returns BLACK ("if (depth > MAX) return Black"), so the mirrors show only their dark local colour.
// (docs/povray-rules.md §7: the primary ray is level 0; a ray at level >= max_trace_level returns black.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 1 }
camera { location <0, 1.8, -6> look_at <0, 1.0, 0> right x*image_width/image_height }
background { rgb <0.45, 0.6, 0.85> }
light_source { <-3, 7, -5>, rgb 1 }
sphere { <-1.05, 1.0, 0.3>, 0.95 pigment { rgb 0.05 } finish { ambient 0 diffuse 0.1 reflection 0.9 phong 0.8 } }
sphere { < 1.05, 1.0, 0.3>, 0.95 pigment { rgb 0.05 } finish { ambient 0 diffuse 0.1 reflection 0.9 phong 0.8 } }
sphere { < 0.0, 0.45, -1.3>, 0.4 pigment { rgb <0.9, 0.2, 0.15> } finish { phong 0.5 } }
sphere { < 0.0, 2.6, 1.5>, 0.45 pigment { rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.55> } finish { reflection 0.2 } }
