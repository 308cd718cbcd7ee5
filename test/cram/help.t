--help documents the command and every POV-Ray switch it accepts.

  $ povml --help=plain > help.txt; echo $?
  0
  $ head -3 help.txt
  NAME
         povml - render POV-Ray 3.7 scenes, pixel for pixel as POV-Ray does
  
  $ for s in +I +O +W +H '+A\[' -A +AM +R '+J\[' -J +L +WT +SR +ER +SC +EC +FN +FP +D -D +V -V; do grep -q -e "$s" help.txt || echo "missing $s"; done
  $ grep -c 'EXIT STATUS' help.txt
  1

POV-Ray switches and their long forms agree:

  $ printf '#version 3.7;\nglobal_settings{assumed_gamma 1}\ncamera{location -5*z}\nlight_source{<0,5,-5>, rgb 1}\nsphere{0,1 pigment{rgb 1}}\n' > s.pov
  $ povml +Is.pov +W32 +H24 -D +Oa.png 2>/dev/null && povml s.pov --width=32 --height=24 --output=b.png 2>/dev/null && cmp a.png b.png && echo same
  same

The default output name is the scene's, beside the scene, as POV-Ray does it; +FP writes PPM:

  $ mkdir sub && cp s.pov sub/ && povml +Isub/s.pov +W8 +H6 -D 2>/dev/null && ls sub
  s.png
  s.pov
  $ povml +Isub/s.pov +W8 +H6 -D +FP 2>/dev/null && head -c 11 sub/s.ppm | od -c | head -1
  0000000   P   6  \n   8       6  \n   2   5   5  \n

A partial render writes a full-size file (unrendered pixels black):

  $ povml +Is.pov +W32 +H24 +SR0.5 +ER1.0 -D +Op.ppm +FP 2>/dev/null && head -c 12 p.ppm | od -c | head -1
  0000000   P   6  \n   3   2       2   4  \n   2   5   5

+AM2 is antialiasing method 2; as in POV-Ray, +AM0 means no antialiasing and +AM3 means method 2:

  $ povml +Is.pov +W32 +H24 -D +A0.3 +AM2 +Om2.png 2>/dev/null && povml +Is.pov +W32 +H24 -D +A0.3 +AM3 +Om3.png 2>/dev/null && cmp m2.png m3.png && echo same
  same
  $ povml +Is.pov +W32 +H24 -D +A0.3 +AM0 +Om0.png 2>/dev/null && cmp m0.png a.png && echo same
  same
  $ cmp -s m2.png a.png || echo differs
  differs
