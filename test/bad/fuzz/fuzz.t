Inputs the fuzzer found (make fuzz): each once crashed povml, hung it or went past a limit unseen,
and now gets an image or a located error, within test/bad's 10 seconds and 1 GiB (../run.sh). As in
test/bad, the scenes are made plain files first:

  $ for f in *.pov; do cp "$f" "$f.copy" && mv "$f.copy" "$f"; done

An infinite sphere among four others: its bounding box is infinite and its centre NaN, and building
the bounding hierarchy wrote outside its bins. It renders:

  $ sh ../run.sh bvh_infinite_sphere.pov
  bvh_infinite_sphere.pov:9:13: warning: sphere radius -inf is not positive
      9 | sphere { 0, -1e400 pigment { rgb 1 } }
        |             ^
  [exit 0, image written]

str() with a width of 12345678901234567890 (C's -2147483648): 2 GiB of padding, 12 seconds. The
string must fit in the memory limit (512 MiB under 1 GiB of address space):

  $ sh ../run.sh str_huge_width.pov
  str_huge_width.pov:5:25: error: 'str' would make a string of 2048 MiB, more than povml's memory limit of 512 MiB (raise it with --max-memory MIB)
      5 | #debug concat("Big = ", str(1e999999, 12345678901234567890, 3), "\n")
        |                         ^
  [exit 3, no image]

A mesh2 that announces 121111111111111 faces and lists one: room for the announced faces was made
before any was read, beyond the memory limit. The count is checked after the list:

  $ sh ../run.sh mesh2_huge_count.pov
  mesh2_huge_count.pov:7:16: error: face_indices says 121111111111111 entries but lists 1
      7 |   face_indices { 121111111111111, <0, 1, 2> }
        |                ^
  [exit 1, no image]

Every scene in this directory has its case above:

  $ for f in *.pov; do grep -q "run.sh $f" fuzz.t 2>/dev/null || echo "no case for $f"; done
