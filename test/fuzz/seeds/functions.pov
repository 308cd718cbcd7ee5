// Fuzz seed: the built-in functions, operators and string escapes (docs/povray-rules.md §11.2).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare S = seed(42);
#declare A = abs(-1) + sqrt(4) + sin(0) + cos(0) + tan(0) + asin(0) + acos(1) + atan(0) + atan2(1, 1);
#declare B = pow(2, 3) + exp(0) + ln(1) + log(10) + min(1, 2, 3) + max(1, 2) + int(2.5) + floor(-1.5) + ceil(1.2);
#declare C = mod(7, 3) + div(7, 2) + radians(180) + degrees(pi) + sinh(0) + cosh(0) + tanh(0);
#declare D = asinh(1) + acosh(2) + atanh(0.5) + bitwise_and(6, 3) + bitwise_or(4, 1) + bitwise_xor(5, 1);
#declare V = vnormalize(<1, 2, 3>) + vcross(x, y) * vdot(x, x) + vrotate(x, <0, 90, 0>) + vaxis_rotate(x, y, 45);
#declare L = vlength(V) + rand(S) + select(-1, 1, 2) + select(0, 1, 2, 3) + (A > B ? A : B);
#declare T = ((A < B) & (C >= 0) | !(D != D) & (1 <= 2) & (A = A));
#declare Str = concat(str(L, 0, 3), vstr(3, V, ", ", 0, 2), chr(65), "\t\"\\\u00e9", strupr("a"), strlwr("B"));
#declare N = strlen(Str) + asc("A") + val("1.5e2") + strcmp("a", "b") + file_exists("colors.inc");
#declare Sub = substr(Str, 1, 3);
#declare Col = rgbft <0.1, 0.2, 0.3, 0.4, 0.5> + color red 1 green 0.5 blue 0.2 filter 0.1 transmit 0.1;
#declare G = Col.red + Col.green + Col.blue + Col.filter + Col.transmit + Col.gray + V.x + V.y + V.z + <1, 2>.u + <1, 2>.v;
#declare Arr = array[2][2] { { 1, 2 }, { 3, 4 } };
#declare Sz = dimensions(Arr) + dimension_size(Arr, 1) + defined(Arr) + defined(Nothing);
#debug concat(Str, Sub, str(N + G + Sz + T, 0, 2), "\n")
camera { location <0, 1, -4> look_at 0 angle 60 sky y up y right x*image_width/image_height direction z }
light_source { <2, 4, -3> color rgb <1, 1, 1> shadowless fade_distance 2 fade_power 1 }
sphere { 0, 1 + clock + version / 100 pigment { rgb Col } finish { ambient 0.1 diffuse 0.6 brilliance 1 specular 0.2 roughness 0.05 metallic } }
