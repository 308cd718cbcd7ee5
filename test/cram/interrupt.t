An interrupted render (SIGINT, SIGTERM) stops at once: its worker processes are killed, no image
is written, an existing one stays as it was and no temporary file is left behind. After SIGKILL,
where nothing can run, the workers notice that their parent is gone and exit.

A scene that takes about half a minute at 2400x1800 on two processes, and one whose parsing takes
as long:

  $ cat > slow.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 max_trace_level 10 }
  > camera { location <0, 3, -12> look_at 0 }
  > light_source { <5, 10, -5>, rgb 1 }
  > light_source { <-5, 8, -3>, rgb 0.5 }
  > #for (I, 0, 199)
  >   sphere { <mod(I, 20) - 9.5, 0.3 * div(I, 20) - 1, 0.5 * div(I, 20)>, 0.45
  >            pigment { rgb <0.8, 0.5, 0.3> } finish { reflection 0.8 phong 1 } }
  > #end
  > plane { y, -2 pigment { rgb 0.5 } finish { reflection 0.5 } }
  > POV
  $ cat > parse.pov <<'POV'
  > #debug "parsing\n"
  > #declare S = 0;
  > #for (I, 1, 4000000)
  >   #declare S = S + sin(I) * cos(I) + sqrt(I) + ln(I) + atan2(I, S + 1) + pow(I, 0.3) + abs(S) + max(I, S) + min(I, S) + mod(I, 7);
  > #end
  > sphere { 0, 1 pigment { rgb 1 } }
  > POV

Helpers. [until_ N CMD] waits up to N tenths of a second for CMD to succeed. [start] runs povml in
the background (the shell would have it ignore SIGINT, hence env) with its temporary files in
tmp/, and waits until its two workers run. [alive] is false for a process that has exited, also
while it waits as a zombie to be reaped by init.

  $ mkdir tmp
  $ until_ () { n=$1; shift; i=0; while ! "$@"; do i=$((i + 1)); if [ $i -ge $n ]; then echo "timed out: $*"; return 1; fi; sleep 0.1; done; }
  $ alive () { s=$(cut -d' ' -f3 "/proc/$1/stat" 2>/dev/null); [ -n "$s" ] && [ "$s" != Z ]; }
  $ two_workers () { [ "$(pgrep -P "$pid" | wc -l)" -eq 2 ]; }
  $ workers_gone () { for w in $ws; do if alive "$w"; then return 1; fi; done; }
  $ start () { env --default-signal=INT TMPDIR="$PWD/tmp" povml slow.pov +W2400 +H1800 +A0.0 +WT2 -D "$@" 2>err & pid=$!; until_ 600 two_workers; ws=$(pgrep -P "$pid"); }

SIGINT during the render: status 130, one line, no image, no temporary file, no worker left:

  $ start +Oa.png
  $ kill -INT $pid; wait $pid; echo "exit $?"
  exit 130
  $ cat err
  povml: interrupted by SIGINT; no image was written
  $ ls -A . tmp | grep -v interrupt.t
  .:
  err
  parse.pov
  slow.pov
  tmp
  
  tmp:
  $ workers_gone && echo "workers gone"
  workers gone

An existing image is left byte for byte as it was:

  $ printf 'the previous image\n' > b.png; cp b.png before
  $ start +Ob.png
  $ kill -INT $pid; wait $pid; echo "exit $?"
  exit 130
  $ cmp b.png before && echo unchanged
  unchanged
  $ ls -A | grep -c part
  0
  [1]

SIGTERM: status 143, the same way:

  $ start +Ob.png
  $ kill -TERM $pid; wait $pid; echo "exit $?"
  exit 143
  $ cat err
  povml: interrupted by SIGTERM; no image was written
  $ cmp b.png before && echo unchanged
  unchanged
  $ workers_gone && echo "workers gone"
  workers gone

Ctrl-C at a terminal reaches the whole process group, workers included; the workers ignore it and
povml ends them:

  $ env --default-signal=INT TMPDIR="$PWD/tmp" setsid povml slow.pov +W2400 +H1800 +A0.0 +WT2 -D +Oe.png 2>err & pid=$!
  $ until_ 600 two_workers; ws=$(pgrep -P "$pid")
  $ [ "$(ps -o pgid= -p $pid | tr -d ' ')" = "$pid" ] && echo "own process group"
  own process group
  $ kill -INT -$pid; wait $pid; echo "exit $?"
  exit 130
  $ cat err
  povml: interrupted by SIGINT; no image was written
  $ workers_gone && echo "workers gone"
  workers gone

SIGINT while parsing:

  $ env --default-signal=INT povml parse.pov -D +Of.png 2>err & pid=$!
  $ until_ 600 grep -q parsing err
  $ kill -INT $pid; wait $pid; echo "exit $?"
  exit 130
  $ cat err
  parsing
  povml: interrupted by SIGINT; no image was written
  $ ls f.png
  ls: cannot access 'f.png': No such file or directory
  [2]

SIGKILL: nothing runs in povml, but nothing is written before the render is complete, and the
workers exit on their own within a second (10 s allowed here). The shell's own "Killed" notice is
left out: when it is printed depends on when the shell reaps the process.

  $ start +Ob.png
  $ { kill -KILL $pid; wait $pid; echo "exit $?" >&3; } 3>&1 2>/dev/null
  exit 137
  $ until_ 100 workers_gone && echo "workers gone"
  workers gone
  $ cmp b.png before && echo unchanged
  unchanged
  $ ls -A . tmp | grep -c -e part -e povml
  0
  [1]

Other failures do not touch an existing image either: a scene error (status 1), an output directory
that does not exist (status 5):

  $ printf 'sphere { 0, 1 pigment { rgb 1 }\n' > broken.pov
  $ povml broken.pov -D +Ob.png 2>/dev/null; echo "exit $?"
  exit 1
  $ cmp b.png before && echo unchanged
  unchanged
  $ printf 'sphere { 0, 1 pigment { rgb 1 } }\n' > ok.pov
  $ povml ok.pov +W8 +H6 -D +Onowhere/x.png 2>err; echo "exit $?"; grep -v warning err
  exit 5
  nowhere/x.png: error: cannot write the image: nowhere: No such file or directory; nothing was written

A device or a pipe is written through, never replaced (as root a rename would put a file where
/dev/null was); a symbolic link stays a link, the file it points to replaced:

  $ povml ok.pov +W8 +H6 -D +O/dev/null 2>/dev/null; echo "exit $?"; test -c /dev/null && echo "/dev/null is a device"
  exit 0
  /dev/null is a device
  $ povml ok.pov +W8 +H6 -D +O/dev/stdout 2>/dev/null | head -c 4 | od -An -c
   211   P   N   G
  $ ln -s b.png link.png; povml ok.pov +W8 +H6 -D +Olink.png 2>/dev/null; test -L link.png && echo "still a link"; cmp link.png b.png && echo "through it"
  still a link
  through it
