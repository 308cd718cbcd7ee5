// A glass cylinder (ior 1) and a glass cone (ior 1.3) standing on a plane: rays inside the glass
// meet the flat end and the plane at the same depth up to rounding, so the pixel depends on the
// last bits of every camera ray. The view angle 48 is one where A·(π/360), as POV-Ray computes
// it, and (A·π)/360 differ (§1.3).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> right x*image_width/image_height angle 48 }
light_source { <-4, 10, -5>, rgb 0.8 }
light_source { <5, 6, -6>, rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.5 } }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.7 pigment { rgbf <1, 0.5, 0.5, 0.9> } interior { ior 1.0 } }
cone { <0, 0, 0>, 0.7, <0, 1, 0>, 0.2 pigment { rgbf <0.5, 1, 0.5, 0.9> } interior { ior 1.3 } translate <2.4, 0, -0.2> }
cone { <0, 0, 0>, 0.6, <0, 1.2, 0>, 0.6 pigment { rgbf <0.6, 0.6, 1, 0.85> } interior { ior 1.0 } translate <-2.4, 0, 0.3> }
