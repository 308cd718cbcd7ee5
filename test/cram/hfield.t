A height_field reads its image, then water_level and smooth; --dump shows the field as Compute_HField
leaves it (its size, heights, box, blocks) and its transform, Parse_HField's scaling then the
modifiers:

  $ printf 'P2\n3 2\n255\n0 10 20\n30 40 255\n' > hf.pgm
  $ printf '#version 3.7;\nheight_field { pgm "hf.pgm" water_level 0.1 smooth scale 2 }\n' > hf.pov
  $ povml --dump hf.pov | grep -A1 height_field
  warning: assumed_gamma not specified in this POV-Ray 3.7 or later scene; the working gamma is 1.0 (add 'assumed_gamma 1.0' to global_settings)
  height_field { // 3 x 2 heights 0 … 65535, box y 6553.599 … 65535.001, water_level 0.1, smooth, 1 x 1 blocks
    matrix <1, 0, 0, 0, 3.051757812e-05, 0, 0, 0, 2, 0, 0, 0>

The function form is not read yet; a missing file and a missing number are located errors:

  $ printf 'height_field { function 4, 4 { x } }\n' > fn.pov
  $ povml fn.pov +W10 +H10 -D
  fn.pov:1:16: error: not supported yet: 'function'
      1 | height_field { function 4, 4 { x } }
        |                ^
  [1]
  $ printf 'height_field { "nofile.png" }\n' > nf.pov
  $ povml nf.pov +W10 +H10 -D
  nf.pov:1:16: error: cannot find the image file "nofile.png" (searched ., /usr/share/povray-3.7/include)
      1 | height_field { "nofile.png" }
        |                ^
  [1]
  $ printf 'height_field { pgm "hf.pgm" water_level }\n' > wl.pov
  $ povml wl.pov +W10 +H10 -D
  wl.pov:1:41: error: expected a numeric expression but found '}'
      1 | height_field { pgm "hf.pgm" water_level }
        |                                         ^
  [1]
