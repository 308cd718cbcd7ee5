CSG (§16): what enters the scene, through --dump, and the messages for CSG written wrong.

A difference is an intersection whose members after the first are inverted; the member with its
own pigment keeps it, the others take the CSG's; only the box has its own interior:

  $ cat > diff.pov <<'POV'
  > #version 3.7;
  > difference {
  >   box { -1, 1 interior { ior 2 } }
  >   sphere { 0, 1.2 pigment { rgb <0, 0, 1> } }
  >   pigment { rgb <1, 0, 0> }
  >   translate x
  > }
  > POV
  $ povml --dump diff.pov 2>/dev/null | grep -v '^//' | sed -n '/intersection/,$p'
  intersection {
    box { <0, -1, -1>, <2, 1, 1>
      texture { pigment { rgb <1, 0, 0> } }
      interior { ior 2 }
    } // diff.pov:3:3
    sphere { <1, 0, 0>, 1.2
      texture { pigment { rgb <0, 0, 1> } }
    } // diff.pov:4:3 inverse shared interior
    texture { pigment { rgb <1, 0, 0> } }
  } // diff.pov:2:1

inverse on a union turns it into an intersection of the inverted members (De Morgan, §16.3); a plane
turns over instead:

  $ cat > inv.pov <<'POV'
  > union { sphere { 0, 1 } plane { y, 1 } inverse }
  > POV
  $ povml --dump inv.pov 2>/dev/null | grep -v '^//' | grep -v pigment | sed -n '/intersection/,$p'
  intersection {
    sphere { <0, 0, 0>, 1
    } // inv.pov:1:9 inverse shared interior
    plane { <0, -1, 0>, -1
    } // inv.pov:1:25 shared interior
  } // inv.pov:1:1

A CSG with fewer than two members is a warning, as in POV-Ray; an empty one is accepted:

  $ cat > few.pov <<'POV'
  > difference { sphere { 0, 1 } }
  > merge { }
  > POV
  $ povml few.pov +W4 +H4 -D +O/dev/null 2>&1 | grep -A2 members
  few.pov:1:1: warning: a difference should have at least two members
      1 | difference { sphere { 0, 1 } }
        | ^
  few.pov:2:1: warning: a merge should have at least two members
      2 | merge { }
        | ^

split_union is for unions (a merge accepts it and is never split); on another object it is an
error, as in POV-Ray:

  $ printf 'merge { sphere { 0, 1 } sphere { x, 1 } split_union off }\n' > merge.pov
  $ povml merge.pov +W4 +H4 -D +O/dev/null 2>&1 | grep split_union
  [1]
  $ printf 'intersection { sphere { 0, 1 } sphere { x, 1 } split_union off }\n' > split.pov
  $ povml split.pov +W4 +H4 -D
  split.pov:1:48: error: split_union found in a non-union object
      1 | intersection { sphere { 0, 1 } sphere { x, 1 } split_union off }
        |                                                ^
  [1]
  $ printf 'sphere { 0, 1 split_union on }\n' > split2.pov
  $ povml split2.pov +W4 +H4 -D
  split2.pov:1:15: error: split_union found in a non-union object
      1 | sphere { 0, 1 split_union on }
        |               ^
  [1]

Something that is not an object among the members is an error:

  $ printf 'intersection { sphere { 0, 1 } pigment { rgb 1 } box { 0, 1 } }\n' > notobj.pov
  $ povml notobj.pov +W4 +H4 -D
  notobj.pov:1:50: error: expected an object modifier or '}' closing 'intersection' but found 'box'
      1 | intersection { sphere { 0, 1 } pigment { rgb 1 } box { 0, 1 } }
        |                                                  ^
  [1]
  $ printf 'difference { sphere { 0, 1 } 42 }\n' > number.pov
  $ povml number.pov +W4 +H4 -D
  number.pov:1:30: error: expected an object modifier or '}' closing 'difference' but found number 42
      1 | difference { sphere { 0, 1 } 42 }
        |                              ^
  [1]
  $ printf '#declare P = pigment { rgb 1 }\nunion { sphere { 0, 1 } P }\n' > ident.pov
  $ povml ident.pov +W4 +H4 -D
  ident.pov:2:25: error: expected an object modifier or '}' closing 'union' but found 'P', which is a pigment
      2 | union { sphere { 0, 1 } P }
        |                         ^
  [1]

clipped_by needs at least one object; clipped_by { bounded_by } links the clips to bounds that
must come first, as POV-Ray's parser requires:

  $ printf 'sphere { 0, 1 clipped_by { } }\n' > clip.pov
  $ povml clip.pov +W4 +H4 -D
  clip.pov:1:28: error: expected an object in clipped_by but found '}'
      1 | sphere { 0, 1 clipped_by { } }
        |                            ^
  [1]
  $ printf 'sphere { 0, 1 clipped_by { box { 0, 1 } } clipped_by { bounded_by } }\n' > clip2.pov
  $ povml clip2.pov +W4 +H4 -D
  clip2.pov:1:56: error: Cannot link bounds with previous clips.
      1 | sphere { 0, 1 clipped_by { box { 0, 1 } } clipped_by { bounded_by } }
        |                                                        ^
  [1]
  $ printf 'sphere { 0, 1 bounded_by { box { 0, 1 pigment { rgb 1 } } } }\n' > bound.pov
  $ povml bound.pov +W4 +H4 -D
  bound.pov:1:28: error: Illegal texture or patch in clip, bound or object pattern.
      1 | sphere { 0, 1 bounded_by { box { 0, 1 pigment { rgb 1 } } } }
        |                            ^
  [1]
