Built-in functions through --dump: values are printed with #debug (on stderr, no newline added) or
appear in the objects. Every expected value was checked against POV-Ray 3.7.0.10; cases where povml
disagrees are left out and described in comments.

Float functions, operators, constants and members (int(1e10) is C's cast on x86, select with 3 and 4
arguments, bitwise operations truncate to int, comparisons treat |a-b| < 1e-10 as equal):

  $ cat > float.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro P(Name, V) #debug concat(Name, "=", str(V,0,6), "\n") #end
  > P("abs(-2.5)", abs(-2.5)) P("ceil(-1.5)", ceil(-1.5)) P("floor(-1.5)", floor(-1.5))
  > P("int(-7.9)", int(-7.9)) P("int(1e10)", int(1e10)) P("div(-7,2)", div(-7,2)) P("mod(-7,3)", mod(-7,3)) P("mod(7.5,2)", mod(7.5,2))
  > P("min(4)", min(4)) P("max(1,5,3)", max(1,5,3)) P("min(3,-1,2,0)", min(3,-1,2,0))
  > P("select(-1,1,2)", select(-1,1,2)) P("select(0,1,2)", select(0,1,2)) P("select(0,1,2,3)", select(0,1,2,3)) P("select(1e-12,1,2,3)", select(1e-12,1,2,3)) P("select(-2,1,2,3)", select(-2,1,2,3))
  > P("bitwise_and(12,10)", bitwise_and(12,10)) P("bitwise_or(12,10,1)", bitwise_or(12,10,1)) P("bitwise_xor(12,10)", bitwise_xor(12,10)) P("bitwise_and(-1,5.9)", bitwise_and(-1,5.9))
  > P("sqrt(2)", sqrt(2)) P("pow(2,10)", pow(2,10)) P("exp(1)", exp(1)) P("ln(10)", ln(10)) P("log(1000)", log(1000))
  > P("sin(pi/6)", sin(pi/6)) P("cos(pi)", cos(pi)) P("tan(pi/4)", tan(pi/4)) P("asin(1)", asin(1)) P("acos(0)", acos(0)) P("atan(1)", atan(1)) P("atan2(1,-1)", atan2(1,-1))
  > P("sinh(1)", sinh(1)) P("cosh(1)", cosh(1)) P("tanh(1)", tanh(1)) P("asinh(1)", asinh(1)) P("acosh(2)", acosh(2)) P("atanh(0.5)", atanh(0.5))
  > P("degrees(pi)", degrees(pi)) P("radians(180)", radians(180))
  > P("1+2*3-4/8", 1+2*3-4/8) P("-2*-3", -2*-3) P("(1<2)", (1<2)) P("(2<=2)", (2<=2)) P("(1=1+1e-11)", (1=1+1e-11)) P("(1!=1+1e-9)", (1!=1+1e-9))
  > P("(1|0&0)", (1|0&0)) P("(!0)", (!0)) P("(!1e-11)", (!1e-11)) P("(1?2:3)", (1?2:3)) P("(0?2:3)", (0?2:3))
  > P("true+yes+on", true+yes+on) P("false+no+off", false+no+off)
  > P("image_width", image_width) P("clock", clock) P("version", version)
  > P("<1,2,3>.y", <1,2,3>.y) #declare Cc = rgb <1,.5,.25>; P("Cc.gray", Cc.gray) P("<1,2,3,4,5>.t", <1,2,3,4,5>.t) P("<1,2,3,4,5>.transmit", <1,2,3,4,5>.transmit)
  > P("vdot(<1,2,3>,<4,5,6>)", vdot(<1,2,3>,<4,5,6>)) P("vlength(<3,4,12>)", vlength(<3,4,12>))
  > P("strlen(\"Hello\")", strlen("Hello")) P("asc(\"A\")", asc("A")) P("asc(\"\")", asc("")) P("val(\"3.5abc\")", val("3.5abc")) P("val(\"abc\")", val("abc")) P("val(\" 1e2\")", val(" 1e2"))
  > P("strcmp(\"abc\",\"abd\")", strcmp("abc","abd")) P("strcmp(\"b\",\"a\")", strcmp("b","a")) P("strcmp(\"a\",\"a\")", strcmp("a","a"))
  > sphere { 0, 1 }
  > POV
  $ povml --dump +W8 +H8 float.pov > /dev/null
  abs(-2.5)=2.500000
  ceil(-1.5)=-1.000000
  floor(-1.5)=-2.000000
  int(-7.9)=-7.000000
  int(1e10)=-2147483648.000000
  div(-7,2)=-3.000000
  mod(-7,3)=-1.000000
  mod(7.5,2)=1.500000
  min(4)=4.000000
  max(1,5,3)=5.000000
  min(3,-1,2,0)=-1.000000
  select(-1,1,2)=1.000000
  select(0,1,2)=2.000000
  select(0,1,2,3)=2.000000
  select(1e-12,1,2,3)=3.000000
  select(-2,1,2,3)=1.000000
  bitwise_and(12,10)=8.000000
  bitwise_or(12,10,1)=15.000000
  bitwise_xor(12,10)=6.000000
  bitwise_and(-1,5.9)=5.000000
  sqrt(2)=1.414214
  pow(2,10)=1024.000000
  exp(1)=2.718282
  ln(10)=2.302585
  log(1000)=3.000000
  sin(pi/6)=0.500000
  cos(pi)=-1.000000
  tan(pi/4)=1.000000
  asin(1)=1.570796
  acos(0)=1.570796
  atan(1)=0.785398
  atan2(1,-1)=2.356194
  sinh(1)=1.175201
  cosh(1)=1.543081
  tanh(1)=0.761594
  asinh(1)=0.881374
  acosh(2)=1.316958
  atanh(0.5)=0.549306
  degrees(pi)=180.000000
  radians(180)=3.141593
  1+2*3-4/8=6.500000
  -2*-3=6.000000
  (1<2)=1.000000
  (2<=2)=1.000000
  (1=1+1e-11)=1.000000
  (1!=1+1e-9)=1.000000
  (1|0&0)=0.000000
  (!0)=1.000000
  (!1e-11)=1.000000
  (1?2:3)=2.000000
  (0?2:3)=3.000000
  true+yes+on=3.000000
  false+no+off=0.000000
  image_width=8.000000
  clock=0.000000
  version=3.700000
  <1,2,3>.y=2.000000
  Cc.gray=0.620000
  <1,2,3,4,5>.t=4.000000
  <1,2,3,4,5>.transmit=5.000000
  vdot(<1,2,3>,<4,5,6>)=32.000000
  vlength(<3,4,12>)=13.000000
  strlen("Hello")=5.000000
  asc("A")=65.000000
  asc("")=0.000000
  val("3.5abc")=3.500000
  val("abc")=0.000000
  val(" 1e2")=100.000000
  strcmp("abc","abd")=-1.000000
  strcmp("b","a")=1.000000
  strcmp("a","a")=0.000000

Not checked here: strcmp returns the difference of the first differing codes in POV-Ray,
strcmp("abc","ab") = 99 and strcmp("A","a") = -32; povml returns only the sign (1 and -1).

Vector functions and promotion (a float is spread to every component, a shorter vector is padded
with zeros), vstr (no promotion, missing components are 0):

  $ cat > vector.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro P(Name, V) #debug concat(Name, "=", vstr(3, V, ",", 0, 6), "\n") #end
  > P("vrotate(x,<0,0,90>)", vrotate(<1,0,0>,<0,0,90>))
  > P("vrotate(<1,2,3>,<30,45,60>)", vrotate(<1,2,3>,<30,45,60>))
  > P("vaxis_rotate(x,z,90)", vaxis_rotate(<1,0,0>,<0,0,1>,90))
  > P("vaxis_rotate(<1,2,3>,<1,1,0>,30)", vaxis_rotate(<1,2,3>,<1,1,0>,30))
  > P("vcross(x,y)", vcross(x,y)) P("vcross(<1,2,3>,<4,5,6>)", vcross(<1,2,3>,<4,5,6>))
  > P("vnormalize(<3,0,4>)", vnormalize(<3,0,4>))
  > P("x+y*2-z/4", x+y*2-z/4) P("<1,2,3>*<2,3,4>", <1,2,3>*<2,3,4>) P("<1,2,3>/2", <1,2,3>/2)
  > P("1+<1,2,3>", 1+<1,2,3>) P("<1,2,3>-1", <1,2,3>-1) P("2*<1,2,3>", 2*<1,2,3>) P("-<1,2,3>", -<1,2,3>)
  > P("<1,2>+<1,2,3>", <1,2>+<1,2,3>) P("<1,2,3>+<1,1,1,1,1>", <1,2,3>+<1,1,1,1,1>)
  > #declare V = <1,2,3>;
  > P("<V.z,V.y,V.x>", <V.z,V.y,V.x>) P("<1+1,2*3,-1>", <1+1,2*3,-1>) P("u+v", u+v)
  > #debug concat("vstr(2,<1,2,3>)=", vstr(2,<1,2,3>,",",0,1), " vstr(5,<1,2,3>)=", vstr(5,<1,2,3>,",",0,1), " vstr(1,5)=", vstr(1,5,",",0,1), "\n")
  > #debug concat("vstr(4,<1,2,3,4,5>)=", vstr(4,<1,2,3,4,5>,"|",-5,-1), "\n")
  > sphere { 1+<1,2,0>, 1 }
  > sphere { 2*y + x, vlength(<3,4,0>) }
  > POV
  $ povml --dump vector.pov
  vrotate(x,<0,0,90>)=0.000000,1.000000,0.000000
  vrotate(<1,2,3>,<30,45,60>)=1.424704,2.931761,1.837117
  vaxis_rotate(x,z,90)=0.000000,1.000000,0.000000
  vaxis_rotate(<1,2,3>,<1,1,0>,30)=2.127647,0.872353,2.951630
  vcross(x,y)=0.000000,0.000000,1.000000
  vcross(<1,2,3>,<4,5,6>)=-3.000000,6.000000,-3.000000
  vnormalize(<3,0,4>)=0.600000,0.000000,0.800000
  x+y*2-z/4=1.000000,2.000000,-0.250000
  <1,2,3>*<2,3,4>=2.000000,6.000000,12.000000
  <1,2,3>/2=0.500000,1.000000,1.500000
  1+<1,2,3>=2.000000,3.000000,4.000000
  <1,2,3>-1=0.000000,1.000000,2.000000
  2*<1,2,3>=2.000000,4.000000,6.000000
  -<1,2,3>=-1.000000,-2.000000,-3.000000
  <1,2>+<1,2,3>=2.000000,4.000000,3.000000
  <1,2,3>+<1,1,1,1,1>=2.000000,3.000000,4.000000
  <V.z,V.y,V.x>=3.000000,2.000000,1.000000
  <1+1,2*3,-1>=2.000000,6.000000,-1.000000
  u+v=1.000000,1.000000,0.000000
  vstr(2,<1,2,3>)=1.0,2.0 vstr(5,<1,2,3>)=1.0,2.0,3.0,0.0,0.0 vstr(1,5)=5.0,0.0
  vstr(4,<1,2,3,4,5>)=1.000000|2.000000|3.000000|4.000000
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <2, 3, 1>, 1
    texture { pigment { rgb <0, 0, 0> } }
  } // vector.pov:17:1
  sphere { <1, 2, 0>, 5
    texture { pigment { rgb <0, 0, 0> } }
  } // vector.pov:18:1
  // 2 objects, 0 lights

Not checked here: '1+<1,2>' is <2,3,1> in POV-Ray (the float is spread over all components, the
2-vector padded with zeros); povml gives <2,3,0>, in a #declare and in a sphere's centre alike
(the same for '<1,2>+1').

String functions: str's width and precision (printf rules), concat, substr, chr, strupr/strlwr,
escapes, #debug without a newline, val, input_file_name, and #warning (which goes on):

  $ cat > string.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #debug concat("[", str(3.14159,0,2), "][", str(3.14159,8,2), "][", str(3.14159,-8,2), "][", str(3.14159,0,-1), "][", str(3.14159,5,-1), "]\n")
  > #debug concat("[", str(-3.14159,-8,3), "][", str(123.456,1,1), "][", str(0.5,0,-3), "][", str(2.5,0,0), "][", str(3.5,0,0), "][", str(1e20,0,0), "]\n")
  > #debug concat("[", concat("a"), "][", concat("a", "b", "c"), "][", substr("Hello",2,3), "][", substr("Hello",5,1), "][", substr("Hello",6,0), "]\n")
  > #debug concat("[", chr(65), chr(66), "][", strupr("MiXed 1"), "][", strlwr("MiXed 1"), "][", str(strlen(""),0,0), "]\n")
  > #debug concat("[", "tab\there", "][", "quote\"s", "][", "back\\slash", "][\u0041]\n")
  > #debug "no newline, "
  > #debug "then the rest\n"
  > #declare S = "abc";
  > #declare S = concat(S, S);
  > #debug concat(S, " ", str(strlen(S),0,0), "\n")
  > #debug concat("input_file_name=", input_file_name, "\n")
  > #debug concat(str(val(str(1/3,0,9)),0,9), "\n")
  > #warning "a warning"
  > sphere { 0, 1 }
  > POV
  $ povml --dump string.pov > /dev/null
  [3.14][    3.14][00003.14][3.141590][3.141590]
  [-003.142][123.5][0.500000][2][4][100000000000000000000]
  [a][abc][ell][o][]
  [AB][MIXED 1][mixed 1][0]
  [tab	here][quote"s][back\slash][A]
  no newline, then the rest
  abcabc 6
  input_file_name=string.pov
  0.333333333
  string.pov:15:1: warning: a warning
     15 | #warning "a warning"
        | ^

seed() makes a new stream each time and returns its number; rand(S) draws from stream int(S):

  $ cat > rand.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #declare S = seed(42);
  > #debug concat("S=", str(S,0,0), " ", str(rand(S),0,9), " ", str(rand(S),0,9), "\n")
  > #declare S2 = seed(42);
  > #debug concat("S2=", str(S2,0,0), " ", str(rand(S2),0,9), " rand(0)=", str(rand(0),0,9), "\n")
  > #declare S3 = seed(-1);
  > #debug concat("seed(-1): ", str(rand(S3),0,9), " rand(1.7)=", str(rand(1.7),0,9), "\n")
  > #declare R = seed(7);
  > #for (I, 1, 3) sphere { <rand(R), rand(R), 0>, 0.1 } #end
  > POV
  $ povml --dump rand.pov
  S=0 0.723582911 0.329979260
  S2=1 0.723582911 rand(0)=0.755761670
  seed(-1): 0.578012874 rand(1.7)=0.329979260
  // version 3.7, working gamma 1
  global_settings { max_trace_level 5 adc_bailout 0.003921568627 ambient_light rgb <1, 1, 1> }
  camera { location <0, 0, 0> direction <0, 0, 1> up <0, 1, 0> right <1.33, 0, 0> }
  background { rgb <0, 0, 0> }
  sphere { <0.9539328806, 0.6104662804, 0>, 0.1
    texture { pigment { rgb <0, 0, 0> } }
  } // rand.pov:10:16
  sphere { <0.1668521357, 0.0348670825, 0>, 0.1
    texture { pigment { rgb <0, 0, 0> } }
  } // rand.pov:10:16
  sphere { <0.739346577, 0.3829757761, 0>, 0.1
    texture { pigment { rgb <0, 0, 0> } }
  } // rand.pov:10:16
  // 3 objects, 0 lights

Division by zero gives +inf with a warning, acos/asin clamp with a warning, div(7,0) is the C cast of
inf, vnormalize(0) gives 0 with a warning, #undef of an unknown identifier warns:

  $ cat > edge.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #debug concat(str(1/0,0,6), " ", str(-1/0,0,6), "\n")
  > #debug concat(str(acos(2),0,6), " ", str(asin(-3),0,6), "\n")
  > #debug concat(str(div(7,0),0,0), "\n")
  > #debug concat(vstr(3, vnormalize(<0,0,0>), ",", 0, 0), "\n")
  > #undef Unknown
  > sphere { 0, 1 }
  > POV
  $ povml --dump edge.pov > /dev/null
  inf inf
  0.000000 -1.570796
  -2147483648
  0,0,0
  edge.pov:3:20: warning: divide by zero; the result is infinity
      3 | #debug concat(str(1/0,0,6), " ", str(-1/0,0,6), "\n")
        |                    ^
  edge.pov:3:40: warning: divide by zero; the result is infinity
      3 | #debug concat(str(1/0,0,6), " ", str(-1/0,0,6), "\n")
        |                                        ^
  edge.pov:4:19: warning: domain error in 'acos': 2 is clamped to the range -1 … 1
      4 | #debug concat(str(acos(2),0,6), " ", str(asin(-3),0,6), "\n")
        |                   ^
  edge.pov:4:42: warning: domain error in 'asin': -3 is clamped to the range -1 … 1
      4 | #debug concat(str(acos(2),0,6), " ", str(asin(-3),0,6), "\n")
        |                                          ^
  edge.pov:6:23: warning: normalizing zero-length vector; the result is <0,0,0>
      6 | #debug concat(vstr(3, vnormalize(<0,0,0>), ",", 0, 0), "\n")
        |                       ^
  edge.pov:7:1: warning: attempt to #undef the unknown identifier 'Unknown'
      7 | #undef Unknown
        | ^

vturbulence(lambda, omega, octaves, V) is POV-Ray's vector turbulence at V (DTurbulence, lambda and
omega in single precision); the values are the 16 digits POV-Ray 3.7.0.10 prints for these calls:

  $ cat > vturb.pov <<'POV'
  > #declare V = vturbulence(2, 0.5, 6, <0.3, 1.7, -2.2>);
  > #debug concat(vstr(3, V, ",", 0, 16), "\n")
  > #declare W = vturbulence(2.5, 0.7, 3, <10.3, -1.7, 5.5>);
  > #debug concat(vstr(3, W, ",", 0, 16), "\n")
  > POV
  $ povml --dump vturb.pov 2>&1 | grep '^[0-9]'
  0.0896179709975022,0.2552221963012811,0.1233993333602959
  0.3482972450677285,0.1612313326432965,0.1910911143504361
