A torus is torus { R, r } with the comma optional; sturm and inverse may stand among its
modifiers. Bad torus syntax gives a located error and exit status 1:

  $ printf 'torus { 1 }\n' > minor.pov
  $ povml minor.pov +W10 +H10 -D
  minor.pov:1:11: error: expected a numeric expression but found '}'
      1 | torus { 1 }
        |           ^
  [1]
  $ printf 'torus { 1, 0.25, 2 }\n' > three.pov
  $ povml three.pov +W10 +H10 -D
  three.pov:1:16: error: expected an object modifier or '}' closing 'torus' but found ','
      1 | torus { 1, 0.25, 2 }
        |                ^
  [1]
  $ printf 'torus { <1,2,3>, 1 }\n' > vector.pov
  $ povml vector.pov +W10 +H10 -D
  vector.pov:1:9: error: expected a float but found a 3-term vector
      1 | torus { <1,2,3>, 1 }
        |         ^
  [1]
  $ printf 'torus { 1, 0.2\n' > open.pov
  $ povml open.pov +W10 +H10 -D
  open.pov:1:15: error: expected an object modifier or '}' closing 'torus' but found end of file
      1 | torus { 1, 0.2
        |               ^
  [1]

sturm is read only by the torus so far:

  $ printf 'sphere { 0, 1 sturm }\n' > sturm.pov
  $ povml sturm.pov +W10 +H10 -D
  sturm.pov:1:15: error: not supported yet: 'sturm'
      1 | sphere { 0, 1 sturm }
        |               ^
  [1]

The dump shows the radii, the flags and the transform every modifier is composed into:

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ntorus { 1 0.25 sturm }\ntorus { 2, 0.5 inverse scale <1,2,1> translate x }\n' > dump.pov
  $ povml --dump dump.pov 2>&1 | grep -A3 torus
  torus { 1, 0.25 sturm
    texture { pigment { rgb <0, 0, 0> } }
  } // dump.pov:3:1
  intersection {
    torus { 2, 0.5
      matrix <1, 0, 0, 0, 2, 0, 0, 0, 1, 1, 0, 0>
      texture { pigment { rgb <0, 0, 0> } }
    } // dump.pov:4:1 inverse shared interior
