Every error of the scene language: the location (file:line:column), the source line with a caret,
notes for the include and macro chains, and exit status 1. (The messages are povml's; where POV-Ray
refuses something povml accepts, the case is described in a comment at the end.)

Unknown identifiers and misspelt words get a suggestion:

  $ cat > ident.pov <<'POV'
  > #declare Radius = 1;
  > sphere { 0, Raduis }
  > POV
  $ povml --dump ident.pov
  ident.pov:2:13: error: unknown identifier 'Raduis'; did you mean 'Radius' or 'radius'?
      2 | sphere { 0, Raduis }
        |             ^
  [1]
  $ cat > kw.pov <<'POV'
  > sphere { 0, 1 pigmnet { rgb 1 } }
  > POV
  $ povml --dump kw.pov
  kw.pov:1:15: error: expected an object modifier or '}' closing 'sphere' but found 'pigmnet'; did you mean 'pigment'?
      1 | sphere { 0, 1 pigmnet { rgb 1 } }
        |               ^
  [1]
  $ cat > dir.pov <<'POV'
  > #delcare X = 1;
  > POV
  $ povml --dump dir.pov
  dir.pov:1:1: error: unknown directive '#delcare'; did you mean '#declare'?
      1 | #delcare X = 1;
        | ^
  [1]
  $ cat > macrotypo.pov <<'POV'
  > #macro MakeBall(R) sphere { 0, R } #end
  > MakeBal(1)
  > POV
  $ povml --dump macrotypo.pov
  macrotypo.pov:2:1: error: expected an object, light_source, camera or directive but found 'MakeBal'; did you mean 'MakeBall'?
      2 | MakeBal(1)
        | ^
  [1]

Unbalanced directives, in the main file and in an include file:

  $ cat > ifnoend.pov <<'POV'
  > #if (1)
  > sphere { 0, 1 }
  > POV
  $ povml --dump ifnoend.pov
  ifnoend.pov:1:1: error: #if has no matching #end before the end of the file
      1 | #if (1)
        | ^
  [1]
  $ cat > ifnoend.inc <<'POV'
  > #if (1)
  > #declare X = 1;
  > POV
  $ cat > ifinc.pov <<'POV'
  > #include "ifnoend.inc"
  > sphere { 0, 1 }
  > POV
  $ povml --dump ifinc.pov
  ifnoend.inc:1:1: error: #if has no matching #end before the end of the file
      1 | #if (1)
        | ^
  ifinc.pov:1:1: note: in the file included from here
  [1]
  $ cat > else.pov <<'POV'
  > #else
  > sphere { 0, 1 }
  > POV
  $ povml --dump else.pov
  else.pov:1:1: error: '#else' without a matching #if
      1 | #else
        | ^
  [1]
  $ cat > elseif.pov <<'POV'
  > #elseif (1)
  > POV
  $ povml --dump elseif.pov
  elseif.pov:1:1: error: '#elseif' without a matching #if
      1 | #elseif (1)
        | ^
  [1]
  $ cat > case.pov <<'POV'
  > #case (1)
  > POV
  $ povml --dump case.pov
  case.pov:1:1: error: '#case' outside a #switch
      1 | #case (1)
        | ^
  [1]
  $ cat > end.pov <<'POV'
  > sphere { 0, 1 }
  > #end
  > POV
  $ povml --dump end.pov
  end.pov:2:1: error: '#end' without a matching #if, #while, #for, #switch or #macro
      2 | #end
        | ^
  [1]
  $ cat > break.pov <<'POV'
  > #break
  > POV
  $ povml --dump break.pov
  break.pov:1:1: error: '#break' outside a #switch, #while, #for or macro
      1 | #break
        | ^
  [1]
  $ cat > vecif.pov <<'POV'
  > #if (<1,2,3>) #end
  > POV
  $ povml --dump vecif.pov
  vecif.pov:1:6: error: the condition of '#if' must be a float, not a 3-term vector
      1 | #if (<1,2,3>) #end
        |      ^
  [1]

Macro calls with too few or too many arguments point at the definition:

  $ cat > args.pov <<'POV'
  > #macro M2(A, B)
  >   sphere { A, B }
  > #end
  > M2(1)
  > POV
  $ povml --dump args.pov
  args.pov:4:5: error: macro 'M2' takes 2 arguments, this call gives 1
      4 | M2(1)
        |     ^
  args.pov:1:1: note: the macro is defined here
  [1]
  $ cat > args2.pov <<'POV'
  > #macro M2(A, B)
  >   sphere { A, B }
  > #end
  > M2(1, 2, 3)
  > POV
  $ povml --dump args2.pov
  args2.pov:4:10: error: too many arguments for macro 'M2', which takes 2
      4 | M2(1, 2, 3)
        |          ^
  args2.pov:1:1: note: the macro is defined here
  [1]
  $ cat > macroundef.pov <<'POV'
  > #macro M(P) #end
  > M(Undefined)
  > POV
  $ povml --dump macroundef.pov
  macroundef.pov:2:3: error: unknown identifier 'Undefined'; did you mean 'defined'?
      2 | M(Undefined)
        |   ^
  [1]

An error inside a macro body names each call; inside an included file, each include:

  $ cat > inmacro.pov <<'POV'
  > #macro Inner(R)
  >   sphere { 0, sqrt(R) }
  > #end
  > #macro Outer(R)
  >   Inner(R - 2)
  > #end
  > Outer(1)
  > POV
  $ povml --dump inmacro.pov
  inmacro.pov:2:15: error: sqrt of negative number -1.000000
      2 |   sphere { 0, sqrt(R) }
        |               ^
  inmacro.pov:5:3: note: in macro 'Inner' called from here
  inmacro.pov:7:1: note: in macro 'Outer' called from here
  [1]
  $ cat > bad.inc <<'POV'
  > #declare A = 1;
  > #declare B = A + Nope;
  > POV
  $ cat > incerr.pov <<'POV'
  > #include "bad.inc"
  > POV
  $ povml --dump incerr.pov
  bad.inc:2:18: error: unknown identifier 'Nope'
      2 | #declare B = A + Nope;
        |                  ^
  incerr.pov:1:1: note: in the file included from here
  [1]
  $ cat > lib.inc <<'POV'
  > #macro Ball(R)
  >   sphere { 0, sqrt(R) }
  > #end
  > POV
  $ cat > outer.inc <<'POV'
  > #include "lib.inc"
  > POV
  $ cat > chain.pov <<'POV'
  > #include "outer.inc"
  > Ball(-4)
  > POV
  $ povml --dump chain.pov
  lib.inc:2:15: error: sqrt of negative number -4.000000
      2 |   sphere { 0, sqrt(R) }
        |               ^
  chain.pov:2:1: note: in macro 'Ball' called from here
  [1]
  $ cat > noinc.pov <<'POV'
  > #include "missing.inc"
  > POV
  $ povml --dump noinc.pov
  noinc.pov:1:1: error: cannot find the include file "missing.inc" (searched ., /usr/share/povray-3.7/include)
      1 | #include "missing.inc"
        | ^
  [1]

#error stops with its text:

  $ cat > err.pov <<'POV'
  > #error concat("stopped at ", str(3,0,0))
  > POV
  $ povml --dump err.pov
  err.pov:1:1: error: #error: stopped at 3
      1 | #error concat("stopped at ", str(3,0,0))
        | ^
  [1]

Arrays:

  $ cat > uninit.pov <<'POV'
  > #declare A = array[3];
  > sphere { 0, A[1] }
  > POV
  $ povml --dump uninit.pov
  uninit.pov:2:13: error: element 1 of the array 'A' has not been assigned a value
      2 | sphere { 0, A[1] }
        |             ^
  [1]
  $ cat > range.pov <<'POV'
  > #declare A = array[3] {1, 2, 3};
  > sphere { 0, A[3] }
  > POV
  $ povml --dump range.pov
  range.pov:2:15: error: array subscript 3 is out of range 0 … 2
      2 | sphere { 0, A[3] }
        |               ^
  [1]
  $ cat > neg.pov <<'POV'
  > #declare A = array[3] {1, 2, 3};
  > sphere { 0, A[-1] }
  > POV
  $ povml --dump neg.pov
  neg.pov:2:15: error: array subscript -1 is out of range 0 … 2
      2 | sphere { 0, A[-1] }
        |               ^
  [1]
  $ cat > init.pov <<'POV'
  > #declare A = array[3] {1, 2};
  > POV
  $ povml --dump init.pov
  init.pov:1:23: error: this initialiser has 2 elements; the array dimension is 3
      1 | #declare A = array[3] {1, 2};
        |                       ^
  [1]

The commas between elements are optional, as in POV-Ray, so { 1 -2 } is the one element 1-2
(POV-Ray refuses it too, saying "Attempted to redefine float identifier as …"):

  $ cat > init1.pov <<'POV'
  > #declare A = array[2] { 1 -2 };
  > POV
  $ povml --dump init1.pov
  init1.pov:1:23: error: this initialiser has 1 elements; the array dimension is 2
      1 | #declare A = array[2] { 1 -2 };
        |                       ^
  [1]
  $ cat > init2.pov <<'POV'
  > #declare A = array[2] {1, 2, 3};
  > POV
  $ povml --dump init2.pov
  init2.pov:1:30: error: too many elements in an array initialiser: the dimension is 2
      1 | #declare A = array[2] {1, 2, 3};
        |                              ^
  [1]

#for with a zero step:

  $ cat > forstep.pov <<'POV'
  > #for (I, 1, 3, 0) #end
  > POV
  $ povml --dump forstep.pov
  forstep.pov:1:14: error: the step of '#for' must not be 0
      1 | #for (I, 1, 3, 0) #end
        |              ^
  [1]

A comma may end a vector of two to four terms, not one of one or five terms (POV-Ray's
Parse_Num_Factor, express.cpp; POV-Ray says "Expected 'numeric expression', > found instead" and
"Expected '>', , found instead"):

  $ echo 'sphere { <1,>, 1 }' > vec1.pov
  $ povml --dump vec1.pov
  vec1.pov:1:13: error: expected a numeric expression but found '>'
      1 | sphere { <1,>, 1 }
        |             ^
  [1]
  $ echo 'sphere { 0, 1 pigment { rgbft <1,1,1,0,0,> } }' > vec5.pov
  $ povml --dump vec5.pov
  vec5.pov:1:42: error: a vector has at most 5 terms
      1 | sphere { 0, 1 pigment { rgbft <1,1,1,0,0,> } }
        |                                          ^
  [1]

Mathematical and string errors:

  $ cat > sqrt.pov <<'POV'
  > #declare X = sqrt(-1);
  > POV
  $ povml --dump sqrt.pov
  sqrt.pov:1:14: error: sqrt of negative number -1.000000
      1 | #declare X = sqrt(-1);
        |              ^
  [1]
  $ cat > ln.pov <<'POV'
  > #declare X = ln(0);
  > POV
  $ povml --dump ln.pov
  ln.pov:1:14: error: ln of a number that is not positive: 0.000000
      1 | #declare X = ln(0);
        |              ^
  [1]
  $ cat > pow.pov <<'POV'
  > #declare X = pow(0, 0);
  > POV
  $ povml --dump pow.pov
  pow.pov:1:14: error: pow(0, 0) is undefined
      1 | #declare X = pow(0, 0);
        |              ^
  [1]
  $ cat > atan2.pov <<'POV'
  > #declare X = atan2(0, 0);
  > POV
  $ povml --dump atan2.pov
  atan2.pov:1:14: error: domain error in atan2(0, 0)
      1 | #declare X = atan2(0, 0);
        |              ^
  [1]
  $ cat > substr.pov <<'POV'
  > #declare S = substr("Hello", 4, 3);
  > POV
  $ povml --dump substr.pov
  substr.pov:1:14: error: substr("Hello", 4, 3) is outside the string (length 5)
      1 | #declare S = substr("Hello", 4, 3);
        |              ^
  [1]
  $ cat > chr.pov <<'POV'
  > #declare S = chr(70000);
  > POV
  $ povml --dump chr.pov
  chr.pov:1:14: error: chr(70000): the value must be 0 … 65535
      1 | #declare S = chr(70000);
        |              ^
  [1]
  $ cat > rand.pov <<'POV'
  > #declare S = seed(1);
  > #declare X = rand(S + 1);
  > POV
  $ povml --dump rand.pov
  rand.pov:2:24: error: rand(1): there is no such random stream (make one with seed())
      2 | #declare X = rand(S + 1);
        |                        ^
  [1]
  $ cat > strfloat.pov <<'POV'
  > #declare X = 1 + "two";
  > POV
  $ povml --dump strfloat.pov
  strfloat.pov:1:16: error: cannot do arithmetic on a float and a string
      1 | #declare X = 1 + "two";
        |                ^
  [1]

Declared values that povml cannot render yet are an error only where they are used: Blobby in
an include file is a composite; in the main file the declaration also warns.

  $ cat > comp.inc <<'POV'
  > #declare Blobby = composite { sphere { 0, 1 } }
  > POV
  $ cat > jade.pov <<'POV'
  > #include "comp.inc"
  > object { Blobby }
  > POV
  $ povml --dump jade.pov
  jade.pov:2:10: error: not supported yet: 'composite' (used through 'Blobby')
      2 | object { Blobby }
        |          ^
  comp.inc:1:19: note: 'Blobby' was declared here
  [1]
  $ cat > unsup3.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare P = pigment { density_file df3 "x.df3" }
  > #declare Q = pigment { rgb 1 }
  > sphere { 0, 1 pigment { Q } }
  > POV
  $ povml --dump unsup3.pov > /dev/null
  unsup3.pov:3:1: warning: 'P' uses 'density_file' as a pattern, which povml does not support yet; using it will be an error
      3 | #declare P = pigment { density_file df3 "x.df3" }
        | ^
  $ echo 'sphere { 0, 1 pigment { P } }' >> unsup3.pov
  $ povml --dump unsup3.pov
  unsup3.pov:6:25: error: not supported yet: 'density_file' as a pattern (used through 'P')
      6 | sphere { 0, 1 pigment { P } }
        |                         ^
  unsup3.pov:3:24: note: 'P' was declared here
  [1]
  $ cat > unsup.pov <<'POV'
  > #declare N = normal { bumps 0.5 }
  > #declare R = 2;
  > sphere { 0, R normal { N } }
  > POV
  $ povml --dump unsup.pov
  // version 3.62, no gamma correction
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <0, 0, 0>, 2
    texture { pigment { rgb <0, 0, 0> } normal { bumps 0.5 accuracy 0.01999999955 frequency 1 phase 0 } }
  } // unsup.pov:3:1
  // 1 objects, 0 lights
  warning: assumed_gamma not specified, so gamma correction is turned off for compatibility with this pre POV-Ray 3.7 scene
  warning: this scene did not contain a #version directive; it is rendered as a POV-Ray 3.62 scene (no gamma correction, legacy transparency); add '#version 3.7;' at the start

A macro call with such an argument is such a value too: it is skipped through the call's ')', so
the sphere after it is read, and using it is the error (POV-Ray renders both scenes: it has wood;
textures/pigments/blkhole.pov calls Correct_Pigment_Gamma(pigment { DMFWood4 … }, 2.2)):

  $ cat > macroarg.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro M(P, G) pigment { P } #end
  > #declare Tree = M(pigment { density_file df3 "x.df3" }, 2.2)
  > sphere { 0, 1 pigment { rgb 1 } }
  > POV
  $ povml --dump macroarg.pov | tail -1
  macroarg.pov:4:1: warning: 'Tree' uses 'density_file' as a pattern, which povml does not support yet; using it will be an error
      4 | #declare Tree = M(pigment { density_file df3 "x.df3" }, 2.2)
        | ^
  // 1 objects, 0 lights
  $ echo 'sphere { 0, 1 pigment { Tree } }' >> macroarg.pov
  $ povml --dump macroarg.pov
  macroarg.pov:6:25: error: not supported yet: 'density_file' as a pattern (used through 'Tree')
      6 | sphere { 0, 1 pigment { Tree } }
        |                         ^
  macroarg.pov:4:29: note: 'Tree' was declared here
  [1]

A directive is no part of a declared value, even when the declaration runs it while looking past
its value (array[3] looks for a '{'): an unsupported value in its condition is the error there
(POV-Ray takes the branch the value decides; incdemo/circletext.pov reached the same through
Circle_Text in shapes.inc while max_extent was not read):

  $ cat > ifunsup.pov <<'POV'
  > #declare S = sphere { 0, 1 }
  > #declare FW = strlen(datetime(now));
  > #local C = array[3]
  > #if (FW > 2)
  >   #error "too long"
  > #end
  > sphere { 0, 1 }
  > POV
  $ povml --dump ifunsup.pov
  ifunsup.pov:4:6: error: not supported yet: the function 'datetime' (used through 'FW')
      4 | #if (FW > 2)
        |      ^
  ifunsup.pov:2:22: note: 'FW' was declared here
  [1]

Not checked here, because POV-Ray refuses them and povml does not (povml accepts each silently):
- '#for (A[0], 1, 2) #end': POV-Ray says "#for loop variable must not be an array element".
- 'array[2] {1, "a"}': POV-Ray says "Attempted to redefine float identifier as string identifier."
- '#version 3.8;': POV-Ray says "Your scene file requires POV-Ray version 3.8 or later!".

A #for loop variable cannot be an array element, and a scene for a later POV-Ray is refused:

  $ printf '#version 3.7;\n#declare A = array[2];\n#for (A[0], 1, 2) #end\n' > forel.pov
  $ povml --dump forel.pov
  forel.pov:3:7: error: the #for loop variable must not be an array element
      3 | #for (A[0], 1, 2) #end
        |       ^
  [1]
  $ printf '#version 3.8;\nsphere { 0, 1 }\n' > v38.pov
  $ povml --dump v38.pov
  v38.pov:1:10: error: this scene requires POV-Ray version 3.8 or later; povml reads the language of POV-Ray 3.7
      1 | #version 3.8;
        |          ^
  [1]
