// Benchmark: a #while loop that creates 100,000 spheres (a 320 × 320 grid less some), each with
// its position, radius and colour computed by expressions: the interpreter's loop cost.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 60, -90> look_at <0, 0, 0> right x*image_width/image_height angle 60 }
light_source { <-100, 200, -150>, rgb 1 }
plane { y, -1 pigment { rgb 0.6 } }
#declare N = 100000;
#declare Side = 317;
#declare I = 0;
#while (I < N)
  #declare X = mod(I, Side);
  #declare Z = div(I, Side);
  sphere { <(X - Side / 2) * 0.5, 0, (Z - Side / 2) * 0.5>, 0.2 + 0.05 * sin(I)
    pigment { rgb <X / Side, 0.5, Z / Side> }
  }
  #declare I = I + 1;
#end
