A polygon is polygon { N, P1, … PN } with the commas optional, and 2-D points get z = 0; a
quadric is quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }. The dump shows a polygon's points in its own
plane and the transform to world space (its frame, then every modifier), and a quadric's
coefficients after every modifier with POV-Ray's box (lower corner + lengths):

  $ cat > dump.pov <<'EOF2'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > polygon { 4 <0,0> <2,0> <0,1> <0,0> translate z }
  > quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 scale 2 translate x }
  > quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 inverse }
  > EOF2
  $ povml --dump dump.pov 2>&1 | grep -A2 "polygon\|quadric"
  polygon { 4, <0, 0>, <2, 0>, <0, 1>, <0, 0> // the points in its own plane
    matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1>
    texture { pigment { rgb <0, 0, 0> } }
  --
  quadric { <0.25, 0.25, 0.25>, <0, 0, 0>, <-0.5, 0, 0>, -0.75 // box <-1, -2, -2> + <4, 4, 4>
    texture { pigment { rgb <0, 0, 0> } }
  } // dump.pov:4:1
  --
    quadric { <-1, 0, -1>, <0, 0, 0>, <0, 0, 0>, 1 // box <-10000000000, -10000000000, -10000000000> + <20000000000, 20000000000, 20000000000>
      texture { pigment { rgb <0, 0, 0> } }
    } // dump.pov:5:1 inverse shared interior

The render statistics have a row for each, in POV-Ray's wording and order (after Plane); a
bounded shape is tried only by rays that meet its box:

  $ cat > stats.pov <<'EOF2'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 0, -5> look_at 0 }
  > polygon { 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> }
  > quadric { <1,1,1>, <0,0,0>, <0,0,0>, -0.25 translate z*-1 }
  > plane { z, 2 }
  > EOF2
  $ povml stats.pov +W20 +H20 -D 2>&1 | grep -E "^(Plane|Polygon|Quadric|Sphere) "
  Plane                              400             400      100.00
  Polygon                             48              48      100.00
  Quadric                             24              16       66.67
