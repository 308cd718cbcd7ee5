Scenes as large as molecule and point-cloud exports, and images and animations as large as povml
allows, render within 2 GiB of address space (ulimit -v), or stop with a clean answer: no stack
overflow, no unbounded memory, no internal error.

  $ run() { (ulimit -v 2097152; exec timeout 120 povml "$@" -D) 2>err.txt >/dev/null; s=$?; grep -E "error|Wrote" err.txt; echo "[exit $s]"; }
  $ field() { awk -v n=$1 -v c=$2 'BEGIN { print "#version 3.7; global_settings { assumed_gamma 1 }";
  >   print "camera { location <0, 0, -30> look_at 0 } light_source { <10, 20, -30>, rgb 1 }";
  >   for (i = 0; i < n; i++) printf "sphere { <%.3f, %.3f, %.3f>, 0.02 pigment { rgb <%.3f, %.3f, 1> } }\n",
  >     (i % 100) / 5 - 10, (int(i / 100) % 100) / 5 - 10, int(i / 10000) / 5 - 10, (i % c) / c, int(i / c) % c / c }'; }

A million spheres, each with a pigment of its own, in 256 colours (the list of objects once
overflowed the stack at about 250,000, and equal pigments compiled one by one cost a quadratic
search):

  $ field 1000000 16 > million.pov
  $ run million.pov +W80 +H60 +Omillion.png
  Wrote million.png (80x60)
  [exit 0]

A million spheres each of a colour of its own (surfaces share what they take from an equal finish,
objects their interior, and the scene's objects are let go as they are compiled):

  $ field 1000000 1000 > colours.pov
  $ run colours.pov +W80 +H60 +Ocolours.png
  Wrote colours.png (80x60)
  [exit 0]

A declared union of 300,000 spheres placed with object {}:

  $ { echo '#version 3.7; global_settings { assumed_gamma 1 }'
  >   echo 'camera { location <0, 0, -30> look_at 0 } light_source { <10, 20, -30>, rgb 1 }'
  >   echo '#declare Cloud = union {'
  >   awk 'BEGIN { for (i = 0; i < 300000; i++) printf "sphere { <%d, %d, %d>, 0.3 }\n", i % 67 - 33, int(i / 67) % 67 - 33, int(i / 4489) - 33 }'
  >   echo '}'
  >   echo 'object { Cloud pigment { rgb 1 } }'; } > cloud.pov
  $ run cloud.pov +W80 +H60 +Ocloud.png
  Wrote cloud.png (80x60)
  [exit 0]

The largest image the default pixel limit allows, 8192×8192, renders in 2 GiB: the image is kept
in single precision and filled as blocks come back:

  $ cat > plain.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 0, -4> look_at 0 }
  > light_source { <3, 5, -5>, rgb 1 }
  > sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
  > POV
  $ run plain.pov +W8192 +H8192 +Obig.png
  Wrote big.png (8192x8192)
  [exit 0]
  $ rm big.png

Where the system gives less than a render needs, povml says so (exit 3, a limit), no internal error
and no image:

  $ (ulimit -v 1048576; povml plain.pov +W8192 +H8192 +WT1 -D +Osmall_memory.png); echo "[exit $?]"
  povml: error: the render needs more memory than the system gives this process (ulimit -v); no image was written (a smaller image, +W and +H, needs less)
  [exit 3]
  $ ls small_memory.png
  ls: cannot access 'small_memory.png': No such file or directory
  [2]

A size whose pixel count overflows is a limit error that says so:

  $ povml plain.pov +W4294967296 +H4294967296 -D
  error: a 4294967296×4294967296 image has over 4,611,686,018,427,387,903 pixels, more than povml's limit of 67,108,864 (raise it with --max-pixels N)
  [3]

A PNG is at most 1,000,000 pixels wide and high (libpng's limit; POV-Ray's render of a wider one
fails when it writes it): povml says so before it renders. A PPM has no such limit: the widest
image the pixel limit allows, one row of 67,108,864 pixels (two million blocks, each once given a
worker's rooms of its own), renders within 2 GiB:

  $ povml plain.pov +W67108864 +H1 -D +Owide.png
  error: a PNG is at most 1,000,000 pixels wide and high (libpng's limit; POV-Ray's render fails when it writes one), this image is 67108864×1: write a PPM instead (+FP)
  [3]
  $ run plain.pov +W67108864 +H1 +FP +WT1 +Owide.ppm
  Wrote wide.ppm (67108864x1)
  [exit 0]
  $ head -c 20 wide.ppm | head -2
  P6
  67108864 1
  $ rm wide.ppm

An animation of two billion frames renders frame after frame, as POV-Ray does, its frames made one
at a time (they were a list of two billion frames first):

  $ mkdir frames
  $ (ulimit -v 2097152; timeout 5 povml plain.pov +KFF2000000000 +W8 +H6 -D +Oframes/f.png 2>/dev/null); echo "[exit $?]"
  [exit 124]
  $ ls frames | head -2
  f0000000001.png
  f0000000002.png

An ini file that includes a directory, or a file without end:

  $ echo 'Include_Ini=.' > dir.ini
  $ povml dir.ini plain.pov -D
  dir.ini:1:1: error: cannot read the ini file ".": it is a directory
      1 | Include_Ini=.
        | ^
  [1]
  $ ln -s /dev/zero zero.ini
  $ povml zero.ini plain.pov -D
  error: the ini file "zero.ini" is longer than 16777216 bytes
  [3]
