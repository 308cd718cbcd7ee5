.ini files stand for the switches they hold, read where they are named on the command line, so
the later of an ini option and a switch wins. Lines are Key=Value options (any case), switches,
comments after ';' or '#', and [Section] headers: the lines before the first section always
count, a named section only when asked for as file.ini[Section].

  $ cat > s.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location -5*z look_at 0 }
  > light_source { <0, 5, -5>, rgb 1 }
  > sphere { <clock, 0, 0>, 1 pigment { rgb <1, 0.5, 0.2> } }
  > POV
  $ cat > a.ini <<'INI'
  > ; a comment
  > # another
  > Width=32   ; a comment after a value
  > height = 24
  > Antialias=Off
  > +K0.5
  > Input_File_Name=s.pov
  > [Big]
  > Width=64
  > Height=48
  > [Other]
  > Width=8
  > INI
  $ povml a.ini -D +Oa.png 2>&1 | grep Wrote
  Wrote a.png (32x24)
  $ povml 'a.ini[big]' -D +Ob.png 2>&1 | grep Wrote
  Wrote b.png (64x48)
  $ povml a.ini +W16 +H12 -D +Oc.png 2>&1 | grep Wrote
  Wrote c.png (16x12)
  $ povml +W16 +H12 a.ini -D +Od.png 2>&1 | grep Wrote
  Wrote d.png (32x24)

+K0.5 in the ini file moved the sphere: the same image as the switch on the command line.

  $ povml s.pov +W32 +H24 -D +K0.5 +Oe.png 2>&1 | grep Wrote
  Wrote e.png (32x24)
  $ cmp a.png e.png && echo same
  same

Include_Ini and a plain ini name read another file there; a plain other name is the scene.
Antialias_Threshold sets the threshold without turning antialiasing on (as POV-Ray's does):

  $ printf 'Antialias_Threshold=0.1\nAntialias=on\n' > aa.ini
  $ printf 'Include_Ini=a.ini\naa.ini\n' > b.ini
  $ povml b.ini -D +Of.png 2>&1 | grep -E '^(Pixels|Wrote)'
  Pixels:              768   Samples:             900   Smpls/Pxl: 1.17
  Wrote f.png (32x24)
  $ printf 'Antialias_Threshold=0.1\n' > c.ini
  $ povml a.ini c.ini -D +Og.png 2>&1 | grep -E '^(Pixels|Wrote)'
  Pixels:              768   Samples:               0   Smpls/Pxl: 0.00
  Wrote g.png (32x24)
  $ printf 'Width=16\nHeight=12\ns.pov\n' > d.ini
  $ povml d.ini -D +Oh.png 2>&1 | grep Wrote
  Wrote h.png (16x12)

POV-Ray's options that povml does not read yet are named in a warning and ignored:

  $ printf 'Output_Alpha=on\nPause_When_Done=off\n' > more.ini
  $ povml s.pov more.ini +W8 +H6 -D +Oi.png 2>&1 | grep -E 'warning|Wrote'
  more.ini:1:1: warning: the ini option 'Output_Alpha' is not supported yet; ignored
  more.ini:2:1: warning: the ini option 'Pause_When_Done' is not supported yet; ignored
  Wrote i.png (8x6)

Declare=NAME=VALUE declares an identifier before the scene is read, as POV-Ray's front end passes
it: a float in single precision with six significant digits (1.23456789 is 1.23457, as POV-Ray
prints it), or a string when quoted. Ini options may be given on the command line too:

  $ cat > d.pov <<'POV'
  > #version 3.7;
  > #debug concat("Size=", str(Size,0,17), " Name=", Name, "\n")
  > camera { location -5*z look_at 0 }
  > sphere { 0, Size pigment { rgb 1 } }
  > POV
  $ printf 'Declare=Size=1.23456789\n' > d.ini
  $ povml d.pov d.ini 'Declare=Name="a name"' Width=16 +H6 -D +Ok.png 2>&1 | grep -E '^(Size|Wrote)'
  Size=1.23456999999999995 Name=a name
  Wrote k.png (16x6)

A key POV-Ray does not have, a value an option cannot take, a file that cannot be read: located
errors, status 1, no image.

  $ printf 'Width=32\nWidht=3\n' > bad.ini
  $ povml bad.ini s.pov -D +Oj.png; echo "exit $?"
  bad.ini:2:1: error: unknown ini option 'Widht' (POV-Ray 3.7 has no such key)
      2 | Widht=3
        | ^
  exit 1
  $ printf 'Antialias=maybe\n' > bad2.ini
  $ povml bad2.ini s.pov -D +Oj.png; echo "exit $?"
  bad2.ini:1:1: error: 'maybe' is not a value of the ini option 'Antialias'
      1 | Antialias=maybe
        | ^
  exit 1
  $ printf 'Width = wide\n' > bad3.ini
  $ povml bad3.ini s.pov -D +Oj.png; echo "exit $?"
  bad3.ini:1:1: error: 'wide' is not a value of the ini option 'Width'
      1 | Width = wide
        | ^
  exit 1
  $ povml nosuch.ini s.pov -D +Oj.png; echo "exit $?"
  error: cannot open the ini file "nosuch.ini"
  exit 1
  $ ls j.png
  ls: cannot access 'j.png': No such file or directory
  [2]
