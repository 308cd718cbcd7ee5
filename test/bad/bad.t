Malformed scenes: whatever a .pov file contains, povml answers with an image or a clear, located
error (file:line:column, the source line, a caret), never a backtrace or a hang. `run.sh` renders a
scene as a user would (16×12, no display), with at most 10 seconds and 1 GiB of address space
(`ulimit -v`; povml's memory limit then defaults to half of it, 512 MiB), and prints povml's messages
without the render statistics, its exit status and whether an image was written. Exit statuses:
0 image written, 1 scene error, 3 one of povml's limits reached. Every scene of this directory has
its case below (the last case checks that).

The test directory holds the scenes as symbolic links into the build tree; povml resolves links
before it decides whether a scene may read a file (a link cannot lead a scene out of its directory),
so the scenes are made plain files first:

  $ for f in *.pov fuzz/*.pov; do cp "$f" "$f.copy" && mv "$f.copy" "$f"; done

Each scene starts with the same four lines (#version 3.7, assumed_gamma 1, a camera, a light), so
the errors are on line 5.

Unclosed blocks:

  $ sh run.sh unclosed_block.pov
  unclosed_block.pov:5:32: error: expected an object modifier or '}' closing 'sphere' but found end of file
      5 | sphere { 0, 1 pigment { rgb 1 }
        |                                ^
  [exit 1, no image]
  $ sh run.sh unclosed_if.pov
  unclosed_if.pov:5:1: error: #if has no matching #end before the end of the file
      5 | #if (1)
        | ^
  [exit 1, no image]
  $ sh run.sh unclosed_macro.pov
  unclosed_macro.pov:5:1: error: #macro Ball has no matching #end
      5 | #macro Ball(R)
        | ^
  [exit 1, no image]
  $ sh run.sh stray_brace.pov
  stray_brace.pov:6:1: error: expected an object, light_source, camera or directive but found '}'
      6 | }
        | ^
  [exit 1, no image]

Unknown keywords, objects and directives (a near keyword is suggested):

  $ sh run.sh unknown_keyword.pov
  unknown_keyword.pov:5:15: error: expected an object modifier or '}' closing 'sphere' but found 'pigmnt'; did you mean 'pigment'?
      5 | sphere { 0, 1 pigmnt { rgb 1 } }
        |               ^
  [exit 1, no image]
  $ sh run.sh unknown_object.pov
  unknown_object.pov:5:1: error: expected an object, light_source, camera or directive but found 'cube'
      5 | cube { 0, 1 }
        | ^
  [exit 1, no image]
  $ sh run.sh unknown_directive.pov
  unknown_directive.pov:5:1: error: unknown directive '#foreach'
      5 | #foreach (I, 1, 3)
        | ^
  [exit 1, no image]

Wrong value types:

  $ sh run.sh wrong_type_string.pov
  wrong_type_string.pov:5:13: error: expected a float but found a string
      5 | sphere { 0, "one" pigment { rgb 1 } }
        |             ^
  [exit 1, no image]
  $ sh run.sh wrong_type_vector.pov
  wrong_type_vector.pov:5:19: error: expected a float but found a 3-term vector
      5 | sphere { <0,0,0>, <1,2,3> pigment { rgb 1 } }
        |                   ^
  [exit 1, no image]
  $ sh run.sh wrong_type_arith.pov
  wrong_type_arith.pov:5:21: error: cannot do arithmetic on a string (strings are joined with concat(…))
      5 | #declare A = "text" + 1;
        |                     ^
  [exit 1, no image]

Random bytes (2 KiB from /dev/urandom, kept as they are): the first byte that cannot start a token
is named; bytes that are not UTF-8 are shown as '?' in the source line.

  $ sh run.sh random_bytes.pov
  random_bytes.pov:1:1: error: unexpected character byte 0xA1
      1 | ?B??9{???J??2????UTˬ??????'?ف???00NK?????-?d*b?t?>?=?????:?;??qL???A{c???`????f???????ð????????Tv??<5????????^?g??@09Yoɒ??Ϟ???(???????{)dzT????????\-?՞J?l??xW?u?0?Tēl??:?
        | ^
  [exit 1, no image]

A NUL byte is blank space to POV-Ray (checked: `sph\0ere` is two identifiers, `1\0 2` two numbers),
and so to povml; this scene has no #version and renders with POV-Ray's two warnings for that:

  $ sh run.sh nul_byte.pov
  warning: assumed_gamma not specified, so gamma correction is turned off for compatibility with this pre POV-Ray 3.7 scene
  warning: this scene did not contain a #version directive; it is rendered as a POV-Ray 3.62 scene (no gamma correction, legacy transparency); add '#version 3.7;' at the start
  [exit 0, image written]

An empty file renders (black) with POV-Ray's three warnings, in POV-Ray's order:

  $ sh run.sh empty.pov
  warning: no objects in scene
  warning: assumed_gamma not specified, so gamma correction is turned off for compatibility with this pre POV-Ray 3.7 scene
  warning: this scene did not contain a #version directive; it is rendered as a POV-Ray 3.62 scene (no gamma correction, legacy transparency); add '#version 3.7;' at the start
  [exit 0, image written]

Unterminated comments and strings point at where they start:

  $ sh run.sh unterminated_comment.pov
  unterminated_comment.pov:5:1: error: unterminated comment: '/*' has no matching '*/'
      5 | /* a comment that
        | ^
  [exit 1, no image]
  $ sh run.sh unterminated_string.pov
  unterminated_string.pov:5:17: error: unterminated string: missing closing '"'
      5 | #declare Name = "never closed;
        |                 ^
  [exit 1, no image]

Huge numbers: 1e999999 is infinity, silently, in POV-Ray too (its #debug prints "Big = inf"); a
sphere of infinite radius renders as POV-Ray renders it (POV-Ray counts it as 0 finite objects):

  $ sh run.sh huge_number.pov
  Big = inf
  [exit 0, image written]
  $ sh run.sh huge_radius.pov
  [exit 0, image written]

Division by zero is a warning and gives infinity (POV-Ray: "Parse Warning: Divide by zero."):

  $ sh run.sh division_by_zero.pov
  division_by_zero.pov:5:16: warning: divide by zero; the result is infinity
      5 | #declare R = 1 / 0;
        |                ^
  [exit 0, image written]

A negative radius is accepted by POV-Ray without a word; povml renders it the same and warns:

  $ sh run.sh negative_radius.pov
  negative_radius.pov:5:13: warning: sphere radius -1 is not positive
      5 | sphere { 0, -1 pigment { rgb 1 } }
        |             ^
  [exit 0, image written]

A zero plane normal is an error in POV-Ray ("Degenerate plane normal.") and in povml:

  $ sh run.sh zero_plane_normal.pov
  zero_plane_normal.pov:5:9: error: degenerate plane normal <0,0,0>
      5 | plane { <0,0,0>, 1 pigment { rgb 1 } }
        |         ^
  [exit 1, no image]

A polygon needs at least three points, as in POV-Ray ("Polygon needs at least three points."),
and as many as it says; an outline that is not closed is closed with a warning, as POV-Ray does:

  $ sh run.sh polygon_too_few.pov
  polygon_too_few.pov:5:11: error: a polygon needs at least three points, not 2
      5 | polygon { 2, <0,0>, <1,0> pigment { rgb 1 } }
        |           ^
  [exit 1, no image]
  $ sh run.sh polygon_missing_points.pov
  polygon_missing_points.pov:5:41: error: the polygon has 5 points but only 4 are written
      5 | polygon { 5, <0,0>, <1,0>, <1,1>, <0,0> }
        |                                         ^
  [exit 1, no image]
  $ sh run.sh polygon_not_closed.pov
  polygon_not_closed.pov:5:1: warning: polygon not closed: POV-Ray closes it with the first point of its last outline
      5 | polygon { 3, <0,0>, <1,0>, <0,1> pigment { rgb 1 } }
        | ^
  [exit 0, image written]

An out-of-range mesh index (POV-Ray: "Mesh face index out of range"):

  $ sh run.sh mesh_index_out_of_range.pov
  mesh_index_out_of_range.pov:7:21: error: vertex index 7 is out of range: there are 3
      7 |   face_indices { 1, <0,1,7> }
        |                     ^
  [exit 1, no image]

An include file that does not exist, and a file that includes itself (POV-Ray stops at 31 nested
include files; povml at 64, --max-include-depth):

  $ sh run.sh unknown_include.pov
  unknown_include.pov:5:1: error: cannot find the include file "no_such_file.inc" (searched ., /usr/share/povray-3.7/include)
      5 | #include "no_such_file.inc"
        | ^
  [exit 1, no image]
  $ sh run.sh include_self.pov
  include_self.pov:1:1: error: include files are nested more than 64 deep, povml's limit (does a file include itself? raise the limit with --max-include-depth N)
      1 | #include "include_self.pov"
        | ^
  include_self.pov:1:1: note: in the file included from here
  include_self.pov:1:1: note: in the file included from here
  include_self.pov:1:1: note: in the file included from here
  include_self.pov:1:1: note: in the file included from here
  include_self.pov:1:1: note: in the file included from here
  note: … 57 more calls and includes …
  include_self.pov:1:1: note: in the file included from here
  include_self.pov:1:1: note: in the file included from here
  [exit 3, no image]

Loops and macros that never end stop at a limit, located at the loop or the call: 10,000,000 loop
iterations (all loops together, --max-iterations), 10,000 nested macro calls (--max-macro-depth;
POV-Ray stops at 98), 3,000,000 macro calls (--max-macro-calls; a macro calling itself twice 64 deep
would make 2^65 calls). Here the loop and call limits are lowered to 1,000,000 and 300,000 to keep
the tests short and far from run.sh's 10 s timeout on a busy machine: at the defaults the empty loop
takes about 5 s and the doubling macro about 11 s on the 2-core test machine.

  $ sh run.sh infinite_while.pov --max-iterations 1000000
  infinite_while.pov:5:1: error: the scene's loops have run 1,000,000 times, povml's limit (does this loop never end? raise the limit with --max-iterations N)
      5 | #while (true)
        | ^
  [exit 3, no image]
  $ sh run.sh recursive_macro.pov
  recursive_macro.pov:5:19: error: macro calls are nested more than 10,000 deep, povml's limit (a macro that calls itself without end? raise the limit with --max-macro-depth N)
      5 | #macro Forever(N) Forever(N + 1) #end
        |                   ^
  recursive_macro.pov:5:19: note: in macro 'Forever' called from here
  recursive_macro.pov:5:19: note: in macro 'Forever' called from here
  recursive_macro.pov:5:19: note: in macro 'Forever' called from here
  recursive_macro.pov:5:19: note: in macro 'Forever' called from here
  recursive_macro.pov:5:19: note: in macro 'Forever' called from here
  note: … 9993 more calls and includes …
  recursive_macro.pov:5:19: note: in macro 'Forever' called from here
  recursive_macro.pov:6:1: note: in macro 'Forever' called from here
  [exit 3, no image]
  $ sh run.sh exponential_macro.pov --max-macro-calls 300000
  exponential_macro.pov:5:29: error: the scene has called macros 300,000 times, povml's limit (raise it with --max-macro-calls N)
      5 | #macro Twice(N) #if (N > 0) Twice(N - 1) Twice(N - 1) #end #end
        |                             ^
  exponential_macro.pov:5:29: note: in macro 'Twice' called from here
  exponential_macro.pov:5:42: note: in macro 'Twice' called from here
  exponential_macro.pov:5:29: note: in macro 'Twice' called from here
  exponential_macro.pov:5:42: note: in macro 'Twice' called from here
  exponential_macro.pov:5:29: note: in macro 'Twice' called from here
  note: … 57 more calls and includes …
  exponential_macro.pov:5:29: note: in macro 'Twice' called from here
  exponential_macro.pov:6:1: note: in macro 'Twice' called from here
  [exit 3, no image]

Memory: a string doubled in a loop, objects made in a loop that never ends (here with the memory
limit lowered to 128 MiB to keep the test short: at the default it takes about 5 s), an array too
large for the memory limit. Each stops with a located error before the system would kill povml:

  $ sh run.sh string_doubling.pov
  string_doubling.pov:6:1: error: the scene needs more than 512 MiB of memory, povml's limit (raise it with --max-memory MIB)
      6 | #while (true) #declare S = concat(S, S); #end
        | ^
  [exit 3, no image]
  $ sh run.sh object_flood.pov --max-memory 128
  object_flood.pov:6:1: error: the scene needs more than 128 MiB of memory, povml's limit (raise it with --max-memory MIB)
      6 | #while (true) sphere { <I, 0, 0>, 1 } #declare I = I + 1; #end
        | ^
  [exit 3, no image]
  $ sh run.sh huge_array.pov
  huge_array.pov:5:14: error: this array of 10000000000 elements would need 76294 MiB, more than povml's memory limit of 512 MiB (raise it with --max-memory MIB)
      5 | #declare A = array[100000][100000];
        |              ^
  [exit 3, no image]

A count of points far beyond those written (here 2³¹ − 1 spheres of a sphere_sweep) is an error at
the first one missing, not an array of that size:

  $ sh run.sh huge_count.pov
  huge_count.pov:6:74: error: expected a numeric expression but found 'pigment'
      6 | sphere_sweep { linear_spline 2147483647, <-1, 1, 3>, 0.3, <1, 1, 3>, 0.4 pigment { rgb 1 } }
        |                                                                          ^
  [exit 1, no image]

An image larger than the pixel limit (--max-pixels, default 8192²) is refused before anything is
read:

  $ sh run.sh plain.pov +W100000 +H100000
  error: a 100000×100000 image has 10,000,000,000 pixels, more than povml's limit of 67,108,864 (raise it with --max-pixels N)
  [exit 3, no image]

A limit can be lowered; here no object at all is allowed:

  $ sh run.sh plain.pov --max-objects 0
  plain.pov:5:1: error: the scene has more than 0 objects and lights, povml's limit (raise it with --max-objects N)
      5 | sphere { 0, 1 pigment { rgb <1,0.5,0> } }
        | ^
  [exit 3, no image]

Deep nesting, 200,000 levels: parentheses, signs, vectors and unions are refused at 10,000 levels
(--max-nesting), long before the stack could overflow (POV-Ray 3.7 crashes with a segmentation fault
on 100,000 nested parentheses); the source line is shown around the column:

  $ nest() { awk -v a="$1" -v m="$2" -v b="$3" -v z="$4" 'BEGIN { print "#version 3.7;"; printf "%s", a; for (i = 0; i < 200000; i++) printf "%s", m; printf "%s", z; for (i = 0; i < 200000; i++) printf "%s", b; print "" }'; }
  $ nest '#declare A = ' '(' ')' '1;' > parentheses.pov && sh run.sh parentheses.pov
  parentheses.pov:2:10014: error: this is nested more than 10,000 levels deep (parentheses, vectors, signs and unions together), povml's limit (raise it with --max-nesting N)
      2 | …((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((…
        |                                                                                  ^
  [exit 3, no image]
  $ nest '#declare A = ' '-' '' '1;' > signs.pov && sh run.sh signs.pov
  signs.pov:2:10014: error: this is nested more than 10,000 levels deep (parentheses, vectors, signs and unions together), povml's limit (raise it with --max-nesting N)
      2 | …----------------------------------------------------------------------------------------------------------------------------------------------------------------…
        |                                                                                  ^
  [exit 3, no image]
  $ nest '#declare A = ' '<' ',1>' '1;' > vectors.pov && sh run.sh vectors.pov
  vectors.pov:2:10014: error: this is nested more than 10,000 levels deep (parentheses, vectors, signs and unions together), povml's limit (raise it with --max-nesting N)
      2 | …<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<<…
        |                                                                                  ^
  [exit 3, no image]
  $ nest '' 'union { ' ' }' 'sphere { 0, 1 }' > unions.pov && sh run.sh unions.pov
  unions.pov:2:80001: error: this is nested more than 10,000 levels deep (parentheses, vectors, signs and unions together), povml's limit (raise it with --max-nesting N)
      2 | …union { union { union { union { union { union { union { union { union { union { union { union { union { union { union { union { union { union { union { union { …
        |                                                                                  ^
  [exit 3, no image]

200,000 nested #if directives are no recursion in povml and render; 200,000 nested macros (each
calling the next) stop at the macro depth limit:

  $ nest '' '#if (1) ' ' #end' 'sphere { 0, 1 }' > ifs.pov && sh run.sh ifs.pov
  warning: assumed_gamma not specified in this POV-Ray 3.7 or later scene; the working gamma is 1.0 (add 'assumed_gamma 1.0' to global_settings)
  [exit 0, image written]
  $ awk 'BEGIN { print "#version 3.7;"; for (i = 0; i < 200000; i++) printf "#macro M%d() M%d() #end\n", i, i + 1; print "M0()" }' > macros.pov
  $ sh run.sh macros.pov
  macros.pov:10001:16: error: macro calls are nested more than 10,000 deep, povml's limit (a macro that calls itself without end? raise the limit with --max-macro-depth N)
  10001 | #macro M9999() M10000() #end
        |                ^
  macros.pov:10000:16: note: in macro 'M9999' called from here
  macros.pov:9999:16: note: in macro 'M9998' called from here
  macros.pov:9998:16: note: in macro 'M9997' called from here
  macros.pov:9997:16: note: in macro 'M9996' called from here
  macros.pov:9996:16: note: in macro 'M9995' called from here
  note: … 9993 more calls and includes …
  macros.pov:2:13: note: in macro 'M1' called from here
  macros.pov:200002:1: note: in macro 'M0' called from here
  [exit 3, no image]

POV-Ray warns about blocks nested 200 deep ("Too many nested '{' braces."), once per block opened at
that depth, and renders; povml gives the same warnings, as many (checked against POV-Ray for 199,
200, 201 and 230 nested objects, and 199, 200, 201 and 250 nested unions):

  $ awk 'BEGIN { print "#version 3.7; global_settings { assumed_gamma 1 }"; for (i = 0; i < 200; i++) printf "object { "; printf "sphere { 0, 1 }"; for (i = 0; i < 200; i++) printf "}"; print "" }' > braces200.pov
  $ sh run.sh braces200.pov
  braces200.pov:2:1799: warning: too many nested '{' braces
      2 | … object { object { object { object { object { object { object { object { object { sphere { 0, 1 }}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}…
        |                                                                                  ^
  braces200.pov:2:1808: warning: too many nested '{' braces
      2 | … object { object { object { object { object { object { object { object { sphere { 0, 1 }}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}…
        |                                                                                  ^
  [exit 0, image written]

A one-megabyte identifier: POV-Ray refuses identifiers, strings and numbers of 256 characters or more
("String too long."; 255 is accepted), and so does povml:

  $ awk 'BEGIN { print "#version 3.7;"; printf "#declare "; for (i = 0; i < 1048576; i++) printf "a"; print " = 1;" }' > identifier.pov
  $ sh run.sh identifier.pov
  identifier.pov:2:10: error: this identifier is 1048576 characters long; POV-Ray allows at most 255
      2 | #declare aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa…
        |          ^
  [exit 1, no image]
  $ awk 'BEGIN { printf "#declare S = \""; for (i = 0; i < 256; i++) printf "a"; print "\";" }' > string256.pov
  $ sh run.sh string256.pov
  string256.pov:1:14: error: this string is 256 characters long; POV-Ray allows at most 255
      1 | #declare S = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa…
        |              ^
  [exit 1, no image]

A UTF-8 byte-order mark and CRLF line ends render normally, to the same image as the plain file:

  $ sh run.sh bom.pov
  [exit 0, image written]
  $ sh run.sh crlf.pov
  [exit 0, image written]
  $ sh run.sh plain.pov
  [exit 0, image written]
  $ cmp bom.png plain.png && cmp crlf.png plain.png && echo same images
  same images

Inputs the fuzzer found (`make fuzz`, test/fuzz) that crashed povml or took too long, each fixed:

  $ sh run.sh fuzz/bvh_infinite_sphere.pov
  fuzz/bvh_infinite_sphere.pov:9:13: warning: sphere radius -inf is not positive
      9 | sphere { 0, -1e400 pigment { rgb 1 } }
        |             ^
  [exit 0, image written]
  $ sh run.sh fuzz/str_huge_width.pov
  fuzz/str_huge_width.pov:5:25: error: 'str' would make a string of 2048 MiB, more than povml's memory limit of 512 MiB (raise it with --max-memory MIB)
      5 | #debug concat("Big = ", str(1e999999, 12345678901234567890, 3), "\n")
        |                         ^
  [exit 3, no image]
  $ sh run.sh fuzz/mesh2_lying_count.pov
  fuzz/mesh2_lying_count.pov:11:16: error: face_indices says 121111111111111 entries but lists 1
     11 |   face_indices { 121111111111111, <0,1,2>, 0 }
        |                ^
  [exit 1, no image]

Functions: a body nested too deep or too long is a limit, located; arithmetic that overflows or
leaves a function's domain gives IEEE infinities and NaNs, as POV-Ray 3.7's VM does (it reports no
floating-point exception), never a crash; a call with the wrong number of parameters is located:

  $ sh run.sh function_deep.pov
  function_deep.pov:5:40028: error: this is nested more than 10,000 levels deep (parentheses, vectors, signs and unions together), povml's limit (raise it with --max-nesting N)
      5 | …(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin(sin…
        |                                                                                  ^
  [exit 3, no image]
  $ sh run.sh function_long.pov
  function_long.pov:5:262171: error: a function has more than 65,536 operators in a row, povml's limit
      5 | …+ x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x + x …
        |                                                                                  ^
  [exit 3, no image]
  $ sh run.sh function_runaway.pov
  -nan -nan
  [exit 0, image written]
  $ sh run.sh function_arity.pov
  function_arity.pov:6:36: error: the function 'F' takes 2 parameters, but 1 was given
      6 | sphere { 0, 1 pigment { function { F(x) } } }
        |                                    ^
  function_arity.pov:5:22: note: 'F' is declared here
  [exit 1, no image]

Every scene in this directory and in fuzz/ has its case above:

  $ for f in *.pov fuzz/*.pov; do grep -q "run.sh $f" bad.t 2>/dev/null || grep -q "> $f" bad.t 2>/dev/null || echo "no case for $f"; done

Issue 34, messages: an array subscript that is not a number or is infinite is out of range (it read
element 0 before; POV-Ray casts it to INT_MIN and says "Negative subscript"):

  $ sh run.sh array_index_nan.pov
  array_index_nan.pov:7:15: error: array subscript nan is out of range 0 … 2
      7 | sphere { 0, A[N] }
        |               ^
  [exit 1, no image]
  $ sh run.sh array_index_inf.pov
  array_index_inf.pov:6:15: error: array subscript inf is out of range 0 … 2
      6 | sphere { 0, A[1e400] }
        |               ^
  [exit 1, no image]

Lines end as POV-Ray counts them: CR alone (old Mac files) and LF CR are line ends as CR LF and LF
are, a `//` comment ends at each, and the error is at the line and column POV-Ray gives (line 5):

  $ sh run.sh cr_line_ends.pov
  cr_line_ends.pov:5:15: error: expected an object modifier or '}' closing 'sphere' but found 'pigmnt'; did you mean 'pigment'?
      5 | sphere { 0, 1 pigmnt { rgb 1 } }
        |               ^
  [exit 1, no image]
  $ sh run.sh lfcr_line_ends.pov
  lfcr_line_ends.pov:5:15: error: expected an object modifier or '}' closing 'sphere' but found 'pigmnt'; did you mean 'pigment'?
      5 | sphere { 0, 1 pigmnt { rgb 1 } }
        |               ^
  [exit 1, no image]
