Errors in scenes are located (file:line:column), show the source line with a caret, exit with
status 1 and write no image.

A misspelt keyword gets a suggestion:

  $ cat > typo.pov <<'POV'
  > #version 3.7;
  > camera { location <0,0,-5> look_at 0 }
  > sphre { <0,0,0>, 1 pigment { rgb 1 } }
  > POV
  $ povml +Itypo.pov +W10 +H10 -D
  typo.pov:3:1: error: expected an object, light_source, camera or directive but found 'sphre'; did you mean 'sphere'?
      3 | sphre { <0,0,0>, 1 pigment { rgb 1 } }
        | ^
  [1]
  $ povml +Inothere.pov -D
  nothere.pov: error: cannot open the scene file: No such file or directory
  [1]
  $ ls typo.png
  ls: cannot access 'typo.png': No such file or directory
  [2]

An unknown identifier:

  $ cat > ident.pov <<'POV'
  > #declare Radius = 1;
  > sphere { 0, Raduis pigment { rgb 1 } }
  > POV
  $ povml ident.pov +W10 +H10 -D
  ident.pov:2:13: error: unknown identifier 'Raduis'; did you mean 'Radius' or 'radius'?
      2 | sphere { 0, Raduis pigment { rgb 1 } }
        |             ^
  [1]

Wrong types:

  $ printf 'sphere { <0,0,0>, <1,2,3> }\n' > type.pov
  $ povml type.pov +W10 +H10 -D
  type.pov:1:19: error: expected a float but found a 3-term vector
      1 | sphere { <0,0,0>, <1,2,3> }
        |                   ^
  [1]

A missing closing brace:

  $ printf 'sphere { <0,0,0>, 1 pigment { rgb 1 }\n' > brace.pov
  $ povml brace.pov +W10 +H10 -D
  brace.pov:1:38: error: expected an object modifier or '}' closing 'sphere' but found end of file
      1 | sphere { <0,0,0>, 1 pigment { rgb 1 }
        |                                      ^
  [1]

An unterminated comment points at where it starts:

  $ printf 'sphere { 0, 1 }\n/* never\nclosed\n' > comment.pov
  $ povml comment.pov +W10 +H10 -D
  comment.pov:2:1: error: unterminated comment: '/*' has no matching '*/'
      2 | /* never
        | ^
  [1]

A zero plane normal is refused, as POV-Ray refuses it:

  $ printf 'plane { <0,0,0>, 1 }\n' > plane.pov
  $ povml plane.pov +W10 +H10 -D
  plane.pov:1:9: error: degenerate plane normal <0,0,0>
      1 | plane { <0,0,0>, 1 }
        |         ^
  [1]

Features of later versions are named:

  $ printf 'composite { sphere { 0, 1 } }\n' > comp.pov
  $ povml comp.pov +W10 +H10 -D
  comp.pov:1:1: error: not supported yet: 'composite'
      1 | composite { sphere { 0, 1 } }
        | ^
  [1]

A cylinder or cone whose end points coincide is refused, as POV-Ray refuses it (§15.2):

  $ printf 'cylinder { <1,2,3>, <1,2,3>, 0.5 }\n' > degenerate_cylinder.pov
  $ povml degenerate_cylinder.pov +W10 +H10 -D
  degenerate_cylinder.pov:1:1: error: degenerate cylinder: its end points <1, 2, 3> and <1, 2, 3> are the same point
      1 | cylinder { <1,2,3>, <1,2,3>, 0.5 }
        | ^
  [1]
  $ printf '#version 3.7;\ncone { y, 1, y, 0.5 open }\n' > degenerate_cone.pov
  $ povml degenerate_cone.pov +W10 +H10 -D
  degenerate_cone.pov:2:1: error: degenerate cone: its end points <0, 1, 0> and <0, 1, 0> are the same point
      2 | cone { y, 1, y, 0.5 open }
        | ^
  [1]

A disc needs a normal:

  $ printf 'disc { 0, <0,0,0>, 1 }\n' > disc.pov
  $ povml disc.pov +W10 +H10 -D
  disc.pov:1:11: error: degenerate disc normal <0,0,0>
      1 | disc { 0, <0,0,0>, 1 }
        |           ^
  [1]

A cylinder of radius 0 is accepted with a warning and never seen:

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncylinder { 0, y, 0 }\n' > thin.pov
  $ povml thin.pov +W10 +H10 -D 2>&1 | grep -E 'warning|Wrote'
  thin.pov:3:18: warning: cylinder radius is 0: it cannot be seen
  Wrote thin.png (10x10)

Warnings are printed and rendering continues (POV-Ray renders a sphere of radius -1 too):

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#declare A = 1/0;\nsphere { 0, -1 }\n' > warn.pov
  $ povml warn.pov +W10 +H10 -D 2>&1 | grep -E 'warning|Wrote'
  warn.pov:3:15: warning: divide by zero; the result is infinity
  warn.pov:4:13: warning: sphere radius -1 is not positive
  Wrote warn.png (10x10)

Usage errors exit with status 2:

  $ povml +Q9 warn.pov
  povml: unknown or incomplete switch '+Q9' (see povml --help)
  [2]
  $ povml
  povml: no scene file given: use +I<file> or give the file name
  [2]
