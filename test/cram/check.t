povml check renders a scene with povml and with the installed POV-Ray (same switches) and compares
the two images; povml report sweeps settings in both. These tests run POV-Ray (make deps installs it).

  $ cat > s.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location -5*z look_at 0 }
  > light_source { <0, 5, -5>, rgb 1 }
  > sphere { <clock, 0, 0>, 1 pigment { rgb <1, 0.5, 0.2> } finish { phong 0.5 } }
  > POV

Identical images pass; the times vary from run to run, the rest does not:

  $ povml check s.pov +W32 +H24 > out.txt; echo "exit $?"
  exit 0
  $ grep -v -e '^povml ' -e '^POV-Ray ' -e '^time ' out.txt
  switches  +W32 +H24 +WT2
  differing 0 of 768 pixels (0.0000%)
  peak      0/255
  RMSE      0.0000/255
  PSNR      inf (identical)
  heat map  s-diff.png (equal: dark grey; differing: blue = 1/255 … yellow = the peak, 0/255)
  result    PASS
  $ grep -c -E '^(povml|POV-Ray) +[0-9.]+ s +s(-povray)?\.png$' out.txt
  2
  $ ls s*.png
  s-diff.png
  s-povray.png
  s.png
  $ povml check s.pov +W32 +H24 --max-differing 0 --max-peak 0 --min-psnr 100 > /dev/null; echo "exit $?"
  exit 0

A threshold exceeded fails with exit status 1. To get images that differ for certain, POV-Ray is
run through a wrapper that adds +K1 (the sphere moves by one unit), a switch povml does not get:

  $ printf '#!/bin/sh\nexec povray "$@" +K1\n' > moved-povray; chmod +x moved-povray
  $ povml check s.pov +W32 +H24 +Oc.png --povray ./moved-povray --max-differing 0.01 --max-peak 300 > out.txt; echo "exit $?"
  exit 1
  $ grep '^result' out.txt | sed 's/[0-9][0-9]* of 768 pixels differ (share [0-9.e-]*)/N of 768 pixels differ/'
  result    FAIL: N of 768 pixels differ, above --max-differing 0.01
  $ ls c*.png
  c-diff.png
  c-povray.png
  c.png

POV-Ray missing: a clear message and exit status 4.

  $ povml check s.pov --povray /nonexistent/povray
  povml check: error: POV-Ray was not found: '/nonexistent/povray' (from --povray) is not an executable file; install POV-Ray 3.7 (Debian/Ubuntu: apt-get install povray) or name its executable with --povray PATH or the POVRAY environment variable
  [4]
  $ POVRAY=/nonexistent/povray povml check s.pov 2>&1 | cut -c1-85
  povml check: error: POV-Ray was not found: '/nonexistent/povray' (from POVRAY) is not
  $ env -u POVRAY PATH=/nonexistent "$(command -v povml)" check s.pov 2>&1 | cut -c1-79
  povml check: error: POV-Ray was not found: no 'povray' in PATH; install POV-Ray

A renderer that fails (here povml, on an object it does not support yet) gives its message and
exit status 3:

  $ printf '#version 3.7;\ncomposite { sphere { 0, 1 } }\n' > comp.pov
  $ povml check comp.pov
  povml check: error: povml failed (exit status 1): comp.pov:2:1: error: not supported yet: 'composite'
  [3]

Usage errors (exit status 2):

  $ povml check
  povml check: error: no scene file given: povml check SCENE [switches]
  [2]
  $ povml check nothere.pov
  povml check: error: scene file not found: nothere.pov
  [2]
  $ povml check s.pov +Q9
  povml check: error: unknown or incomplete switch '+Q9' (see povml --help)
  [2]

povml report: one sweep part, one level, one run (a full report takes minutes):

  $ povml report s.pov --out rep +W16 +H12 --runs 1 --parts trace --trace-levels 1,2 2> progress.txt
  rep/report.csv
  rep/report.md
  rep/report.svg
  rep/s.svg
  $ cut -d, -f4,5,10,11,12 rep/report.csv
  renderer,setting,max_trace_level,status,runs
  POV-Ray,ground truth: +AM2 +R5 +A0.0,scene,truth,1
  povml,-A max_trace_level 1,1,ok,1
  POV-Ray,-A max_trace_level 1,1,ok,1
  povml,-A max_trace_level 2,2,ok,1
  POV-Ray,-A max_trace_level 2,2,ok,1
  $ grep -c '^s.pov \[' progress.txt
  2
  $ grep -c '<polyline\|<circle\|<rect' rep/s.svg > /dev/null && head -c 38 rep/s.svg
  <?xml version="1.0" encoding="UTF-8"?>

Two scenes of the same name get their own files, and each its own copy for the max_trace_level
override: with the ground truth rendered with -A, a scene without reflections has error 0 at any
level:

  $ mkdir sub && sed 's/rgb <1, 0.5, 0.2>/rgb <0.2, 0.5, 1>/' s.pov > sub/s.pov
  $ povml report s.pov sub/s.pov --out rep2 +W16 +H12 --runs 1 --parts trace --trace-levels 1 --truth=-A 2> /dev/null
  rep2/report.csv
  rep2/report.md
  rep2/report.svg
  rep2/s.svg
  rep2/s-2.svg
  $ cut -d, -f1,4,11,15 rep2/report.csv
  scene,renderer,status,rmse
  s.pov,POV-Ray,truth,0
  s.pov,povml,ok,0
  s.pov,POV-Ray,ok,0
  sub/s.pov,POV-Ray,truth,0
  sub/s.pov,povml,ok,0
  sub/s.pov,POV-Ray,ok,0

Report usage errors:

  $ povml report s.pov
  povml report: error: no output directory given: --out DIR
  [2]
  $ povml report s.pov --out rep +A0.3
  povml report: error: +A0.3: the report sweeps +A, +AM and +R itself and names its own images (+O, +F)
  [2]
  $ povml report s.pov nothere.pov --out rep
  povml report: error: scene file not found: nothere.pov
  [2]
  $ povml report s.pov --out s.pov/x
  povml report: error: cannot create the output directory s.pov/x: Not a directory
  [1]
  $ povml report s.pov --out rep --trace-levels 5-1 2>&1 | head -1
  povml: option '--trace-levels': expected integers and ranges like 1-4,8, got
  $ povml report s.pov --out rep --trace-levels 5-1 2> /dev/null
  [2]
