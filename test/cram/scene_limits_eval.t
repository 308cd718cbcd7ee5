Work without end while the scene is read, and memory that stays bounded (issue 34). Each scene
runs as a user would run it, within 20 seconds and 2 GiB of address space; POV-Ray 3.7 runs the
first three until killed, so povml's limits are the answer: a located error and exit status 3.

  $ run() { (ulimit -v 2097152 && exec timeout 20 povml "$@" +W16 +H12 -D) 2>messages >/dev/null; s=$?; sed '/^------/,$d' messages; echo "[exit $s]"; }

A user function summing 10¹² terms, called while the scene is read, stops at the call when the
scene's functions have taken 1,000,000,000 steps (an operation of a body at each call and at each
iteration of sum or prod):

  $ cat > sum.pov <<'POV'
  > #declare F = function(n) { sum(i, 1, n, 1/(i*i)) }
  > #declare V = F(1e12);
  > POV
  $ run sum.pov
  sum.pov:2:14: error: the scene's functions need more than 1,000,000,000 steps, povml's limit (does a sum, a chain of calls or an octave count run too long? raise the limit with --max-function-steps N)
      2 | #declare V = F(1e12);
        |              ^
  [exit 3]

64 functions each calling the one before twice (2^63 calls), with a lower limit:

  $ { echo '#declare F0 = function(x) { x + 1 }'
  >   for i in $(seq 1 63); do echo "#declare F$i = function(x) { F$((i - 1))(x) + F$((i - 1))(x) }"; done
  >   echo '#declare V = F63(0);'; } > calls.pov
  $ run calls.pov --max-function-steps 10000000
  calls.pov:65:14: error: the scene's functions need more than 10,000,000 steps, povml's limit (does a sum, a chain of calls or an octave count run too long? raise the limit with --max-function-steps N)
     65 | #declare V = F63(0);
        |              ^
  [exit 3]

An internal function whose octaves a parameter sets takes that many steps before it runs (here
2,000,000,000 octaves of noise; 1e300 octaves of f_hetero_mf would never end):

  $ cat > octaves.pov <<'POV'
  > #include "functions.inc"
  > #declare F = function { f_ridge(x, y, z, 0.5, 2e9, 0.5, 1, 1, 2) }
  > #declare V = F(0.1, 0.2, 0.3);
  > POV
  $ run octaves.pov
  octaves.pov:3:14: error: the scene's functions need more than 1,000,000,000 steps, povml's limit (does a sum, a chain of calls or an octave count run too long? raise the limit with --max-function-steps N)
      3 | #declare V = F(0.1, 0.2, 0.3);
        |              ^
  [exit 3]

Functions within the limit give their values, and rendering does not count (the pigment's
function runs at every pixel):

  $ cat > within.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare F = function(n) { sum(i, 1, n, 1/(i*i)) }
  > #debug concat(str(F(1000), 0, 6), "\n")
  > #declare G = function { sum(i, 1, 1000, x / 1000) }
  > camera { location <0, 0, -3> look_at 0 }
  > plane { z, 0 pigment { function { G(x, y, z) } } }
  > POV
  $ run within.pov --max-function-steps 20000
  1.643935
  [exit 0]

A function image is computed while the scene is read, its functions counted:

  $ cat > image.pov <<'POV'
  > #declare F = function { sum(i, 1, 1e6, x) }
  > plane { z, 0 pigment { image_map { function 100, 100 { F(x, y, z) } } } }
  > POV
  $ run image.pov --max-function-steps 1000000
  image.pov:2:36: error: the scene's functions need more than 1,000,000 steps, povml's limit (does a sum, a chain of calls or an octave count run too long? raise the limit with --max-function-steps N)
      2 | plane { z, 0 pigment { image_map { function 100, 100 { F(x, y, z) } } } }
        |                                    ^
  [exit 3]

A million concats growing one string (quadratic work: 5·10¹¹ bytes copied) stop when the string
functions have built 4,096 MiB of strings, all together:

  $ cat > concat.pov <<'POV'
  > #declare S = "";
  > #for (I, 1, 1000000) #declare S = concat(S, "x"); #end
  > POV
  $ run concat.pov
  concat.pov:2:35: error: the scene's string functions have built 4,096 MiB of strings, povml's limit (is a string grown in a long loop? raise the limit with --max-strings MIB)
      2 | #for (I, 1, 1000000) #declare S = concat(S, "x"); #end
        |                                   ^
  [exit 3]

The switches are documented:

  $ povml --help=plain | grep -A1 -e '--max-function-steps=N' -e '--max-strings=N'
         --max-function-steps=N (absent=1000000000)
             User functions called while the scene is read that take more than
  --
         --max-strings=N (absent=4096)
             Strings built by the string functions (concat, str, substr …) of

A bicubic patch of type 1 with u_steps 12 and v_steps 12: POV-Ray builds a tree of 4^12 leaves
(28 s and 3.7 GB; "Out of memory" under 2 GiB); povml subdivides it for every ray instead, the
same subpatches in the same order, in bounded memory:

  $ cat > patch.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0.5, 2, -2> look_at <0.5, 0, 0.5> }
  > light_source { <5, 5, -5>, rgb 1 }
  > bicubic_patch { type 1 u_steps 12 v_steps 12
  >   <0, 0, 0>, <0.33, 0.2, 0>, <0.66, -0.2, 0>, <1, 0, 0>,
  >   <0, 0.1, 0.33>, <0.33, 0.5, 0.33>, <0.66, 0.3, 0.33>, <1, 0, 0.33>,
  >   <0, 0, 0.66>, <0.33, 0.3, 0.66>, <0.66, 0.5, 0.66>, <1, 0.1, 0.66>,
  >   <0, 0, 1>, <0.33, 0.2, 1>, <0.66, -0.2, 1>, <1, 0, 1>
  >   pigment { rgb 1 } }
  > POV
  $ run patch.pov
  [exit 0]

A julia fractal of 3,000,000 iterations (POV-Ray renders 10,000,000 in 640 MB): its iteration
stack is one per process, not one per normal or inside test:

  $ cat > julia.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > camera { location <0, 0, -3> look_at 0 }
  > light_source { <5, 5, -5>, rgb 1 }
  > julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 3000000 precision 15 pigment { rgb 1 } }
  > POV
  $ run julia.pov
  [exit 0]
