Transforms through --dump. A sphere keeps a plain centre and radius under translate, rotate and
uniform scale and gets a matrix for anything else (POV-Ray's per-shape rules); 'transform { T
inverse }' inverts the whole block; union{} is dissolved into its members, which inherit its pigment,
and its lights move with it; the camera's vectors are transformed. The positions below were checked
against POV-Ray's min_extent/max_extent of the same objects (rotations are not rounded: cos 90° is
6.1e-17 as in POV-Ray).

  $ cat > tr.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 0, -5> look_at <0, 0, 0> rotate <0, 90, 0> translate <1, 0, 0> }
  > light_source { <0, 10, 0> rgb 1 translate <1, 0, 0> }
  > sphere { <1, 0, 0>, 1 scale 2 }
  > sphere { <1, 0, 0>, 1 rotate <0, 0, 90> translate <0, 0, 1> }
  > sphere { 0, 1 scale <1, 2, 3> }
  > sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 1,2,3> }
  > #declare T = transform { rotate <0, 0, 90> translate <1, 0, 0> }
  > sphere { <1, 0, 0>, 0.5 transform T }
  > sphere { <1, 1, 0>, 0.5 transform { T inverse } }
  > sphere { <1, 0, 0>, 0.5 transform { T scale 2 } }
  > sphere { 0, 1 scale <1, 2, 1> transform { scale <1, 2, 1> inverse } }
  > union {
  >   sphere { <1, 0, 0>, 0.5 }
  >   sphere { <2, 0, 0>, 0.5 pigment { rgb <1, 0, 0> } }
  >   light_source { <0, 1, 0> rgb 1 }
  >   pigment { rgb <0, 1, 0> }
  >   translate <0, 0, 10>
  > }
  > plane { y, 1 rotate <0, 0, 90> }
  > sphere { 0, 1 matrix <1,1,0, 0,1,0, 0,0,1, 0,0,0> }
  > #declare O = sphere { 0, 1 translate x }
  > object { O rotate y*90 }
  > #declare TT = transform { scale 2 translate y }
  > #declare U = union { sphere { 0, 1 } light_source { <0, 0, 1> rgb <1, 1, 0> } transform TT }
  > object { U translate x }
  > POV
  $ povml --dump tr.pov
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <-4, 0, -3.061616998e-16> direction <1, 0, 6.123233996e-17> up <0, 1, 0> right <8.143901214e-17, 0, -1.33> }
  background { rgb <0, 0, 0> }
  light_source { <1, 10, 0>, rgb <1, 1, 1> }
  light_source { <0, 1, 10>, rgb <1, 1, 1> }
  light_source { <1, 1, 2>, rgb <1, 1, 0> }
  sphere { <2, 0, 0>, 2
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:5:1
  sphere { <6.123233996e-17, 1, 1>, 1
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:6:1
  sphere { <0, 0, 0>, 1
    matrix <1, 0, 0, 0, 2, 0, 0, 0, 3, 0, 0, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:7:1
  sphere { <0, 0, 0>, 1
    matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 2, 3>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:8:1
  sphere { <1, 0, 0>, 0.5
    matrix <6.123233996e-17, 1, 0, -1, 6.123233996e-17, 0, 0, 0, 1, 1, 0, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:10:1
  sphere { <1, 1, 0>, 0.5
    matrix <6.123233996e-17, -1, 0, 1, 6.123233996e-17, 0, 0, 0, 1, -6.123233996e-17, 1, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:11:1
  sphere { <1, 0, 0>, 0.5
    matrix <1.224646799e-16, 2, 0, -2, 1.224646799e-16, 0, 0, 0, 2, 2, 0, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:12:1
  sphere { <0, 0, 0>, 1
    matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:13:1
  sphere { <1, 0, 10>, 0.5
    texture { pigment { rgb <0, 1, 0> } }
  } // tr.pov:15:3
  sphere { <2, 0, 10>, 0.5
    texture { pigment { rgb <1, 0, 0> } }
  } // tr.pov:16:3
  plane { <-1, 6.123233996e-17, 0>, 1
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:21:1
  sphere { <0, 0, 0>, 1
    matrix <1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:22:1
  sphere { <6.123233996e-17, 0, -1>, 1
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:24:1
  sphere { <0, 0, 0>, 1
    matrix <2, 0, 0, 0, 2, 0, 0, 0, 2, 1, 1, 0>
    texture { pigment { rgb <0, 0, 0> } }
  } // tr.pov:26:22
  // 14 objects, 3 lights

Cylinders, cones and discs always carry their canonical transform (§15.2–§15.4): the dump shows
them as written, with the matrix from canonical space to the world (P2 of a cylinder at z = 0;
a cone's apex at z = 0, its big end at z = 1), and a disc's normal as the modifiers moved it:

  $ cat > q.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > cylinder { <0, 2, 0>, <0, 0, 0>, 0.5 open translate x }
  > cone { <0, 0, 1>, 1, <0, 0, 0>, 0.5 inverse }
  > disc { 0, <1, 1, 0>, 1, 0.5 scale <2, 1, 1> }
  > POV
  $ povml q.pov --dump 2>&1 | grep -A1 -E '^ *(cylinder|cone|disc)'
  cylinder { <0, 2, 0>, <0, 0, 0>, 0.5 open // canonical cylinder
    matrix <0.5, 0, 0, 0, 3.061616998e-17, -0.5, 0, 2, 1.224646799e-16, 1, 0, 0>
  --
    cone { <0, 0, 1>, 1, <0, 0, 0>, 0.5 // canonical cone from z = 0.5
      matrix <1, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, -1>
  --
  disc { <0, 0, 0>, <0.4472135955, 0.894427191, 0>, 1, 0.5 // centre as written, normal as moved
    matrix <1, -0.5, -0.7071067812, -1, 0.5, -0.7071067812, 1.414213562, 0.7071067812, 6.123233996e-17, 0, 0, 0>
