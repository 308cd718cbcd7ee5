The language, directive by directive: small scenes run with --dump. Every expected value below was
checked against POV-Ray 3.7.0.10 (`povray +W8 +H8 -D`, #debug text on stderr); where povml disagrees
with POV-Ray the case is left out and described in a comment.

#declare and #local: an existing identifier is changed where it is found (innermost table first), a
new #declare goes to the global table, a new #local to the current one. Macros see their callers'
locals (dynamic scoping). A bare identifier argument is passed by reference; an expression is not.

  $ cat > scope.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare G = 1;
  > #local TL = 3;
  > #declare TL = 4;
  > #debug concat("TL=", str(TL,0,0), "\n")
  > #macro M(P)
  >   #local L = 10;
  >   #declare L = 20;
  >   #debug concat("in M: L=", str(L,0,0), "\n")
  >   #local G = 7;
  >   #declare G = 8;
  >   #debug concat("in M: G=", str(G,0,0), "\n")
  >   #declare P = 99;
  > #end
  > #declare X = 1;
  > M(X)
  > #debug concat("G=", str(G,0,0), " X=", str(X,0,0), "\n")
  > #ifndef (L) #debug "L is not defined\n" #end
  > #macro Inner() #declare CL = 99; #end
  > #macro Outer() #local CL = 1; Inner() #debug concat("Outer sees CL=", str(CL,0,0), "\n") #end
  > Outer()
  > #ifndef (CL) #debug "CL is not global\n" #end
  > #macro Show() #debug concat("Show sees CL2=", str(CL2,0,0), "\n") #end
  > #macro Caller() #local CL2 = 42; Show() #end
  > Caller()
  > #macro SetP(P) #declare P = 77; #end
  > #declare Y = 5;
  > SetP(Y+0) #debug concat("SetP(Y+0): Y=", str(Y,0,0), "\n")
  > SetP((Y)) #debug concat("SetP((Y)): Y=", str(Y,0,0), "\n")
  > SetP(Y) #debug concat("SetP(Y): Y=", str(Y,0,0), "\n")
  > #declare V = <1,2,3>;
  > SetP(V) #debug concat("SetP(V): V=", str(V,0,0), "\n")
  > #macro LocP(P) #local P = 3; #end
  > #declare Z = 1;
  > LocP(Z) #debug concat("LocP(Z): Z=", str(Z,0,0), "\n")
  > #declare A = array[3] {1, 2, 3};
  > #macro Fill(Arr) #declare Arr[2] = 9; #end
  > Fill(A) #debug concat("Fill(A): A[2]=", str(A[2],0,0), "\n")
  > #declare R = 1;
  > #declare R = "now a string";
  > #debug concat(R, "\n")
  > sphere { 0, 1 }
  > POV
  $ povml --dump scope.pov > /dev/null
  TL=4
  in M: L=20
  in M: G=8
  G=1 X=99
  L is not defined
  Outer sees CL=99
  CL is not global
  Show sees CL2=42
  SetP(Y+0): Y=5
  SetP((Y)): Y=5
  SetP(Y): Y=77
  SetP(V): V=77
  LocP(Z): Z=3
  Fill(A): A[2]=9
  now a string

Not checked here, because povml still disagrees with POV-Ray:
- SetP(A[1]) with an array element argument: POV-Ray passes the element by reference (A[1]=77);
 povml passes a copy (A[1] stays 2).
- '#local Rad = Rad * 2;' in a macro when Rad is only global: POV-Ray stops with "Cannot assign
 uninitialized identifier" (the new local exists before its value is read); povml reads the global.

#undef removes the entry where lookup finds it: a global from inside a macro, a local (so the
global shows through), or only the alias of a by-reference parameter.

  $ cat > undef.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare G = 1;
  > #macro KillG() #undef G #end
  > KillG()
  > #ifndef (G) #debug "G removed\n" #end
  > #declare H = 1;
  > #macro LocH() #local H = 2; #undef H #debug concat("H=", str(H,0,0), "\n") #end
  > LocH()
  > #macro UndefP(P) #undef P #end
  > #declare K = 5;
  > UndefP(K)
  > #debug concat("K still ", str(K,0,0), "\n")
  > #declare S = 1;
  > #undef S
  > #declare S = "S is a string again";
  > #debug concat(S, "\n")
  > POV
  $ povml --dump undef.pov > /dev/null
  G removed
  H=1
  K still 5
  S is a string again
  warning: no objects in scene

Not checked here: '#undef A[0]' clears one element in POV-Ray (A[1] stays readable); povml removes
the whole array A. '#ifdef (A[0])' / 'defined(A[0])' after it is an error in povml.

#if/#elseif/#else, #ifdef/#ifndef and defined(): a condition is true when |v| > 1e-10; skipped
branches are not interpreted (an unknown directive there is no error).

  $ cat > cond.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #if (0) #debug "no\n" #elseif (0) #debug "no\n" #elseif (1) #debug "third\n" #elseif (1) #debug "no\n" #else #debug "no\n" #end
  > #if (1e-11) #debug "no\n" #else #debug "1e-11 is false\n" #end
  > #if (1e-9) #debug "1e-9 is true\n" #end
  > #if (0) #if (1) #debug "no\n" #else #debug "no\n" #end #else #debug "nested skip\n" #end
  > #if (1 < 2 & 2 < 3) #debug "and\n" #end
  > #if ((1<2<3) = 1 & (3>2>1) = 0) #debug "chained comparisons\n" #end
  > #if (0) #undefined_directive_skipped #error "skipped" #end
  > #ifdef (SS) #debug "SS defined\n" #end
  > #ifdef (sphere) #debug "no\n" #else #debug "keywords are not defined\n" #end
  > #ifndef (Q) #debug "Q not defined\n" #end
  > #declare A = array[3];
  > #declare A[1] = 1;
  > 
  > 
  > #debug concat("defined(A[1])=", str(defined(A[1]),0,0), " defined(Q)=", str(defined(Q),0,0), "\n")
  > sphere { 0, 1 }
  > POV
  $ povml --dump cond.pov > /dev/null
  third
  1e-11 is false
  1e-9 is true
  nested skip
  and
  chained comparisons
  keywords are not defined
  Q not defined
  defined(A[1])=1 defined(Q)=0

Not checked here: string comparison in a condition, '#if (SS = "x")', works in POV-Ray; povml says
"logical and relational operators need floats, not a string and a string". '#ifdef (A[1])' on an
array element is an error in povml ("expected ')' closing '#ifdef' but found '['"); POV-Ray tests the
element.

#switch: #case matches within 1e-10, #range (lo, hi) inclusive; once a case has matched, later
labels (even #else) fall through until #break or #end; an #else before any match is taken; a #break
inside an #if inside a case leaves the #switch.

  $ cat > switch.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro Sw(V)
  >   #debug concat(str(V,0,1), ":")
  >   #switch (V)
  >     #case (1) #debug " case1"
  >     #case (2) #debug " case2" #break
  >     #range (1, 3) #debug " range1-3" #if (V = 3) #break #end #debug " after-if"
  >     #case (3) #debug " case3"
  >     #else #debug " else"
  >   #end
  >   #debug "\n"
  > #end
  > Sw(1) Sw(2) Sw(2.5) Sw(3) Sw(4)
  > #switch (2) #case (1) #debug "A" #else #debug "B" #case (2) #debug "C" #end #debug "\n"
  > #switch (1) #case (1) #debug "A" #else #debug "B" #case (1) #debug "C" #end #debug "\n"
  > #switch (1+1e-11) #case (1) #debug "1+1e-11 matches 1" #end #debug "\n"
  > #switch (1+1e-9) #case (1) #debug "no" #else #debug "1+1e-9 does not" #end #debug "\n"
  > #switch (5) #case (1) #debug "no" #range (6, 9) #debug "no" #end #debug "nothing matched\n"
  > #switch (3) #case (3) #debug "three\n" #end
  > sphere { 0, 1 }
  > POV
  $ povml --dump switch.pov > /dev/null
  1.0: case1 case2
  2.0: case2
  2.5: range1-3 after-if case3 else
  3.0: range1-3
  4.0: else
  BC
  ABC
  1+1e-11 matches 1
  1+1e-9 does not
  nothing matched
  three

Not checked here: directives between '#switch' and its first '#case' run in POV-Ray
('#switch (3) #debug "before the first case\n" #case (3) …' prints the text); povml skips them.

#while re-evaluates its condition at each #end; #break leaves the loop. Nested loops make objects:

  $ cat > while.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare K = 0;
  > #while (K < 3) #debug concat("K=", str(K,0,0), "\n") #declare K = K + 1; #end
  > #debug concat("after: K=", str(K,0,0), "\n")
  > #while (0) #debug "never\n" #end
  > #declare K = 0;
  > #while (1) #declare K = K + 1; #if (K > 4) #break #end #end
  > #debug concat("break: K=", str(K,0,0), "\n")
  > #declare N = 0;
  > #while (N < 3)
  >   #declare M = 0;
  >   #while (M < 2) sphere { <N, M, 0>, 0.25 } #declare M = M + 1; #end
  >   #declare N = N + 1;
  > #end
  > POV
  $ povml --dump while.pov
  K=0
  K=1
  K=2
  after: K=3
  break: K=5
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <0, 0, 0>, 0.25
    texture { pigment { rgb <0, 0, 0> } }
  } // while.pov:13:18
  sphere { <0, 1, 0>, 0.25
    texture { pigment { rgb <0, 0, 0> } }
  } // while.pov:13:18
  sphere { <1, 0, 0>, 0.25
    texture { pigment { rgb <0, 0, 0> } }
  } // while.pov:13:18
  sphere { <1, 1, 0>, 0.25
    texture { pigment { rgb <0, 0, 0> } }
  } // while.pov:13:18
  sphere { <2, 0, 0>, 0.25
    texture { pigment { rgb <0, 0, 0> } }
  } // while.pov:13:18
  sphere { <2, 1, 0>, 0.25
    texture { pigment { rgb <0, 0, 0> } }
  } // while.pov:13:18
  // 6 objects, 0 lights

#for (I, start, end [, step]): end and step are evaluated once, I lives in the current table (a
macro's loop leaves the global I alone), ends one step past the last value, and changes made in the
body stick. A loop whose start is past its end never runs and leaves I at the start value.

  $ cat > for.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #for (I, 1, 3) #debug concat(" ", str(I,0,0)) #end #debug concat(" after: I=", str(I,0,0), "\n")
  > #for (I, 0, 1, 0.3) #debug concat(" ", str(I,0,1)) #end #debug concat(" after: I=", str(I,0,1), "\n")
  > #for (I, 3, 1, -1) #debug concat(" ", str(I,0,0)) #end #debug concat(" after: I=", str(I,0,0), "\n")
  > #for (I, 0, 1, 0.1) #end #debug concat("(0,1,0.1) after: I=", str(I,0,17), "\n")
  > #for (I, 5, 1) #debug "never" #end #debug concat("(5,1) after: I=", str(I,0,0), "\n")
  > #declare E = 3;
  > #for (I, 1, E) #debug concat(" ", str(I,0,0)) #declare E = 10; #end #debug " (end evaluated once)\n"
  > #for (I, 1, 10) #debug concat(" ", str(I,0,0)) #declare I = I + 2; #end #debug " (I changed in the body)\n"
  > #for (I, 1, 5) #if (I = 3) #break #end #debug concat(" ", str(I,0,0)) #end #debug concat(" break: I=", str(I,0,0), "\n")
  > #declare I = 100;
  > #macro Loop() #for (I, 1, 3) #end #debug concat("in the macro: I=", str(I,0,0), "\n") #end
  > Loop()
  > #debug concat("global I=", str(I,0,0), "\n")
  > #for (J, -1, 1) sphere { <J, 0, 0>, 0.5 } #end
  > POV
  $ povml --dump for.pov
   1 2 3 after: I=4
   0.0 0.3 0.6 0.9 after: I=1.2
   3 2 1 after: I=0
  (0,1,0.1) after: I=1.09999999999999987
  (5,1) after: I=5
   1 2 3 (end evaluated once)
   1 4 7 10 (I changed in the body)
   1 2 break: I=3
  in the macro: I=4
  global I=100
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <-1, 0, 0>, 0.5
    texture { pigment { rgb <0, 0, 0> } }
  } // for.pov:16:17
  sphere { <0, 0, 0>, 0.5
    texture { pigment { rgb <0, 0, 0> } }
  } // for.pov:16:17
  sphere { <1, 0, 0>, 0.5
    texture { pigment { rgb <0, 0, 0> } }
  } // for.pov:16:17
  // 3 objects, 0 lights

Macros: recursion, values spliced into expressions ('X*2' returned by Ret(3) in '1 + Ret(3)' gives
1+3*2), a trailing ';' in the body, strings and vectors from macros, #break returning from a macro,
a macro defined by running another one, 90 nested calls, and objects and object modifiers from macros.

  $ cat > macro.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro Fact(N) #if (N > 1) Fact(N - 1) #declare F = F * N; #else #declare F = 1; #end #end
  > Fact(5) #debug concat("Fact(5)=", str(F,0,0), "\n")
  > #macro Ret(X) X*2 #end
  > #declare R1 = Ret(4);
  > #declare R3 = 1 + Ret(3);
  > #debug concat("Ret(4)=", str(R1,0,0), " 1+Ret(3)=", str(R3,0,0), "\n")
  > #macro Semi() 5; #end
  > #declare Y = Semi()
  > #debug concat("Semi()=", str(Y,0,0), "\n")
  > #macro M2(A, B) #debug concat(str(A,0,0), ",", str(B,0,0), "\n") #end
  > M2(1, 2) M2 (3, 4)
  > #macro Str() "from a macro" #end
  > #debug concat(Str(), "\n")
  > #macro One() 1 #end
  > #declare V = <One(), 2*One(), 3>;
  > #debug concat("V=", vstr(3, V, ",", 0, 0), "\n")
  > #macro Brk() #debug "before " #if (1) #break #end #debug "after" #end
  > Brk() #debug "\n"
  > #macro Outer() #macro Inner() #debug "Inner called\n" #end #end
  > #ifndef (Inner) #debug "Inner not defined yet\n" #end
  > Outer()
  > Inner()
  > #macro Depth(N) #if (N > 0) Depth(N - 1) #else #debug "depth reached\n" #end #end
  > Depth(90)
  > #macro Ball(C, Rad) sphere { C, Rad } #end
  > Ball(<1, 2, 3>, 0.5)
  > #macro Row(N) #if (N > 0) sphere { <N, 0, 0>, 0.1 } Row(N - 1) #end #end
  > Row(3)
  > #declare Obj = Ball(0, 2)
  > object { Obj }
  > #macro Mods() pigment { rgb <1, 0, 0> } #end
  > sphere { 0, 1 Mods() }
  > POV
  $ povml --dump macro.pov
  Fact(5)=120
  Ret(4)=8 1+Ret(3)=7
  Semi()=5
  1,2
  3,4
  from a macro
  V=1,2,3
  before 
  Inner not defined yet
  Inner called
  depth reached
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <1, 2, 3>, 0.5
    texture { pigment { rgb <0, 0, 0> } }
  } // macro.pov:27:21
  sphere { <3, 0, 0>, 0.1
    texture { pigment { rgb <0, 0, 0> } }
  } // macro.pov:29:27
  sphere { <2, 0, 0>, 0.1
    texture { pigment { rgb <0, 0, 0> } }
  } // macro.pov:29:27
  sphere { <1, 0, 0>, 0.1
    texture { pigment { rgb <0, 0, 0> } }
  } // macro.pov:29:27
  sphere { <0, 0, 0>, 2
    texture { pigment { rgb <0, 0, 0> } }
  } // macro.pov:32:1
  sphere { <0, 0, 0>, 1
    texture { pigment { rgb <1, 0, 0> } }
  } // macro.pov:34:1
  // 6 objects, 0 lights

Not checked here: '#declare R3 = 1 + Ret(3) + 1;' is 8 in POV-Ray (the macro's tokens are spliced in
and the expression goes on); povml stops the expression at the macro's end ("expected an object …
but found '+'"). Argument commas are optional in POV-Ray ('M2(1 2)') and a trailing comma is
accepted ('M2(1,2,)'); povml refuses both. A recursive '#local R = N * Fact(N - 1); … R' loses R
(see #local above).

#include: each include file has its own local table (IL and the loop variable FI die with it, the
global #declare ID stays, #declare TL on a name local to the include changes the include's TL);
#version set in an include stays set; ".inc" is appended when the name is not found; the name can be
any string expression; macros defined in an include can be called later.

  $ cat > a.inc <<'POV'
  > #local IL = 1;
  > #declare ID = 2;
  > #local TL = 100;
  > #debug concat("in a.inc: TL=", str(TL,0,0))
  > #declare TL = 101;
  > #debug concat(" then ", str(TL,0,0), "\n")
  > #for (FI, 1, 2) #end
  > #macro FromInc(R) sphere { <0, 1, 0>, R } #end
  > #version 3.5;
  > sphere { <0, 2, 0>, ID }
  > POV
  $ cat > l.inc <<'POV'
  > #debug "l.inc read\n"
  > POV
  $ cat > inc.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #local TL = 4;
  > #include "a.inc"
  > #ifndef (IL) #debug "IL is gone\n" #end
  > #debug concat("ID=", str(ID,0,0), " TL=", str(TL,0,0), "\n")
  > #ifndef (FI) #debug "FI is gone\n" #end
  > #debug concat("version=", str(version,0,2), "\n")
  > #version 3.7;
  > #include "l"
  > #include concat("l", ".inc")
  > #debug concat("file_exists: ", str(file_exists("a.inc"),0,0), str(file_exists("colors.inc"),0,0), "\n")
  > FromInc(0.5)
  > POV
  $ povml --dump inc.pov
  in a.inc: TL=100 then 101
  IL is gone
  ID=2 TL=4
  FI is gone
  version=3.50
  l.inc read
  l.inc read
  file_exists: 11
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <0, 2, 0>, 2
    texture { pigment { rgb <0, 0, 0> } }
  } // a.inc:10:1
  sphere { <0, 1, 0>, 0.5
    texture { pigment { rgb <0, 0, 0> } }
  } // a.inc:8:19
  // 2 objects, 0 lights

Not checked here: file_exists("l") is 0 in POV-Ray (no extension is appended); povml says 1 when l.inc
exists.

Arrays: nested initialisers, dimensions()/dimension_size(), subscripts truncated (B[1.99999] is
B[1]), #declare of a whole array copies it, element assignment, a trailing comma in an initialiser,
arrays of strings and objects.

  $ cat > array.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare B = array[2][3] { {1, 2, 3}, {4, 5, 6} };
  > #debug concat("dimensions=", str(dimensions(B),0,0), " sizes=", str(dimension_size(B,1),0,0), ",", str(dimension_size(B,2),0,0), "\n")
  > #debug concat("B[1][2]=", str(B[1][2],0,0), " B[1.99999][0]=", str(B[1.99999][0],0,0), "\n")
  > #declare F = B;
  > #declare F[0][0] = 99;
  > #debug concat("copy: F[0][0]=", str(F[0][0],0,0), " B[0][0]=", str(B[0][0],0,0), "\n")
  > #declare C = array[2];
  > #declare C[0] = <1, 2, 3>;
  > #declare C[1] = C[0] * 2;
  > #debug concat("C[1]=", vstr(3, C[1], ",", 0, 0), "\n")
  > #declare T = array[2] {1, 2,};
  > #debug concat("trailing comma: ", str(T[1],0,0), "\n")
  > #declare S = array[3] {"a", "b", "c"};
  > #debug concat(S[0], S[1], S[2], "\n")
  > #declare I = 0;
  > #declare Sum = 0;
  > #while (I < 3) #declare Sum = Sum + B[1][I]; #declare I = I + 1; #end
  > #debug concat("sum of B[1]=", str(Sum,0,0), "\n")
  > #declare Spheres = array[2] { sphere { 0, 1 }, sphere { x, 2 } };
  > object { Spheres[1] }
  > #declare Pos = array[2] { <1, 2, 3>, <4, 5, 6> };
  > sphere { Pos[1], B[0][2] }
  > POV
  $ povml --dump array.pov
  dimensions=2 sizes=2,3
  B[1][2]=6 B[1.99999][0]=4
  copy: F[0][0]=99 B[0][0]=1
  C[1]=2,4,6
  trailing comma: 2
  abc
  sum of B[1]=15
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <1, 0, 0>, 2
    texture { pigment { rgb <0, 0, 0> } }
  } // array.pov:22:1
  sphere { <4, 5, 6>, 3
    texture { pigment { rgb <0, 0, 0> } }
  } // array.pov:24:1
  // 2 objects, 0 lights

Not checked here: dimension_size(B, 3) and dimension_size(B, 0) are 0 in POV-Ray; povml stops with
"dimension 3 is out of range: the array has 2". 'array[2.5]' has size 2 in POV-Ray; povml stops with
"an array dimension must be a whole number of at least 1, not 2.5".

#default: objects made before a #default keep the old default; #default { pigment } / { finish }
change only that part; a declared textureless object takes the default current where it is used;
an object's own pigment or finish starts from the default of that moment; #default { texture }
replaces the whole texture.

  $ cat > default.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > sphere { <0, 0, 0>, 1 }
  > #default { finish { ambient 1 } pigment { rgb 1 } }
  > sphere { <1, 0, 0>, 1 }
  > #declare Decl = sphere { <2, 0, 0>, 1 }
  > #default { pigment { rgb <1, 0, 0> } }
  > #declare P = pigment { rgb <0, 1, 1> }
  > #default { finish { ambient 0.5 } }
  > object { Decl }
  > #default { pigment { rgb <0, 1, 0> } }
  > sphere { <3, 0, 0>, 1 pigment { P } }
  > sphere { <4, 0, 0>, 1 finish { diffuse 0.2 } }
  > #default { texture { pigment { rgb <0, 0, 1> } } }
  > sphere { <5, 0, 0>, 1 }
  > POV
  $ povml --dump default.pov
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <0, 0, 0>, 1
    texture { pigment { rgb <0, 0, 0> } }
  } // default.pov:3:1
  sphere { <1, 0, 0>, 1
    texture { pigment { rgb <1, 1, 1> } finish { ambient rgb <1, 1, 1> } }
  } // default.pov:5:1
  sphere { <2, 0, 0>, 1
    texture { pigment { rgb <1, 0, 0> } finish { ambient rgb <0.5, 0.5, 0.5> } }
  } // default.pov:10:1
  sphere { <3, 0, 0>, 1
    texture { pigment { rgb <0, 1, 1> } finish { ambient rgb <0.5, 0.5, 0.5> } }
  } // default.pov:12:1
  sphere { <4, 0, 0>, 1
    texture { pigment { rgb <0, 1, 0> } finish { ambient rgb <0.5, 0.5, 0.5> diffuse 0.2 } }
  } // default.pov:13:1
  sphere { <5, 0, 0>, 1
    texture { pigment { rgb <0, 0, 1> } finish { ambient rgb <0.5, 0.5, 0.5> } }
  } // default.pov:15:1
  // 6 objects, 0 lights

Cases found to differ from POV-Ray and then fixed (values checked with POV-Ray 3.7.0.10): a #local
whose value is a macro's #local, a recursive macro that returns through #local, an expression that
goes on after a macro's value, macro arguments without commas and with a trailing comma, #undef of
one array element, #ifdef of an element, string equality, dimension_size of a missing dimension,
array[2.5], strcmp's difference of codes, file_exists without ".inc" appended:

  $ touch l.inc
  $ cat > fixed.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro Two() #local T = 2; T #end
  > #local X = Two();
  > #macro Fact(N) #if (N <= 1) #local R = 1; #else #local R = N * Fact(N - 1); #end R #end
  > #macro Ret(X) X*2 #end
  > #declare R3 = 1 + Ret(3) + 1;
  > #macro M2(A, B) concat(str(A,0,0), str(B,0,0)) #end
  > #declare A = array[2.5] { 1, 2 }
  > #undef A[0]
  > #ifndef (A[0]) #debug "A[0] undefined\n" #end
  > #ifdef (A[1]) #debug "A[1] defined\n" #end
  > #declare SS = "x";
  > #if (SS = "x") #debug "SS equals x\n" #end
  > #debug concat("X=", str(X,0,0), " Fact(5)=", str(Fact(5),0,0), " R3=", str(R3,0,0), " M2=", M2(1 2), M2(3,4,), "\n")
  > #debug concat("dims=", str(dimension_size(A, 1),0,0), " ", str(dimension_size(A, 2),0,0), " ", str(dimension_size(A, 0),0,0), "\n")
  > #debug concat("strcmp=", str(strcmp("abc","ab"),0,0), " ", str(strcmp("A","a"),0,0), " file_exists(l)=", str(file_exists("l"),0,0), " file_exists(l.inc)=", str(file_exists("l.inc"),0,0), "\n")
  > POV
  $ povml --dump fixed.pov > /dev/null
  A[0] undefined
  A[1] defined
  SS equals x
  X=2 Fact(5)=120 R3=8 M2=1234
  dims=2 0 0
  strcmp=99 -32 file_exists(l)=0 file_exists(l.inc)=1
  warning: no objects in scene

Found in POV-Ray's sample scenes and then fixed (checked with POV-Ray 3.7.0.10, which prints the
same values and renders the same image): array initialisers with commas left out, after elements
and after inner braces, and with a comma after the closing brace (Parse_Initalizer in tokenize.cpp
reads an element, then an optional comma; textures/patterns/tiling.pov, advanced/grenadine/lemon.inc),
a comma before the '>' of a vector (Parse_Num_Factor in express.cpp; animations/float4/float4.pov),
and a '#' with no directive name after it, which POV-Ray ignores without a message (Parse_Directive
in tokenize.cpp; language/image_size.pov), and so does povml:

  $ cat > found.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare A = array[3] { 1, 2 3 }
  > #declare B = array[2][2] { {<1,2> <3,4>} {<5,6>, <7,8>,}, },
  > #declare S = array[2] { "a" "b" }
  > #declare C = rgb<0.2,0.1,0.5,>;
  > #declare V = <1,2,3,4,>;
  > #debug concat("A[2]=", str(A[2],0,0), " B[1][1]=", vstr(2, B[1][1], ",", 0, 0), " S=", S[0], S[1], "\n")
  > #debug concat("C=", vstr(5, C, ",", 0, 1), " V=", vstr(4, V, ",", 0, 0), "\n")
  > camera { location -5*z look_at 0#
  > }
  > sphere { 0, 1 pigment { C } }
  > POV
  $ povml --dump found.pov
  A[2]=3 B[1][1]=7,8 S=ab
  C=0.2,0.1,0.5,0.0,0.0 V=1,2,3,4
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, -5> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <0, 0, 0>, 1
    texture { pigment { rgb <0.2, 0.1, 0.5> } }
  } // found.pov:12:1
  // 1 objects, 0 lights
