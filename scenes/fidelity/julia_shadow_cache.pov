// A julia fractal shadows itself through POV-Ray's shadow cache. The point of a crossing is a
// point inside the set, so a shadow ray from it starts inside and leaves the set within about the
// precision's step: at depth 9.2e-4 at pixel (82, 98). The full search for a blocker counts hits
// from 1e-3 on and finds none; the test of the cached object (the fractal, which shadowed the light
// on an earlier pixel) counts them from 1e-4 on and finds that exit: a full shadow. The cache of
// POV-Ray's one render thread carries from block to block, so this pixel, in the third row of its
// block, is in shadow only because of what earlier blocks left there (with +WT1; with an empty
// cache at the block's start it is lit). One object, one light: the tolerances are the only
// difference between the two tests.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.3, 0>
  up <0, 0, 1>
  right x*image_width/image_height
  sky <0, 0, 1>
  look_at <0, 0, 0>
}

light_source { <-6, 4.2, -10> rgb 1 }

julia_fractal {
  <0.49, 0.5, -0.34, 0.1>
  quaternion
  max_iteration 7
  precision 400
  pigment { rgb <0.6, 1, 0.5> }
  rotate <110, 50, -60>
}

background { rgb 1 }
