Bad mesh input gets located errors, exit status 1 and no image (POV-Ray refuses each of these too).

An out-of-range vertex index:

  $ echo 'mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }' > a.pov
  $ povml a.pov +W10 +H10 -D
  a.pov:1:75: error: vertex index 3 is out of range: there are 3
      1 | mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,3> } }
        |                                                                           ^
  [1]

A count that disagrees with the list:

  $ echo 'mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }' > b.pov
  $ povml b.pov +W10 +H10 -D
  b.pov:1:24: error: vertex_vectors says 4 entries but lists 3
      1 | mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }
        |                        ^
  [1]

Normal indices without normals, and normals that cannot pair with the vertices:

  $ echo 'mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } normal_indices { 1, <0,1,2> } }' > c.pov
  $ povml c.pov +W10 +H10 -D
  c.pov:1:85: error: normal_indices before normal_vectors
      1 | mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } normal_indices { 1, <0,1,2> } }
        |                                                                                     ^
  [1]
  $ echo 'mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } normal_vectors { 2, y, y } face_indices { 1, <0,1,2> } }' > d.pov
  $ povml d.pov +W10 +H10 -D
  d.pov:1:84: error: normal_vectors has 2 entries and vertex_vectors 3: without normal_indices they must be as many
      1 | mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } normal_vectors { 2, y, y } face_indices { 1, <0,1,2> } }
        |                                                                                    ^
  [1]

An out-of-range texture index:

  $ echo 'mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0,1,2>, 4 } }' > e.pov
  $ povml e.pov +W10 +H10 -D
  e.pov:1:134: error: texture index 4 is out of range: the texture_list has 1
      1 | mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } texture_list { 1, texture { pigment { rgb 1 } } } face_indices { 1, <0,1,2>, 4 } }
        |                                                                                                                                      ^
  [1]

A mesh triangle takes a texture identifier only:

  $ echo 'mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> texture { pigment { rgb 1 } } } }' > f.pov
  $ povml f.pov +W10 +H10 -D
  f.pov:1:55: error: expected a texture identifier: a mesh triangle takes texture { Identifier }
      1 | mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> texture { pigment { rgb 1 } } } }
        |                                                       ^
  [1]
  $ ls *.png
  ls: cannot access '*.png': No such file or directory
  [2]

A degenerate standalone triangle is a warning, as in POV-Ray, and the render goes on:

  $ echo '#version 3.7; global_settings { assumed_gamma 1 } triangle { <0,0,0>, <1,1,1>, <2,2,2> }' > g.pov
  $ povml g.pov +W10 +H10 -D 2>&1 | grep -E 'warning|Wrote'
  g.pov:1:51: warning: degenerate triangle; please remove it
  Wrote g.png (10x10)
