Light source keywords that need a spotlight, cylinder or parallel light are errors where they are
written when the light is not one yet (the kind keyword must come first), with exit status 1.

radius, falloff and tightness before the spotlight keyword:

  $ printf 'light_source { <0,5,0>, rgb 1 radius 20 spotlight }\n' > radius.pov
  $ povml radius.pov +W10 +H10 -D
  radius.pov:1:31: error: 'radius' needs a spotlight or cylinder light: write 'spotlight' or 'cylinder' before it
      1 | light_source { <0,5,0>, rgb 1 radius 20 spotlight }
        |                               ^
  [1]
  $ printf 'light_source { <0,5,0>, rgb 1\n  falloff 20 }\n' > falloff.pov
  $ povml falloff.pov +W10 +H10 -D
  falloff.pov:2:3: error: 'falloff' needs a spotlight or cylinder light: write 'spotlight' or 'cylinder' before it
      2 |   falloff 20 }
        |   ^
  [1]
  $ printf 'light_source { <0,5,0>, rgb 1 tightness 3 }\n' > tightness.pov
  $ povml tightness.pov +W10 +H10 -D
  tightness.pov:1:31: error: 'tightness' needs a spotlight or cylinder light: write 'spotlight' or 'cylinder' before it
      1 | light_source { <0,5,0>, rgb 1 tightness 3 }
        |                               ^
  [1]

point_at needs a spotlight, cylinder or parallel light:

  $ printf 'light_source { <0,5,0>, rgb 1 point_at <0,0,0> parallel }\n' > point_at.pov
  $ povml point_at.pov +W10 +H10 -D
  point_at.pov:1:31: error: 'point_at' needs a spotlight, cylinder or parallel light: write 'spotlight', 'cylinder' or 'parallel' before it
      1 | light_source { <0,5,0>, rgb 1 point_at <0,0,0> parallel }
        |                               ^
  [1]

A light takes one looks_like object:

  $ printf 'light_source { <0,5,0>, rgb 1\n  looks_like { sphere { 0, 1 } }\n  looks_like { sphere { 0, 2 } } }\n' > looks.pov
  $ povml looks.pov +W10 +H10 -D
  looks.pov:3:3: error: a light_source takes only one looks_like
      3 |   looks_like { sphere { 0, 2 } } }
        |   ^
  [1]

After the keyword they are read:

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\nlight_source { <0,5,0>, rgb 1 spotlight radius 20 falloff 30 tightness 2 point_at 0 }\nlight_source { <0,5,0>, rgb 1 parallel point_at 0 }\nlight_source { <0,5,0>, rgb 1 cylinder radius 1 falloff 2 }\nsphere { 0, 1 pigment { rgb 1 } }\n' > good.pov
  $ povml good.pov +W10 +H10 -D > /dev/null 2>&1 && echo rendered
  rendered
