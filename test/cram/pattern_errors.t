Pigment patterns (docs/povray-rules.md §17): errors in colour maps and pattern modifiers are located and
exit with status 1; patterns not read yet are "not supported yet" where they are used.

A colour map entry needs a colour keyword or identifier; a bare vector is an error:

  $ cat > bare.pov <<'POV'
  > #version 3.7;
  > plane { y, 0 pigment { gradient x color_map { [0 <1,0,0>] [1 rgb 1] } } }
  > POV
  $ povml bare.pov +W10 +H10 -D
  bare.pov:2:50: error: expected a colour ('rgb …', 'color …' or a colour identifier) in a color_map entry but found '<'
      2 | plane { y, 0 pigment { gradient x color_map { [0 <1,0,0>] [1 rgb 1] } } }
        |                                                  ^
  [1]

checker, hexagon and brick take their colours in the list, not a color_map:

  $ cat > cmap.pov <<'POV'
  > #version 3.7;
  > plane { y, 0 pigment { checker color_map { [0 rgb 1] [1 rgb 0] } } }
  > POV
  $ povml cmap.pov +W10 +H10 -D
  cmap.pov:2:32: error: cannot use color_map with this pattern type
      2 | plane { y, 0 pigment { checker color_map { [0 rgb 1] [1 rgb 0] } } }
        |                                ^
  [1]

An empty map, a missing ']', and a value that is not a map:

  $ printf 'plane { y, 0 pigment { gradient x color_map { } } }\n' > empty.pov
  $ povml empty.pov +W10 +H10 -D
  empty.pov:1:45: error: a color_map needs at least one entry
      1 | plane { y, 0 pigment { gradient x color_map { } } }
        |                                             ^
  [1]
  $ printf 'plane { y, 0 pigment { gradient x color_map { [0 rgb 1 [1 rgb 0] } } }\n' > bracket.pov
  $ povml bracket.pov +W10 +H10 -D
  bracket.pov:1:56: error: expected ']' closing a color_map entry but found '['
      1 | plane { y, 0 pigment { gradient x color_map { [0 rgb 1 [1 rgb 0] } } }
        |                                                        ^
  [1]
  $ printf '#declare C = rgb 1;\nplane { y, 0 pigment { gradient x color_map { C } } }\n' > notmap.pov
  $ povml notmap.pov +W10 +H10 -D
  notmap.pov:2:47: error: 'C' is a colour, not a color_map
      2 | plane { y, 0 pigment { gradient x color_map { C } } }
        |                                               ^
  [1]

brick_size and mortar belong to brick; gradient needs a direction:

  $ printf 'plane { y, 0 pigment { checker mortar 0.1 } }\n' > mortar.pov
  $ povml mortar.pov +W10 +H10 -D
  mortar.pov:1:32: error: 'mortar' is only valid in a brick pattern
      1 | plane { y, 0 pigment { checker mortar 0.1 } }
        |                                ^
  [1]
  $ printf 'plane { y, 0 pigment { gradient <0,0,0> } }\n' > zero.pov
  $ povml zero.pov +W10 +H10 -D
  zero.pov:1:33: error: the gradient vector is <0,0,0>
      1 | plane { y, 0 pigment { gradient <0,0,0> } }
        |                                 ^
  [1]

A pattern povml does not read yet, directly and through a declaration:

  $ printf 'plane { y, 0 pigment { density_file df3 "x.df3" } }\n' > wood.pov
  $ povml wood.pov +W10 +H10 -D
  wood.pov:1:24: error: not supported yet: 'density_file' as a pattern
      1 | plane { y, 0 pigment { density_file df3 "x.df3" } }
        |                        ^
  [1]
  $ cat > turb.pov <<'POV'
  > #declare P = pigment { density_file df3 "x.df3" warp { turbulence 0.5 } }
  > plane { y, 0 pigment { P } }
  > POV
  $ povml turb.pov +W10 +H10 -D
  turb.pov:2:24: error: not supported yet: 'density_file' as a pattern (used through 'P')
      2 | plane { y, 0 pigment { P } }
        |                        ^
  turb.pov:1:24: note: 'P' was declared here
  [1]

The dump shows a pattern pigment with its whole map and its transform, object transforms
composed after the pigment's own:

  $ cat > dump.pov <<'POV'
  > #version 3.7;
  > sphere { 0, 1 pigment { checker rgb 1 scale 2 } translate x }
  > POV
  $ povml dump.pov --dump 2>&1 | grep pigment
    texture { pigment { checker frequency 0 phase 0 color_map { [0 rgb <1, 1, 1>] [1 rgb <0, 1, 0>] } matrix <2, 0, 0, 0, 2, 0, 0, 0, 2, 1, 0, 0> } }

Pigment maps follow the same rules: not on checker (which lists its pigments), at least one entry:

  $ printf 'plane { y, 0 pigment { checker pigment_map { [0 rgb 1] } } }\n' > pmap.pov
  $ povml pmap.pov +W10 +H10 -D
  pmap.pov:1:32: error: cannot use pigment_map with this pattern type
      1 | plane { y, 0 pigment { checker pigment_map { [0 rgb 1] } } }
        |                                ^
  [1]
  $ printf 'plane { y, 0 pigment { gradient y pigment_map { } } }\n' > pempty.pov
  $ povml pempty.pov +W10 +H10 -D
  pempty.pov:1:47: error: a pigment_map needs at least one entry
      1 | plane { y, 0 pigment { gradient y pigment_map { } } }
        |                                               ^
  [1]
  $ printf 'plane { y, 0 pigment { gradient y pigment_map { [0 rgb 1 } } }\n' > pclose.pov
  $ povml pclose.pov +W10 +H10 -D
  pclose.pov:1:58: error: expected a colour, a pattern or ']' in a pigment_map entry but found '}'
      1 | plane { y, 0 pigment { gradient y pigment_map { [0 rgb 1 } } }
        |                                                          ^
  [1]

The colour or pattern comes first in a pigment (after an identifier), then only modifiers; a
second rgb… keyword starts a new colour, so two colours in a pigment are an error, as in POV-Ray:

  $ printf 'plane { y, 0 pigment { scale 2 checker } }\n' > order.pov
  $ povml order.pov +W10 +H10 -D
  order.pov:1:32: error: expected '}' closing the pigment but found 'checker': the colour or pattern comes first in a pigment
      1 | plane { y, 0 pigment { scale 2 checker } }
        |                                ^
  [1]
  $ printf 'plane { y, 0 pigment { rgb <1,0,0> rgb <0,1,0> } }\n' > twice.pov
  $ povml twice.pov +W10 +H10 -D
  twice.pov:1:36: error: expected '}' closing the pigment but found 'rgb': the colour or pattern comes first in a pigment
      1 | plane { y, 0 pigment { rgb <1,0,0> rgb <0,1,0> } }
        |                                    ^
  [1]

A pattern's work at every point is bounded: a fractal's iterations and number_of_waves above
povml's limit of pattern steps are a located limit error (exit 3), raised with --max-pattern-steps:

  $ printf '#version 3.7;\ncamera { location -3*z look_at 0 }\nsphere { 0, 1 pigment { mandel 300000 } }\n' > mandel.pov
  $ povml mandel.pov +W8 +H8 -D
  mandel.pov:3:32: error: 300,000 iterations at every point are beyond povml's limit of 100,000 pattern steps (raise it with --max-pattern-steps N)
      3 | sphere { 0, 1 pigment { mandel 300000 } }
        |                                ^
  [3]
  $ povml mandel.pov +W8 +H8 -D --max-pattern-steps 400000 2>&1 | tail -1
  Wrote mandel.png (8x8)
  $ printf '#version 3.7;\nglobal_settings { number_of_waves -2 }\n' > waves.pov
  $ povml waves.pov --dump 2>&1 | grep warning
  waves.pov:2:35: warning: Illegal Value: number_of_waves must be greater than 0. Changed to 1.
  warning: no objects in scene
  warning: assumed_gamma not specified in this POV-Ray 3.7 or later scene; the working gamma is 1.0 (add 'assumed_gamma 1.0' to global_settings)
