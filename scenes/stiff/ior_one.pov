// povml stiff scene: ior_one
// Stresses: transmission at ior 1.0. A ray crossing a surface whose relative ior is 1 goes on
// straight as a "continued" ray that does NOT use a trace level (§6.2, §7), so with
// max_trace_level 3 the camera still sees through 24 nested tinted shells (48 surfaces) on the
// left. On the right the same shells alternate ior 1.0 and 1.02: every crossing there changes
// the ior, uses a level, and the third surface met is the last. In the middle two ior-1 spheres overlap (leaving one of them while
// inside the other is an ior-1 crossing too, §6.2) and a third has fade_distance with the
// default fade_power 0, which halves the colour seen through it (§6.3). Each crossing filters
// by the shell's rgbf colour in single precision, 48 times over.
// A correct image: left, a yellow-green disc, brighter at its edge where the ray crosses fewer
// shells, with the red ball visible through all of them; right, the same nest black inside its
// second shell (max_trace_level 3 allows three surfaces); in the middle the overlapping pair and the dimmer faded ball; no NaN, no black
// speckles from rays cut at the level limit on the left.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 3 }
camera { location <0, 1, -7> look_at <0, 1, 0> right x*image_width/image_height angle 60 }
background { rgb <0.35, 0.55, 0.9> }
light_source { <-3, 8, -6>, rgb 1 }
plane { y, 0 pigment { rgb <0.85, 0.8, 0.7> } }
#macro Nest(C, Step)
  #local I = 0;
  #while (I < 24)
    sphere { C, 1.2 - I * 0.045
      pigment { rgbf <0.99, 1, 0.96, 0.99> } finish { ambient 0 diffuse 0 }
      interior { ior 1 + Step * mod(I, 2) } }
    #local I = I + 1;
  #end
  sphere { C, 0.12 pigment { rgb <0.9, 0.15, 0.1> } }
#end
Nest(<-2.2, 1.3, 1>, 0)
Nest(< 2.2, 1.3, 1>, 0.02)
sphere { <-0.2, 0.6, -1>, 0.5 pigment { rgbt <0.7, 0.9, 1, 0.8> } finish { ambient 0 diffuse 0.1 } }
sphere { < 0.3, 0.6, -1>, 0.5 pigment { rgbt <1, 0.8, 0.7, 0.8> } finish { ambient 0 diffuse 0.1 } }
sphere { <0, 2.6, 0>, 0.45 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { fade_distance 0.5 } }
