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

POV-Ray's options that povml does not read yet are named in a warning and ignored; those whose
value is what povml does anyway (POV-Ray's defaults, console and display settings) pass silently:

  $ printf 'Output_Alpha=on\nPause_When_Done=off\nSplit_Unions=on\nRemove_Bounds=on\nVerbose=on\n' > more.ini
  $ povml s.pov more.ini +W8 +H6 -D +Oi.png 2>&1 | grep -E 'warning|Wrote'
  more.ini:1:1: warning: the ini option 'Output_Alpha=on' is not supported yet; ignored
  more.ini:3:1: warning: the ini option 'Split_Unions=on' is not supported yet; ignored
  Wrote i.png (8x6)

Output_to_File=off (-F) renders without writing the image; Bounding=off (-MB) and
Bounding_Threshold (+MBn) decide whether POV-Ray's bounding tree is used (fidelity scenes
bounding_threshold_4, bounding_threshold_5, bounding_off):

  $ printf 'Output_to_File=off\nBounding_Threshold=3\n' > nofile.ini
  $ povml s.pov nofile.ini +W8 +H6 -D +Onofile.png 2>&1 | grep -E 'warning|Wrote|Render Time'
  Render Time:    0 hours  0 minutes  0 seconds (0.000 seconds)
  $ ls nofile.png
  ls: cannot access 'nofile.png': No such file or directory
  [2]
  $ povml s.pov nofile.ini +W8 +H6 -D +F +Onofile.png 2>&1 | grep Wrote
  Wrote nofile.png (8x6)
  $ povml s.pov +W8 +H6 -D -MB +MB2 -F 2>&1 | grep -c warning
  0
  [1]

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

Before the command line povml reads one ini file, as POV-Ray's Unix front end does: the file the
POVINI environment variable names, else the first of ./povray.ini, ~/.povray/3.7/povray.ini,
/etc/povray/3.7/povray.ini, ~/.povrayrc and /etc/povray.ini. (These tests run with POVINI naming
an empty file, /dev/null.) Its settings come first, so the command line wins:

  $ printf 'Width=20\nHeight=10\nAntialias=on\n' > mine.ini
  $ POVINI=$PWD/mine.ini povml s.pov -D +Om1.png 2>&1 | grep -E '^(Pixels|Wrote)'
  Pixels:              200   Samples:             369   Smpls/Pxl: 1.84
  Wrote m1.png (20x10)
  $ povml --no-povray-ini s.pov +W20 +H10 +A -D +Om0.png 2>/dev/null; cmp m0.png m1.png && echo "same as +W20 +H10 +A"
  same as +W20 +H10 +A
  $ POVINI=$PWD/mine.ini povml s.pov +W8 +H6 -A -D +Om2.png 2>&1 | grep -E '^(Pixels|Wrote)'
  Pixels:               48   Samples:               0   Smpls/Pxl: 0.00
  Wrote m2.png (8x6)

--no-povray-ini reads none (POV-Ray's defaults: 160×120):

  $ POVINI=$PWD/mine.ini povml --no-povray-ini s.pov -D +Om3.png 2>&1 | grep Wrote
  Wrote m3.png (160x120)

A POVINI that names no file is a warning, and the search goes on: here to ./povray.ini, which
comes before the user's and the system's:

  $ mkdir -p run home/.povray/3.7 && printf 'Width=12\nHeight=9\n' > run/povray.ini && printf 'Width=14\nHeight=7\n' > home/.povray/3.7/povray.ini
  $ cd run && POVINI=$PWD/none.ini HOME=$PWD/../home povml ../s.pov -D +O../m4.png 2>&1 | grep -E 'warning|Wrote'; cd ..
  warning: the POVINI environment variable names "$TESTCASE_ROOT/run/none.ini", which cannot be read; looking for povray.ini
  Wrote ../m4.png (12x9)
  $ env -u POVINI HOME=$PWD/home povml s.pov -D +Om5.png 2>&1 | grep -E 'warning|Wrote'
  Wrote m5.png (14x7)

Without any of those, Debian's /etc/povray/3.7/povray.ini (installed with POV-Ray) sets 800×600
and a bounding threshold of 3, silently:

  $ env -u POVINI HOME=/nonexistent povml s.pov -D +Om6.png 2>&1 | grep -E 'warning|Wrote'
  Wrote m6.png (800x600)

+A and Antialias_Threshold set one threshold, so the later wins, whichever of them it is:

  $ printf 'Antialias_Threshold=0.9\n' > t9.ini
  $ povml s.pov +W20 +H10 -D t9.ini +A0.01 +Om8.png 2>&1 | grep Samples
  Pixels:              200   Samples:             369   Smpls/Pxl: 1.84
  $ povml s.pov +W20 +H10 -D +A0.01 t9.ini +Om9.png 2>&1 | grep Samples
  Pixels:              200   Samples:             252   Smpls/Pxl: 1.26

The POVINC environment variable names one more include directory, searched after all others:

  $ mkdir inc && printf '#declare R = 0.5;\n' > inc/r.inc && printf '#include "r.inc"\nsphere { 0, R pigment { rgb 1 } }\n' > inc.pov
  $ povml inc.pov +W8 +H6 -D +Om7.png 2>&1 | grep -E 'error'
  inc.pov:1:1: error: cannot find the include file "r.inc" (searched ., /usr/share/povray-3.7/include)
  $ POVINC=$PWD/inc povml inc.pov +W8 +H6 -D +Om7.png 2>&1 | grep -E 'error|Wrote'
  Wrote m7.png (8x6)
