// A glass cylinder standing on a glass box (both ior 1.5; the cylinder's end on the box's top face).
// Rays refracted into the cylinder meet its end and the box's face 1 unit in the last place apart;
// POV-Ray's bounding tree enters the cylinder's box first and skips the box, entered beyond the end.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 8 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> right x*image_width/image_height angle 48 }
light_source { <-4, 10, -5>, rgb 0.8 }
light_source { <5, 6, -6>, rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.5 } }
box { <-3.3, 0, -0.8>, <-1.5, 0.5, 0.8> pigment { rgbf <0.6, 0.6, 1, 0.85> } interior { ior 1.5 } }
cylinder { <-2.4, 0.5, 0>, <-2.4, 1.5, 0>, 0.6 pigment { rgbf <1, 1, 0.6, 0.85> } interior { ior 1.5 } }
