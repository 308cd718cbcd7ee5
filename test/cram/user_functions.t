User functions (lib/fn, lib/sdl/fn_reader.ml): values printed with #debug. Every expected value below is
POV-Ray 3.7.0.10's output for the same script, line for line: POV-Ray's constant folding (q - 2*3 + 4
is q - 10), x / 3 as x * (1/3), pow with small integer powers as products, select, min, max, sum, prod,
x y z u v registers, nested calls, spline, pigment, transform and pattern functions.

  $ cat > fns.pov <<'POV'
  > #version 3.7;
  > global_settings { assumed_gamma 1 }
  > #macro P(Name, V) #debug concat(Name, "=", str(V,0,15), "\n") #end
  > #declare K = 0.25;
  > #declare F1 = function(q) { q - 2*3 + 4 }
  > P("F1(100)", F1(100))
  > #declare F2 = function(q) { q + 0.1 + 0.2 + K }
  > P("F2(1)", F2(1))
  > #declare F3 = function(q) { q / 3 + q / (3) + pow(q, 3) + pow(q, 2.5) }
  > P("F3(1.1)", F3(1.1))
  > #declare F4 = function(q) { select(q, 1, 2, 3) + min(q, 2, -1) + max(q, 4) + select(q, 10, 20) }
  > P("F4(-1)", F4(-1)) P("F4(0)", F4(0)) P("F4(7)", F4(7))
  > #declare F5 = function(q) { sum(i, 1, q, i*i) + prod(j, 1, 4, j + q) }
  > P("F5(3.5)", F5(3.5))
  > #declare F6 = function { x + y*2 + z*3 }
  > #declare F7 = function(u, v) { x + y*10 + F6(v, u, 1) * 2 * 3 }
  > P("F7(1,2)", F7(1, 2))
  > #declare F8 = function(q) { (q < 2) + (q = 3)*10 + (q | 0)*100 + (q & 0) * 1000 + (q >= 3 & q <= 4) * 10000 + (q != 3) * 100000 }
  > P("F8(3)", F8(3))
  > #declare F9 = function(q) { int(q) + div(q, 2)*10 + mod(q, 2)*100 + radians(q) + degrees(q) + ceil(q) + floor(q) + abs(q) }
  > P("F9(-7.5)", F9(-7.5))
  > #declare F10 = function(q) { 2 / 4 * q + 1 - 2 - 3 - -q + +q }
  > P("F10(8)", F10(8))
  > #declare F11 = function(q) { asinh(q) + acosh(q+2) + atanh(q/4) + ln(q) + log(q) + exp(q) + sqrt(q) + sin(q) + cos(q) + tan(q) + asin(q/2) + acos(q/2) + atan(q) + atan2(q, 2) + sinh(q) + cosh(q) + tanh(q) }
  > P("F11(1.3)", F11(1.3))
  > #declare F12 = function { -x*2 + pi + clock }
  > P("F12(1,0,0)", F12(1, 0, 0))
  > #declare S = spline { natural_spline -1, <0,0,1> 0, <1,2,3> 1.5, <2,-1,0> 3, <0,0,0> }
  > #declare FS = function { spline { S } }
  > #declare F13 = function(a) { FS(a).x + FS(a*2).y * 10 + FS(a).z*100 }
  > P("F13(0.3)", F13(0.3))
  > #declare FP = function { pigment { gradient x color_map { [0 rgb <1, 0, 0.5>] [1 rgb <0, 1, 0.2>] } } }
  > #declare F14 = function { FP(x, y, z).red + FP(x, y, z).gray * 10 + FP(x, y, z).blue * 100 }
  > P("F14(0.3,0,0)", F14(0.3, 0, 0))
  > #declare V = FP(0.6, 0, 0);
  > #debug concat("FP(0.6,0,0)=", vstr(5, V, ",", 0, 6), "\n")
  > #declare FT = function { transform { rotate <0, 0, 90> scale 2 } }
  > #declare V = FT(1, 2, 3);
  > #debug concat("FT(1,2,3)=", vstr(3, V, ",", 0, 6), "\n")
  > #declare FA = function { pattern { agate } }
  > P("FA(0.3,0.2,0.1)", FA(0.3, 0.2, 0.1))
  > #declare FC = function { pattern { checker } }
  > P("FC(0.5,0.5,1.5)", FC(0.5, 0.5, 1.5))
  > #declare FG = function { pattern { gradient x frequency 3 triangle_wave } }
  > P("FG(0.4,0,0)", FG(0.4, 0, 0))
  > sphere { 0, 1 }
  > POV
  $ povml +W8 +H8 -D fns.pov 2>&1 | grep '='
  F1(100)=90.000000000000000
  F2(1)=1.550000000000000
  F3(1.1)=3.333392039619217
  F4(-1)=14.000000000000000
  F4(0)=25.000000000000000
  F4(7)=29.000000000000000
  F5(3.5)=1220.562500000000000
  F7(1,2)=63.000000000000000
  F8(3)=10110.000000000000000
  F9(-7.5)=-624.349246042016944
  F10(8)=16.000000000000000
  F11(1.3)=20.891189180256703
  F12(1,0,0)=1.141592653589793
  F13(0.3)=290.915891891891874
  F14(0.3,0,0)=46.013399661183357
  FP(0.6,0,0)=0.400000,0.600000,0.320000,0.000000,0.000000
  FT(1,2,3)=-4.000000,2.000000,6.000000
  FA(0.3,0.2,0.1)=0.370484161213077
  FC(0.5,0.5,1.5)=1.000000000000000
  FG(0.4,0,0)=0.399980000000000

Errors in functions are located at the call or the identifier, with the declaration where it helps:

  $ cat > e1.pov <<'POV'
  > #version 3.7;
  > #declare F = function(a, b) { a + b }
  > #declare G = function { F(x, y, z) }
  > POV
  $ povml +W8 +H8 -D e1.pov
  e1.pov:3:25: error: the function 'F' takes 2 parameters, but 3 were given
      3 | #declare G = function { F(x, y, z) }
        |                         ^
  e1.pov:2:22: note: 'F' is declared here
  [1]

  $ cat > e2.pov <<'POV'
  > #version 3.7;
  > #declare F = function { x + Q }
  > POV
  $ povml +W8 +H8 -D e2.pov
  e2.pov:2:29: error: unknown identifier 'Q' in a function: expected a parameter or a declared float
      2 | #declare F = function { x + Q }
        |                             ^
  [1]

  $ cat > e3.pov <<'POV'
  > #version 3.7;
  > #declare A = 2;
  > #declare F = function(A) { A }
  > POV
  $ povml +W8 +H8 -D e3.pov
  e3.pov:3:23: error: expected a parameter name but 'A' is a float (a parameter cannot be a declared identifier)
      3 | #declare F = function(A) { A }
        |                       ^
  [1]

  $ cat > e4.pov <<'POV'
  > #version 3.7;
  > #declare V = <1,2,3>;
  > #declare F = function { x + V }
  > POV
  $ povml +W8 +H8 -D e4.pov
  e4.pov:3:29: error: 'V' is a 3-term vector, but a function can use only floats and functions
      3 | #declare F = function { x + V }
        |                             ^
  [1]

  $ cat > e5.pov <<'POV'
  > #version 3.7;
  > #declare F = function { x / 0 }
  > POV
  $ povml +W8 +H8 -D e5.pov
  e5.pov:2:23: error: division by zero in a function
      2 | #declare F = function { x / 0 }
        |                       ^
  [1]

  $ cat > e6.pov <<'POV'
  > #version 3.7;
  > #declare F = function { x }
  > #declare F = function { F(x, y, z) }
  > POV
  $ povml +W8 +H8 -D e6.pov
  e6.pov:3:25: error: recursive function calls are not allowed: 'F' calls itself
      3 | #declare F = function { F(x, y, z) }
        |                         ^
  [1]

  $ cat > e7.pov <<'POV'
  > #version 3.7;
  > #declare F = function(a, b) { a + b }
  > #declare R = F(1, 2, 3);
  > POV
  $ povml +W8 +H8 -D e7.pov
  e7.pov:3:20: error: 'F' takes 2 parameters
      3 | #declare R = F(1, 2, 3);
        |                    ^
  [1]

  $ cat > e8.pov <<'POV'
  > #version 3.7;
  > #declare F = function(a) { a }
  > #declare R = F(<1,2>);
  > POV
  $ povml +W8 +H8 -D e8.pov
  e8.pov:3:16: error: expected a float but found a 2-term vector
      3 | #declare R = F(<1,2>);
        |                ^
  [1]

  $ cat > e9.pov <<'POV'
  > #version 3.7;
  > #declare F = function { sin(x, y) }
  > POV
  $ povml +W8 +H8 -D e9.pov
  e9.pov:2:25: error: 'sin' takes 1 parameter, but 2 were given
      2 | #declare F = function { sin(x, y) }
        |                         ^
  [1]

  $ cat > e11.pov <<'POV'
  > #version 3.7;
  > #declare F = function { g(x) }
  > POV
  $ povml +W8 +H8 -D e11.pov
  e11.pov:2:25: error: 'g' is not a declared function (an internal function needs #include "functions.inc")
      2 | #declare F = function { g(x) }
        |                         ^
  [1]

  $ cat > e12.pov <<'POV'
  > #version 3.7;
  > #declare F = function { internal(200) }
  > POV
  $ povml +W8 +H8 -D e12.pov
  e12.pov:2:34: error: function 'internal(200)' does not exist
      2 | #declare F = function { internal(200) }
        |                                  ^
  [1]

  $ cat > e13.pov <<'POV'
  > #version 3.7;
  > #declare F = function(a) { pigment { rgb 1 } }
  > POV
  $ povml +W8 +H8 -D e13.pov
  e13.pov:2:28: error: a pigment function cannot have parameters
      2 | #declare F = function(a) { pigment { rgb 1 } }
        |                            ^
  [1]

