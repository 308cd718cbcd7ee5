The object pattern (parstxtr.cpp OBJECT_TOKEN, Parse_Bound_Clip): exactly one object in its
block, then transforms, then up to two colours, pigments or normals.

No object at all: POV-Ray says "Expected 'object', color keyword 'rgb' found instead":

  $ cat > none.pov <<'POV'
  > #version 3.7;
  > sphere { 0, 1 pigment { object { rgb 1, rgb 0 } } }
  > POV
  $ povml none.pov +W10 +H10 -D
  none.pov:2:34: error: expected an object or object identifier in the object pattern but found 'rgb'
      2 | sphere { 0, 1 pigment { object { rgb 1, rgb 0 } } }
        |                                  ^
  [1]

Two objects: POV-Ray says "object or object identifier expected.":

  $ cat > two.pov <<'POV'
  > #version 3.7;
  > #declare B = box { 0, 1 }
  > sphere { 0, 1 normal { object { sphere { 0, 1 } B translate x } } }
  > POV
  $ povml two.pov +W10 +H10 -D
  two.pov:3:63: error: object or object identifier expected: an object pattern takes exactly one object, 2 were written
      3 | sphere { 0, 1 normal { object { sphere { 0, 1 } B translate x } } }
        |                                                               ^
  [1]

A transform with no object before it (POV-Ray reads the transforms first, then says "Expected
'object', sphere found instead"), and a color_map on the pattern (POV-Ray: "Cannot use color_map
with this pattern type"):

  $ printf 'sphere { 0, 1 pigment { object { translate x sphere { 0, 1 } } } }\n' > early.pov
  $ povml early.pov +W10 +H10 -D
  early.pov:1:46: error: expected an object or object identifier in the object pattern but found 'sphere'
      1 | sphere { 0, 1 pigment { object { translate x sphere { 0, 1 } } } }
        |                                              ^
  [1]
  $ printf 'sphere { 0, 1 pigment { object { sphere { 0, 1 } } color_map { [0 rgb 1] } } }\n' > cmap.pov
  $ povml cmap.pov +W10 +H10 -D
  cmap.pov:1:52: error: cannot use color_map with this pattern type
      1 | sphere { 0, 1 pigment { object { sphere { 0, 1 } } color_map { [0 rgb 1] } } }
        |                                                    ^
  [1]

object_pattern is no keyword of POV-Ray's: a name like any other.

  $ printf '#declare object_pattern = 1;\n#debug concat(str(object_pattern, 0, 0), "\\n")\n' > name.pov
  $ povml name.pov +W1 +H1 -D 2>&1 | head -1
  1

The dump shows the object (moved by the transform inside the block), the checker's default map
and frequency 0, and the pattern's own transform after the block:

  $ cat > dump.pov <<'POV'
  > #version 3.7;
  > sphere { 0, 1 pigment { object { sphere { 0, 1 } translate x rgb 1 } scale 2 } }
  > POV
  $ povml dump.pov --dump 2>&1 | grep pigment
    texture { pigment { object { sphere { <1, 0, 0>, 1 texture { pigment { rgb <0, 0, 0> } } } // dump.pov:2:34 } frequency 0 phase 0 color_map { [0 rgb <1, 1, 1>] [1 rgb <0, 1, 0>] } matrix <2, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0> } }
