Scenes come from strangers, so a scene reads and writes only the files it is allowed to. It reads
files under its own directory, the working directory, the +L directories and POV-Ray's include
directory, and under each --allow-read DIR; it writes files only under an --allow-write DIR (and
may read them too). A refused file is a located error, and povml exits with status 4.

The scenes live in scene/, run from there; a secret lies beside it:

  $ mkdir scene secret
  $ printf '#debug "the secret was read\\n"\n' > secret/secret.inc
  $ cd scene

An absolute path outside the allowed directories is refused, whatever the file holds:

  $ cat > abs.pov <<'POV'
  > #version 3.7;
  > #include "/etc/passwd"
  > POV
  $ povml --dump abs.pov > /dev/null
  abs.pov:2:1: error: reading "/etc/passwd" is not allowed: it is outside the scene's directory, the working directory and the library paths (allow it with --allow-read DIR)
      2 | #include "/etc/passwd"
        | ^
  [4]

So is a relative path that leaves the scene's directory with "..":

  $ cat > up.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #include "../secret/secret.inc"
  > POV
  $ povml --dump up.pov > /dev/null
  up.pov:3:1: error: reading "../secret/secret.inc" is not allowed: it is outside the scene's directory, the working directory and the library paths (allow it with --allow-read DIR)
      3 | #include "../secret/secret.inc"
        | ^
  [4]

--allow-read DIR allows it:

  $ povml --dump up.pov --allow-read ../secret > /dev/null
  the secret was read
  warning: no objects in scene

A symbolic link inside the scene's directory that leads out of it is refused too: paths are
compared after links are resolved. Allowing the directory it leads to allows it:

  $ ln -s ../secret link
  $ cat > link.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #include "link/secret.inc"
  > POV
  $ povml --dump link.pov > /dev/null
  link.pov:3:1: error: reading "link/secret.inc" is not allowed: it is outside the scene's directory, the working directory and the library paths (allow it with --allow-read DIR)
      3 | #include "link/secret.inc"
        | ^
  [4]
  $ povml --dump link.pov --allow-read ../secret > /dev/null
  the secret was read
  warning: no objects in scene

A +L directory is searched and readable:

  $ cat > lib.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #include "secret.inc"
  > POV
  $ povml --dump +L../secret lib.pov > /dev/null
  the secret was read
  warning: no objects in scene

file_exists() does not tell whether a file the scene may not read exists: it is false, as in
POV-Ray, whose file_exists() opens the file through its I/O restrictions:

  $ cat > exists.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #debug concat(str(file_exists("../secret/secret.inc"), 0, 0), str(file_exists("/etc/passwd"), 0, 0), str(file_exists("exists.pov"), 0, 0), "\n")
  > POV
  $ povml --dump exists.pov > /dev/null
  001
  warning: no objects in scene
  $ povml --dump exists.pov --allow-read ../secret > /dev/null
  101
  warning: no objects in scene

Writing is refused unless a directory is given with --allow-write, and nothing is written:

  $ cat > write.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #fopen Out "out.txt" write
  > #write (Out, "hello\n")
  > #fclose Out
  > POV
  $ povml --dump write.pov > /dev/null
  write.pov:3:12: error: writing "out.txt" is not allowed: scenes may write files only under a directory given with --allow-write DIR
      3 | #fopen Out "out.txt" write
        |            ^
  [4]
  $ ls out.txt
  ls: cannot access 'out.txt': No such file or directory
  [2]
  $ povml --dump write.pov --allow-write . > /dev/null && cat out.txt
  warning: no objects in scene
  hello

A file outside the --allow-write directories, through ".." or through a link, is refused:

  $ cat > escape.pov <<'POV'
  > #version 3.7;
  > #fopen Out "../secret/out.txt" write
  > POV
  $ povml --dump escape.pov --allow-write . > /dev/null
  escape.pov:2:12: error: writing "../secret/out.txt" is not allowed: it is outside the directories given with --allow-write (allow it with --allow-write DIR)
      2 | #fopen Out "../secret/out.txt" write
        |            ^
  [4]
  $ printf '#version 3.7;\n#fopen Out "link/out.txt" append\n' > escape2.pov
  $ povml --dump escape2.pov --allow-write . > /dev/null
  escape2.pov:2:12: error: writing "link/out.txt" is not allowed: it is outside the directories given with --allow-write (allow it with --allow-write DIR)
      2 | #fopen Out "link/out.txt" append
        |            ^
  [4]
  $ ls ../secret
  secret.inc

#write writes strings as they are, floats with C's %g and vectors as "<x,y,z> " (with the space),
and no separator of its own; #read reads the values back, separated by commas. The file and the
values printed below are byte for byte what POV-Ray 3.7.0.10 writes and reads for this scene:

  $ cat > roundtrip.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #fopen Out "data.txt" write
  > #write (Out, "\"a \\\\ string\",", 1/3, ",", -2.5e-7, ",", 1e6, ",", 123456789, ",")
  > #write (Out, <1, 2.5, -3>, ",", <0.1, 0.2>, ",", <1, 2, 3, 4>, ",", -0, "\n")
  > #fclose Out
  > #fopen In "data.txt" read
  > #read (In, S, A, B, C, D, V, W, Four, Z)
  > #debug concat("S = [", S, "]\n")
  > #debug concat("A = ", str(A, 0, 9), ", B = ", str(B, 0, 9), ", C = ", str(C, 0, 1), ", D = ", str(D, 0, 1), "\n")
  > #debug concat("V = ", vstr(3, V, ", ", 0, 2), "; W = ", vstr(2, W, ", ", 0, 2), "; Four = ", vstr(4, Four, ", ", 0, 0), "; Z = ", str(Z, 0, 0), "\n")
  > #ifdef (In) #debug "In is still open\n" #else #debug "In is closed\n" #end
  > POV
  $ povml --dump roundtrip.pov --allow-write . > /dev/null
  S = [a \ string]
  A = 0.333333000, B = -0.000000250, C = 1000000.0, D = 123457000.0
  V = 1.00, 2.50, -3.00; W = 0.10, 0.20; Four = 1, 2, 3, 4; Z = -0
  In is closed
  warning: no objects in scene
  $ cat data.txt
  "a \\ string",0.333333,-2.5e-07,1e+06,1.23457e+08,<1,2.5,-3> ,<0.1,0.2> ,<1,2,3,4> ,-0

A file identifier becomes undefined at the end of the data, so #while (defined(F)) reads a file
to its end. After a last comma the end is found by one more #read, which changes nothing: POV-Ray
runs this loop four times too. #fclose of a file already closed does nothing:

  $ printf '1,\n2,\n3,\n' > list.txt
  $ cat > loop.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare N = 0;
  > #fopen In "list.txt" read
  > #while (defined(In))
  >   #read (In, X)
  >   #declare N = N + 1;
  >   #debug concat("pass ", str(N, 0, 0), ": X = ", str(X, 0, 0), "\n")
  > #end
  > #fclose In
  > POV
  $ povml --dump loop.pov > /dev/null
  pass 1: X = 1
  pass 2: X = 2
  pass 3: X = 3
  pass 4: X = 3
  warning: no objects in scene
  $ printf '1,\n2,\n3\n' > list.txt
  $ povml --dump loop.pov > /dev/null
  pass 1: X = 1
  pass 2: X = 2
  pass 3: X = 3
  warning: no objects in scene

Values must be separated by commas: POV-Ray drops the token after a value that is not a comma, so
from "1 2 3 4 5 6" three reads give 1, 3 and 5, in POV-Ray and in povml:

  $ printf '1 2 3 4 5 6\n' > spaces.txt
  $ cat > spaces.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #fopen In "spaces.txt" read
  > #read (In, A, B, C)
  > #debug concat(str(A, 0, 0), " ", str(B, 0, 0), " ", str(C, 0, 0), "\n")
  > POV
  $ povml --dump spaces.pov > /dev/null
  1 3 5
  warning: no objects in scene

After uint8, sint8, uint16be/le, sint16be/le or sint32be/le, #write writes the numbers up to the
next comma as binary integers, rounded and clamped (the bytes POV-Ray writes):

  $ cat > binary.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #fopen Out "bytes.bin" write
  > #write (Out, uint8 65 66.4 300, sint16be -2, uint16le 258, "\n")
  > POV
  $ povml --dump binary.pov --allow-write . > /dev/null && od -An -c bytes.bin
  warning: no objects in scene
     A   B 377 377 376 002 001  \n

append adds to the end of a file, creating it if needed:

  $ printf '#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#fopen Out "log.txt" append\n#write (Out, "a line\\n")\n' > append.pov
  $ povml --dump append.pov --allow-write . > /dev/null && povml --dump append.pov --allow-write . > /dev/null && cat log.txt
  warning: no objects in scene
  warning: no objects in scene
  a line
  a line

Files the scene leaves open are closed when it ends, also at an error, with what was written:

  $ cat > partial.pov <<'POV'
  > #version 3.7;
  > #fopen Out "partial.txt" write
  > #write (Out, "written before the error\n")
  > #error "stop here"
  > POV
  $ povml --dump partial.pov --allow-write . > /dev/null
  partial.pov:4:1: error: #error: stop here
      4 | #error "stop here"
        | ^
  [1]
  $ cat partial.txt
  written before the error

Opening a missing file for reading is an error, as in POV-Ray ("Cannot open user file"):

  $ printf '#version 3.7;\n#fopen In "missing.txt" read\n' > missing.pov
  $ povml --dump missing.pov > /dev/null
  missing.pov:2:11: error: cannot find the file "missing.txt" to read (searched ., /usr/share/povray-3.7/include)
      2 | #fopen In "missing.txt" read
        |           ^
  [1]

#read stores into a new identifier or one that holds a float, a 3-term vector or a string (it may
change its type); POV-Ray refuses the others, a colour for instance:

  $ printf '"text", 1\n' > two.txt
  $ cat > types.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare F = 1;
  > #declare C = rgb 1;
  > #fopen In "two.txt" read
  > #read (In, F, C)
  > POV
  $ povml --dump types.pov > /dev/null
  types.pov:6:15: error: '#read' stores into a new identifier or one that holds a float, a 3-term vector or a string; 'C' is a colour
      6 | #read (In, F, C)
        |               ^
  [1]

A data file holds only numbers, vectors and strings; anything else is an error in the data file:

  $ printf '1, two, 3\n' > words.txt
  $ printf '#version 3.7;\n#fopen In "words.txt" read\n#read (In, A, B)\n' > words.pov
  $ povml --dump words.pov > /dev/null
  words.txt:1:4: error: expected a float, a vector or a string in the data file but found 'two'
      1 | 1, two, 3
        |    ^
  words.pov:3:1: note: read by this #read
  [1]

A file is read or written, not both, and colours are not written, as in POV-Ray:

  $ printf '#version 3.7;\n#fopen In "two.txt" read\n#write (In, "x")\n' > mode.pov
  $ povml --dump mode.pov > /dev/null
  mode.pov:3:9: error: cannot write to "two.txt": it is open for reading
      3 | #write (In, "x")
        |         ^
  [1]
  $ printf '#version 3.7;\n#fopen Out "c.txt" write\n#write (Out, rgb 1)\n' > colour.pov
  $ povml --dump colour.pov --allow-write . > /dev/null
  colour.pov:3:14: error: '#write' writes strings, floats and vectors, not a colour
      3 | #write (Out, rgb 1)
        |              ^
  [1]

--help documents both switches; a directory that does not exist is a usage error:

  $ povml --help=plain | grep -e '--allow-read=DIR' -e '--allow-write=DIR'
         --allow-read=DIR
         --allow-write=DIR
  $ povml --dump loop.pov --allow-write nothere
  povml: option '--allow-write': no 'nothere' directory
  Usage: povml [OPTION]… [SCENE]
  Try 'povml --help' for more information.
  [2]
