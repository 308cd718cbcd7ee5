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

  $ printf 'height_field { tiff "x.tif" }\n' > fn.pov
  $ povml fn.pov +W10 +H10 -D
  fn.pov:1:16: error: not supported yet: 'tiff' images
      1 | height_field { tiff "x.tif" }
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

A POT file (Fractint's continuous potential) is a GIF twice as wide as its heights; only height
fields read it, and its width must be even:

  $ printf 'GIF89a\001\000\001\000\200\000\000\377\377\377\000\000\000,\000\000\000\000\001\000\001\000\000\002\002D\001\000;' > odd.gif
  $ printf 'height_field { pot "odd.gif" }\n' > odd.pov
  $ povml odd.pov +W10 +H10 -D
  odd.pov:1:16: error: cannot read the image file "odd.gif": invalid width for POT file
      1 | height_field { pot "odd.gif" }
        |                ^
  [1]
  $ printf 'plane { y, 0 pigment { image_map { pot "odd.gif" } } }\n' > im.pov
  $ povml im.pov +W10 +H10 -D
  im.pov:1:36: error: file type not supported here: 'pot' images are read only by height fields
      1 | plane { y, 0 pigment { image_map { pot "odd.gif" } } }
        |                                    ^
  [1]
  $ printf 'height_field { pot "mtmand.pot" }\n' > mt.pov
  $ povml --dump mt.pov 2>/dev/null | grep height_field
  height_field { // 160 x 120 heights 256 … 65024, box y 255.999 … 65024.001, 12 x 10 blocks
