(* Interp: scene text to Scene.t (docs/povray-rules.md §1.3, §2.3, §5.1, §8.1, §8.4, §10, §11). *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

(* Parts of the only object of a scene (a sphere for centre and radius). *)
let centre text = fst (sphere_of (the_object (scene text)))
let radius text = snd (sphere_of (the_object (scene text)))
let pigment text = pigment_of (the_object (scene text))
let finish text = (layer_of (the_object (scene text))).finish

(* ---- expressions (§11.2) ---- *)

let test_promotion () =
  (* <1,2,3>*2+1: the float is replicated: <2,4,6> + <1,1,1> = <3,5,7> *)
  vec_eq "<1,2,3>*2+1" (v 3. 5. 7.) (centre "#declare V = <1,2,3>*2+1;\nsphere { V, 1 }");
  (* <1,2>+1 = <2,3>, then padded with a zero to three terms: <2,3,0> *)
  vec_eq "<1,2>+1" (v 2. 3. 0.) (centre "sphere { <1,2>+1, 1 }");
  (* a 2-term vector plus a 3-term one: <1,2> is padded to <1,2,0>: <1,2,0>+<1,1,1> = <2,3,1> *)
  vec_eq "<1,2>+<1,1,1>" (v 2. 3. 1.) (centre "sphere { <1,2>+<1,1,1>, 1 }");
  (* a float in a vector context is replicated: sphere { 2, 1 } is at <2,2,2> *)
  vec_eq "float as vector" (v 2. 2. 2.) (centre "sphere { 2, 1 }");
  (* precedence: 1+2*3 = 7, (1+2)*3 = 9, -2*-3 = 6, 8/4/2 = 1 *)
  float_eq "1+2*3" 7. (radius "sphere { 0, 1+2*3 }");
  float_eq "(1+2)*3" 9. (radius "sphere { 0, (1+2)*3 }");
  float_eq "-2*-3" 6. (radius "sphere { 0, -2*-3 }");
  float_eq "8/4/2" 1. (radius "sphere { 0, 8/4/2 }");
  (* relational operators inside parentheses give 1 or 0 *)
  float_eq "(1 < 2) + (2 <= 1) + (3 != 3) + (3 = 3)" 2. (radius "sphere { 0, (1 < 2) + (2 <= 1) + (3 != 3) + (3 = 3) }");
  float_eq "?:" 5. (radius "sphere { 0, (0 ? 4 : 5) }")

let test_array_declared_without_semicolon () =
  (* #declare A = array[3] with no ';': looking for an initialiser reads the directives after it,
     which may already assign its elements, as in POV-Ray's incdemo/glasses scenes *)
  float_eq "element set by the next directive" 5. (radius "#declare A = array[3]\n#declare A[1] = 5;\nsphere { 0, A[1] }");
  float_eq "two dimensions" 7.
    (radius "#declare B = array[2][2]\n#declare X = 1;\n#declare B[1][0] = 7;\nsphere { 0, B[1][0] }");
  float_eq "an initialiser still follows" 2. (radius "#declare C = array[2] { 1, 2 }\nsphere { 0, C[1] }")

let test_string_declared_without_semicolon () =
  (* a string is read without looking past it: the macro call after it sees the new identifier *)
  float_eq "literal" 3. (radius "#macro Mk(A) sphere { 0, strlen(A) } #end\n#declare S = \"abc\"\nMk(S)");
  float_eq "function" 2. (radius "#macro Mk(A) sphere { 0, strlen(A) } #end\n#declare S = concat(\"a\", \"b\")\nMk(S)");
  float_eq "identifier" 3. (radius "#macro Mk(A) sphere { 0, strlen(A) } #end\n#declare T = \"xyz\";\n#declare S = T\nMk(S)")

let test_optional_vector_commas () =
  (* POV-Ray's commas between vector terms are optional: <0 20 0> = <0,20,0>; <1 -2 3> is <1-2, 3> *)
  vec_eq "<0 20 0>" (v 0. 20. 0.) (centre "sphere { <0 20 0>, 1 }");
  vec_eq "<1 -2 3>" (v (-1.) 3. 0.) (centre "sphere { <1 -2 3>, 1 }");
  vec_eq "<1, 2 3>" (v 1. 2. 3.) (centre "sphere { <1, 2 3>, 1 }")

let test_directives_without_hash () =
  (* at the top level, 'default', 'version', 'declare' and 'include' work without '#', the last two
     with a warning (checked with POV-Ray) *)
  let f = finish "default { finish { ambient 0.7 } }\ndeclare R = 2;\nsphere { 0, R pigment { rgb 1 } }" in
  float_eq "default without #" 0.7 f.ambient.r;
  float_eq "declare without #" 2. (radius "declare R = 2;\nsphere { 0, R }")

let test_functions () =
  (* sqrt(16) + pow(2,3) + abs(-1) = 4 + 8 + 1 = 13 *)
  float_eq "sqrt+pow+abs" 13. (radius "sphere { 0, sqrt(16) + pow(2,3) + abs(-1) }");
  (* int(-2.5) = -2 (truncates), div(-7,2) = -3, mod(-7,2) = -1: -2 - 3 - 1 = -6, negated 6 *)
  float_eq "int/div/mod" 6. (radius "sphere { 0, -(int(-2.5) + div(-7,2) + mod(-7,2)) }");
  (* int(-0.5) and div(-1, 3) are C's (double)(int) casts: 0 without a sign, so 1/… is +infinity
     (POV-Ray's str(int(-0.5), 0, 2) prints 0.00, not -0.00: float2.pov's frames) *)
  Alcotest.(check bool) "int(-0.5) is +0" false (Float.sign_bit (radius "sphere { 0, int(-0.5) }"));
  Alcotest.(check bool) "div(-1, 3) is +0" false (Float.sign_bit (radius "sphere { 0, div(-1, 3) }"));
  Alcotest.(check bool) "function int(-0.5) is +0" false
    (Float.sign_bit (radius "#declare F = function(a) { int(a) }\nsphere { 0, F(-0.5) }"));
  (* vlength(<3,4,12>) = 13; vdot(<1,2,3>,<4,5,6>) = 32 *)
  float_eq "vlength" 13. (radius "sphere { 0, vlength(<3,4,12>) }");
  float_eq "vdot" 32. (radius "sphere { 0, vdot(<1,2,3>,<4,5,6>) }");
  (* vcross(x, y) = z *)
  vec_eq "vcross" (v 0. 0. 1.) (centre "sphere { vcross(x, y), 1 }");
  (* max(1, 5, 3) = 5, min(4, 2) = 2 *)
  float_eq "max/min" 7. (radius "sphere { 0, max(1, 5, 3) + min(4, 2) }");
  (* image_width = 160, image_height = 120 from the options *)
  float_eq "image_width/image_height" (160. /. 120.) (radius "sphere { 0, image_width/image_height }")

let test_components () =
  (* <4,5,6>.y = 5, .z = 6, .x = 4 *)
  vec_eq ".x .y .z" (v 5. 6. 4.) (centre "#declare V = <4,5,6>;\nsphere { <V.y, V.z, V.x>, 1 }");
  (* rgb <0.2,0.4,0.6>: .red 0.2, .green 0.4, .blue 0.6 *)
  vec_eq ".red .green .blue" (v 0.2 0.4 0.6)
    (centre "#declare C = rgb <0.2,0.4,0.6>;\nsphere { <C.red, C.green, C.blue>, 1 }");
  (* rgbft <0,0,0,0.3,0.7>: .filter 0.3, .transmit 0.7 *)
  vec_eq ".filter .transmit" (v 0.3 0.7 0.)
    (centre "#declare C = rgbft <0,0,0,0.3,0.7>;\nsphere { <C.filter, C.transmit, 0>, 1 }");
  (* .gray = 0.297·0.2 + 0.589·0.4 + 0.114·0.6 = 0.0594 + 0.2356 + 0.0684 = 0.3634 *)
  float_eq ".gray" 0.3634 (radius "#declare C = rgb <0.2,0.4,0.6>;\nsphere { 0, C.gray }");
  (* the selector on a literal vector *)
  float_eq "<1,2,3>.z" 3. (radius "sphere { 0, <1,2,3>.z }");
  expect_scene_error ".z of a 2-vector" "sphere { 0, <1,2>.z }" ~line:1 ~col:18 ~sub:"at least 3 terms"

let test_division_by_zero () =
  let s, w = load "sphere { 0, 1/0 }" in
  (* division by exactly 0 gives +infinity whatever the sign (checked with POV-Ray 3.7.0.10:
     -1/0 prints "inf" with "Divide by zero.") *)
  Alcotest.(check (float 0.)) "1/0 = inf" Float.infinity (snd (sphere_of (the_object s)));
  (* (a scene without #version also gets the legacy-scene warnings, which are not located) *)
  match List.filter (fun (e : Error.t) -> contains ~sub:"divide" e.msg) w with
  | [ e ] ->
      check_contains "warning" ~sub:"divide by zero" e.msg;
      (* the '/' is at column 14 of "sphere { 0, 1/0 }" *)
      Alcotest.(check (pair int int)) "warning location" (1, 14) (e.loc.line, e.loc.col)
  | l -> Alcotest.failf "expected one warning, got %d" (List.length l)

(* ---- colours (§11.2) ---- *)

let test_colours () =
  (* color 0.5: a bare float is promoted to all five terms *)
  colour_eq "color 0.5" (colour5 0.5 0.5 0.5 0.5 0.5) (pigment "sphere { 0, 1 pigment { color 0.5 } }");
  colour_eq "rgb 0.5" (colour5 0.5 0.5 0.5 0. 0.) (pigment "sphere { 0, 1 pigment { rgb 0.5 } }");
  (* rgbt: the 4th term is transmit, filter 0 *)
  colour_eq "rgbt 0.5" (colour5 0.5 0.5 0.5 0. 0.5) (pigment "sphere { 0, 1 pigment { rgbt 0.5 } }");
  colour_eq "rgbf 0.5" (colour5 0.5 0.5 0.5 0.5 0.) (pigment "sphere { 0, 1 pigment { rgbf 0.5 } }");
  colour_eq "rgbft <.1,.2,.3,.4,.5>" (colour5 0.1 0.2 0.3 0.4 0.5)
    (pigment "sphere { 0, 1 pigment { rgbft <.1,.2,.3,.4,.5> } }");
  colour_eq "rgb <1,0,0> filter 0.3" (colour5 1. 0. 0. 0.3 0.)
    (pigment "sphere { 0, 1 pigment { rgb <1,0,0> filter 0.3 } }");
  (* color <1,0.5,0.25> pads with zeros; a 4-vector gives filter *)
  colour_eq "color <1,0.5,0.25>" (colour5 1. 0.5 0.25 0. 0.) (pigment "sphere { 0, 1 pigment { color <1,0.5,0.25> } }");
  colour_eq "color <1,0.5,0.25,0.1>" (colour5 1. 0.5 0.25 0.1 0.)
    (pigment "sphere { 0, 1 pigment { color <1,0.5,0.25,0.1> } }");
  colour_eq "color red 1 green 0.5 transmit 0.2" (colour5 1. 0.5 0. 0. 0.2)
    (pigment "sphere { 0, 1 pigment { color red 1 green 0.5 transmit 0.2 } }");
  (* a colour identifier in an expression has 5 terms: (rgb 1)*0.5 has f = t = 0 *)
  colour_eq "White*0.5" (colour5 0.5 0.5 0.5 0. 0.)
    (pigment "#declare White = rgb 1;\nsphere { 0, 1 pigment { White*0.5 } }");
  (* identifier followed by a component keyword *)
  colour_eq "C filter 0.5" (colour5 1. 0. 0. 0.5 0.)
    (pigment "#declare C = rgb <1,0,0>;\nsphere { 0, 1 pigment { C filter 0.5 } }");
  (* no pigment: the default texture is black *)
  colour_eq "default pigment" Colour.black (pigment "sphere { 0, 1 }")

(* ---- shapes (§2.2, §2.3) ---- *)

let test_plane () =
  let n, d = plane_of (the_object (scene "plane { <0,2,0>, 1 }")) in
  (* §2.3: the normal is normalised, d is NOT divided by |n|: the plane is at y = 1 *)
  vec_eq "normal <0,2,0> normalised" (v 0. 1. 0.) n;
  float_eq "offset stays 1" 1. d;
  let n, d = plane_of (the_object (scene "plane { <0,3,4>, 2 }")) in
  vec_eq "normal <0,3,4>/5" (v 0. 0.6 0.8) n;
  float_eq "offset 2" 2. d;
  expect_scene_error "degenerate normal" "plane { <0,0,0>, 1 }" ~line:1 ~col:9 ~sub:"degenerate"

let test_translate () =
  (* sphere: the centre moves: <1,2,3> + <1,1,1> = <2,3,4>; two translates add up *)
  vec_eq "sphere translate" (v 2. 3. 4.) (centre "sphere { <1,2,3>, 1 translate <1,1,1> }");
  vec_eq "two translates" (v 3. 4. 5.) (centre "sphere { <1,2,3>, 1 translate x translate <1,2,2> }");
  float_eq "radius kept" 1.5 (radius "sphere { <1,2,3>, 1.5 translate <1,1,1> }");
  (* plane y, 1 moved by <5,2,7>: offset 1 + n̂·v = 1 + 2 = 3 *)
  let n, d = plane_of (the_object (scene "plane { y, 1 translate <5,2,7> }")) in
  vec_eq "plane normal kept" (v 0. 1. 0.) n;
  float_eq "plane offset 1 + 2" 3. d;
  (* n̂ = <0,0.6,0.8>, v = <9,5,5>: 2 + 0.6·5 + 0.8·5 = 2 + 3 + 4 = 9 *)
  let _, d = plane_of (the_object (scene "plane { <0,3,4>, 2 translate <9,5,5> }")) in
  float_eq "tilted plane offset" 9. d

let test_declare_object () =
  let s =
    scene
      "#declare S = sphere { <0,0,0>, 1 pigment { rgb <1,0,0> } }\n\
       object { S translate <1,0,0> }\n\
       object { S }\n\
       object { S pigment { rgb <0,0,1> } translate <0,2,0> }\n"
  in
  match s.objects with
  | [ a; b; c ] ->
      let ca, ra = sphere_of a and cb, _ = sphere_of b and cc, _ = sphere_of c in
      vec_eq "first copy moved" (v 1. 0. 0.) ca;
      float_eq "radius kept" 1. ra;
      vec_eq "second copy unmoved (declared value not changed)" (v 0. 0. 0.) cb;
      vec_eq "third copy" (v 0. 2. 0.) cc;
      colour_eq "declared pigment kept" (colour5 1. 0. 0. 0. 0.) (pigment_of a);
      colour_eq "pigment replaced in the copy" (colour5 0. 0. 1. 0. 0.) (pigment_of c);
      colour_eq "declared pigment unchanged by the copy" (colour5 1. 0. 0. 0. 0.) (pigment_of b);
      (* the object's location is that of 'object' on line 2 *)
      Alcotest.(check (pair int int)) "location of the copy" (2, 1) (a.loc.line, a.loc.col)
  | l -> Alcotest.failf "expected 3 objects, got %d" (List.length l)

let test_declare_values () =
  (* declared pigment, finish and texture identifiers *)
  let o =
    the_object
      (scene
         "#declare P = pigment { rgb <0.1,0.2,0.3> }\n\
          #declare F = finish { ambient 0.3 diffuse 0.4 }\n\
          sphere { 0, 1 pigment { P } finish { F phong 0.5 } }")
  in
  colour_eq "pigment id" (colour5 0.1 0.2 0.3 0. 0.) (pigment_of o);
  rgb_eq "finish id ambient" (Rgb.grey 0.3) (layer_of o).finish.ambient;
  float_eq "finish id diffuse" 0.4 (layer_of o).finish.diffuse;
  float_eq "finish id modified" 0.5 (layer_of o).finish.phong;
  let o = the_object (scene "#declare T = texture { pigment { rgb 1 } finish { diffuse 0.9 } }\nsphere { 0, 1 texture { T } }") in
  colour_eq "texture id pigment" (colour5 1. 1. 1. 0. 0.) (pigment_of o);
  float_eq "texture id finish" 0.9 (layer_of o).finish.diffuse;
  (* no_shadow *)
  Alcotest.(check bool) "no_shadow" true (the_object (scene "sphere { 0, 1 no_shadow }")).no_shadow;
  Alcotest.(check bool) "shadow by default" false (the_object (scene "sphere { 0, 1 }")).no_shadow

(* ---- camera (§1.1, §1.3) ---- *)

let camera text = (scene text).camera

let test_camera_defaults () =
  let c = camera "" in
  vec_eq "location" (v 0. 0. 0.) c.location;
  vec_eq "direction z" (v 0. 0. 1.) c.direction;
  vec_eq "up y" (v 0. 1. 0.) c.up;
  (* §1.1: right is 1.33 x, not 4/3 *)
  vec_eq "right 1.33 x" (v 1.33 0. 0.) c.right;
  let c = camera "camera { location <1,2,3> }" in
  vec_eq "location only" (v 1. 2. 3.) c.location;
  vec_eq "direction still z" (v 0. 0. 1.) c.direction

let test_camera_angle () =
  (* §1.3: |direction| = |right| / (2 tan(angle/2)); angle 90: 1.33 / (2·1) = 0.665 *)
  vec_eq "angle 90" (v 0. 0. 0.665) (camera "camera { angle 90 }").direction;
  (* right <2,0,0>, angle 90: 2 / 2 = 1 *)
  vec_eq "right 2x angle 90" (v 0. 0. 1.) (camera "camera { right <2,0,0> angle 90 }").direction;
  (* angle 60: tan 30° = 0.5773503, 1.33 / 1.1547005 = 1.1518138 *)
  vec_eq ~eps:1e-6 "angle 60" (v 0. 0. 1.1518138) (camera "camera { angle 60 }").direction;
  (* the direction keeps its own direction: direction <0,0,5> angle 90 gives <0,0,0.665> *)
  vec_eq "direction length replaced" (v 0. 0. 0.665) (camera "camera { direction <0,0,5> angle 90 }").direction;
  (* keywords are applied in a fixed order: angle before right still uses the new right *)
  vec_eq "order-independent" (v 0. 0. 1.) (camera "camera { angle 90 right <2,0,0> }").direction;
  expect_scene_error "angle 180" "camera { angle 180 }" ~line:1 ~col:16 ~sub:"less than 180";
  (* §1.3: the angle is multiplied by π/360 (POV-Ray's M_PI_360), not multiplied by π and then
     divided by 360: for 48°, 48·(π/360) = 0x1.acee9f37bebd6p-2 but (48·π)/360 = 0x1.acee9f37bebd5p-2,
     and 1 / tan / 2 gives 1.123018386952108 (0x1.1f7e220cc4171p+0) against 0x1.1f7e220cc4172p+0 —
     one bit that moves every camera ray and decides coincident-surface ties *)
  let d = (camera "camera { right <1,0,0> angle 48 }").direction in
  Alcotest.(check (float 0.)) "angle 48 to the last bit" 0x1.1f7e220cc4171p+0 d.z;
  Alcotest.(check bool) "not the (A·π)/360 value" true (d.z <> 0x1.1f7e220cc4172p+0)

let test_camera_look_at () =
  (* location <0,5,0>, look_at <5,5,0>: D = x; R = sky × D = y × x = <0,0,-1>;
     handedness (up × dir)·right = (y × z)·(1.33 x) = x·1.33x = 1.33 > 0, so right = 1.33 R;
     U = D × R = x × -z = <0,1,0> *)
  let c = camera "camera { location <0,5,0> look_at <5,5,0> }" in
  vec_eq "direction" (v 1. 0. 0.) c.direction;
  vec_eq "right" (v 0. 0. (-1.33)) c.right;
  vec_eq "up" (v 0. 1. 0.) c.up;
  vec_eq "location" (v 0. 5. 0.) c.location;
  (* look_at <1,1,1> from the origin: D = <1,1,1>/√3, R = y × D = <1,0,-1>/√3 → <1,0,-1>/√2,
     U = D × R = <-1,2,-1>/√6 *)
  let c = camera "camera { look_at <1,1,1> }" in
  let s3 = 1. /. sqrt 3. and s2 = 1. /. sqrt 2. and s6 = 1. /. sqrt 6. in
  vec_eq ~eps:1e-12 "diagonal direction" (v s3 s3 s3) c.direction;
  vec_eq ~eps:1e-12 "diagonal right" (v (1.33 *. s2) 0. (-1.33 *. s2)) c.right;
  vec_eq ~eps:1e-12 "diagonal up" (v (-.s6) (2. *. s6) (-.s6)) c.up;
  float_eq ~eps:1e-12 "dir·right = 0" 0. (Vec.dot c.direction c.right);
  float_eq ~eps:1e-12 "dir·up = 0" 0. (Vec.dot c.direction c.up);
  float_eq ~eps:1e-12 "right·up = 0" 0. (Vec.dot c.right c.up);
  (* the lengths are kept: direction 2 long, up 1, right 1.33 *)
  let c = camera "camera { direction <0,0,2> location <0,0,-5> look_at <3,0,-1> }" in
  (* D = normalize(<3,0,4>) = <0.6,0,0.8>, times 2 *)
  vec_eq ~eps:1e-12 "direction length kept" (v 1.2 0. 1.6) c.direction;
  float_eq ~eps:1e-12 "right length kept" 1.33 (Vec.length c.right);
  (* translate moves the location after look_at, not the vectors *)
  let c = camera "camera { location <0,0,-5> look_at <0,0,0> translate <1,0,0> }" in
  vec_eq "translated location" (v 1. 0. (-5.)) c.location;
  vec_eq "direction not translated" (v 0. 0. 1.) c.direction;
  (* a left-handed right vector keeps its sign: right -1.33x gives handedness < 0 *)
  let c = camera "camera { right <-1.33,0,0> location <0,5,0> look_at <5,5,0> }" in
  vec_eq "negative handedness" (v 0. 0. 1.33) c.right;
  expect_scene_error "look_at = location" "camera { location <1,1,1> look_at <1,1,1> }" ~line:1 ~col:35
    ~sub:"same as the location"

(* ---- lights (§10.2) ---- *)

let test_lights () =
  let s = scene "light_source { <1,2,3> }" in
  (match s.lights with
  | [ l ] ->
      vec_eq "position" (v 1. 2. 3.) l.position;
      (* §10.2: no colour means black *)
      rgb_eq "no colour is black" Rgb.black l.colour;
      Alcotest.(check bool) "shadows on" false l.shadowless;
      float_eq "no fade" 0. l.fade_power
  | _ -> Alcotest.fail "expected one light");
  let s =
    scene
      "light_source { <0,0,0> color rgb <1,0.5,0> }\n\
       light_source { <0,0,0>, 2 shadowless fade_distance 3 fade_power 2 translate <1,1,1> }"
  in
  match s.lights with
  | [ a; b ] ->
      rgb_eq "colour" (Rgb.make 1. 0.5 0.) a.colour;
      rgb_eq "float colour is grey" (Rgb.grey 2.) b.colour;
      Alcotest.(check bool) "shadowless" true b.shadowless;
      float_eq "fade_distance" 3. b.fade_distance;
      float_eq "fade_power" 2. b.fade_power;
      vec_eq "translated" (v 1. 1. 1.) b.position
  | _ -> Alcotest.fail "expected two lights, in order"

(* ---- version, gamma, background (§8.1, §8.4) ---- *)

let test_version_gamma () =
  let s, w = load "sphere { 0, 1 }" in
  Alcotest.(check int) "no #version: 362" 362 s.version;
  Alcotest.(check bool) "no #version: gamma off" true (s.gamma = Scene.Gamma_off);
  (* POV-Ray warns that gamma correction is off and that the scene has no #version *)
  let has sub = List.exists (fun (e : Error.t) -> contains ~sub e.msg) w in
  Alcotest.(check bool) "warning: assumed_gamma" true (has "assumed_gamma");
  Alcotest.(check bool) "warning: #version" true (has "#version");
  Alcotest.(check bool) "legacy warnings are not located" true (List.for_all (fun (e : Error.t) -> e.loc.line = 0) w);
  let s, w = load "#version 3.7;\nsphere { 0, 1 }" in
  Alcotest.(check int) "#version 3.7" 370 s.version;
  Alcotest.(check bool) "implied working gamma 1.0" true (s.gamma = Scene.Working 1.);
  (match w with
  | [ e ] -> check_contains "warning" ~sub:"assumed_gamma" e.msg
  | l -> Alcotest.failf "expected one warning about assumed_gamma, got %d" (List.length l));
  let s, w = load "#version 3.7;\nglobal_settings { assumed_gamma 2.2 }\nsphere { 0, 1 }" in
  Alcotest.(check bool) "assumed_gamma 2.2" true (s.gamma = Scene.Working 2.2);
  Alcotest.(check int) "no warning with assumed_gamma" 0 (List.length w);
  (* assumed_gamma applies whatever the version *)
  let s = scene "global_settings { assumed_gamma 1.0 }" in
  Alcotest.(check bool) "assumed_gamma 1 without #version" true (s.gamma = Scene.Working 1.);
  Alcotest.(check int) "still 362" 362 s.version;
  (* #version 3.6: int(3.6·100 + 0.5) = 360, legacy, gamma off *)
  let s = scene "#version 3.6;" in
  Alcotest.(check int) "#version 3.6" 360 s.version;
  Alcotest.(check bool) "3.6 gamma off" true (s.gamma = Scene.Gamma_off);
  (* the version keyword reads 3.7 before any #version *)
  float_eq "version keyword" 3.7 (radius "sphere { 0, version }")

let test_background () =
  (* a legacy scene without background: opaque black, as POV-Ray's is without an alpha channel *)
  colour_eq "legacy default" Colour.black (scene "").background;
  colour_eq "3.7 default" Colour.black (scene v37).background;
  (* #version 3.6 background{}: f = t = 0, rgb kept *)
  colour_eq "3.6 background" (colour5 1. 0.5 0. 0. 0.) (scene "#version 3.6;\nbackground { rgbt <1,0.5,0,0.5> }").background;
  (* 3.7: rgb·(1 − t) = <1,0.5,0>·0.5 = <0.5,0.25,0>, then f = t = 0 *)
  colour_eq "3.7 background transmit folded" (colour5 0.5 0.25 0. 0. 0.)
    (scene (v37 ^ "background { rgbt <1,0.5,0,0.5> }")).background

(* Found missing by this test, now fixed: POV-Ray's Parse_Frame tests
   EffectiveLanguageVersion() < 370 when it reads background{}, and that is 362 until a #version has
   been read. A scene without #version therefore keeps the background's rgb and sets f = t = 0
   (§8.1, §8.4). povml compares its provisional version (370) instead and folds the transmit in:
   background { rgbt <1,0.5,0,0.5> } gives <0.5,0.25,0> instead of <1,0.5,0>. *)
let test_legacy_background () =
  colour_eq "legacy background{} without #version" (colour5 1. 0.5 0. 0. 0.)
    (scene "background { rgbt <1,0.5,0,0.5> }").background;
  (* the same holds for a background written before the #version directive *)
  colour_eq "background before #version 3.7" (colour5 1. 0.5 0. 0. 0.)
    (scene "background { rgbt <1,0.5,0,0.5> }\n#version 3.7;").background

let test_global_settings () =
  let s = scene "" in
  Alcotest.(check int) "max_trace_level default 5" 5 s.max_trace_level;
  float_eq "adc_bailout default 1/255" (1. /. 255.) s.adc_bailout;
  rgb_eq "ambient_light default 1" Rgb.white s.ambient_light;
  let s = scene "global_settings { max_trace_level 7 adc_bailout 0.5 ambient_light rgb <0.5,1,1> }" in
  Alcotest.(check int) "max_trace_level 7" 7 s.max_trace_level;
  float_eq "adc_bailout 0.5" 0.5 s.adc_bailout;
  rgb_eq "ambient_light" (Rgb.make 0.5 1. 1.) s.ambient_light;
  (* §7: clipped to 1 … 256 *)
  Alcotest.(check int) "max_trace_level 0 → 1" 1 (scene "global_settings { max_trace_level 0 }").max_trace_level;
  Alcotest.(check int) "max_trace_level 300 → 256" 256 (scene "global_settings { max_trace_level 300 }").max_trace_level;
  (* POV-Ray warns above 256 (its wording), not at 256 and not below 1 *)
  let one_warning text =
    match warnings text with
    | [ w ] -> w.Error.msg
    | l -> Alcotest.failf "expected one warning, got %d" (List.length l)
  in
  check_contains "above 256" ~sub:"Maximum max_trace_level is 256 but 300 was specified. Going to use max_trace_level 256."
    (one_warning "#version 3.7;\nglobal_settings { assumed_gamma 1 max_trace_level 300 }\nsphere { 0, 1 }");
  Alcotest.(check int) "256: no warning" 0 (List.length (warnings "#version 3.7;\nglobal_settings { assumed_gamma 1 max_trace_level 256 }\nsphere { 0, 1 }"));
  Alcotest.(check int) "0: no warning" 0 (List.length (warnings "#version 3.7;\nglobal_settings { assumed_gamma 1 max_trace_level 0 }\nsphere { 0, 1 }"))

(* ---- finishes (§5.1, §10.1) ---- *)

let test_finish_defaults () =
  let f = finish "sphere { 0, 1 }" in
  rgb_eq "ambient 0.1" (Rgb.grey 0.1) f.ambient;
  rgb_eq "emission 0" Rgb.black f.emission;
  float_eq "diffuse 0.6" 0.6 f.diffuse;
  float_eq "brilliance 1" 1. f.brilliance;
  float_eq "phong 0" 0. f.phong;
  float_eq "phong_size 40" 40. f.phong_size;
  float_eq "specular 0" 0. f.specular;
  float_eq "roughness 0.05" 0.05 f.roughness;
  float_eq "metallic 0" 0. f.metallic;
  rgb_eq "reflection min 0" Rgb.black f.reflection.rmin;
  rgb_eq "reflection max 0" Rgb.black f.reflection.rmax;
  float_eq "falloff 1" 1. f.reflection.falloff;
  float_eq "exponent 1" 1. f.reflection.exponent;
  Alcotest.(check bool) "conserve_energy off" false f.conserve_energy;
  (* the same defaults when a finish block changes something else *)
  let f = finish "sphere { 0, 1 finish { phong 1 } }" in
  float_eq "diffuse still 0.6" 0.6 f.diffuse;
  rgb_eq "ambient still 0.1" (Rgb.grey 0.1) f.ambient;
  (* metallic alone means 1 *)
  float_eq "metallic alone" 1. (finish "sphere { 0, 1 finish { metallic } }").metallic;
  (* interior defaults: ior 1 *)
  float_eq "interior ior 1" 1. (the_object (scene "sphere { 0, 1 }")).interior.ior

let test_reflection () =
  (* §5.1: fresnel with one colour: that colour is the maximum, the minimum is 0 *)
  let r = (finish "sphere { 0, 1 finish { reflection { 1 fresnel } } }").reflection in
  rgb_eq "fresnel min 0" Rgb.black r.rmin;
  rgb_eq "fresnel max 1" Rgb.white r.rmax;
  Alcotest.(check bool) "fresnel set" true r.fresnel;
  (* old syntax: min = max = 0.3, type 0 *)
  let r = (finish "sphere { 0, 1 finish { reflection 0.3 } }").reflection in
  rgb_eq "old min" (Rgb.grey 0.3) r.rmin;
  rgb_eq "old max" (Rgb.grey 0.3) r.rmax;
  Alcotest.(check bool) "old not fresnel" false r.fresnel;
  float_eq "old falloff 1" 1. r.falloff;
  (* min, max, falloff, exponent, metallic *)
  let r = (finish "sphere { 0, 1 finish { reflection { 0.2, 0.8 falloff 2 exponent 0.5 metallic 0.7 } } }").reflection in
  rgb_eq "min" (Rgb.grey 0.2) r.rmin;
  rgb_eq "max" (Rgb.grey 0.8) r.rmax;
  float_eq "falloff" 2. r.falloff;
  float_eq "exponent as written" 0.5 r.exponent;
  float_eq "metallic" 0.7 r.refl_metallic;
  (* one colour without fresnel: min = max *)
  let r = (finish "sphere { 0, 1 finish { reflection { rgb <0.1,0.2,0.3> } } }").reflection in
  rgb_eq "one colour min" (Rgb.make 0.1 0.2 0.3) r.rmin;
  rgb_eq "one colour max" (Rgb.make 0.1 0.2 0.3) r.rmax;
  (* two colours with fresnel: min kept *)
  let r = (finish "sphere { 0, 1 finish { reflection { 0.1, 0.9 fresnel } } }").reflection in
  rgb_eq "two colours fresnel min kept" (Rgb.grey 0.1) r.rmin;
  (* fresnel off *)
  let r = (finish "sphere { 0, 1 finish { reflection { 1 fresnel off } } }").reflection in
  Alcotest.(check bool) "fresnel off" false r.fresnel;
  rgb_eq "fresnel off: min kept" Rgb.white r.rmin;
  float_eq "reflection_exponent" 2. (finish "sphere { 0, 1 finish { reflection_exponent 2 } }").reflection.exponent

let test_albedo () =
  (* §10.1: diffuse albedo a → a·(brilliance+1)/2 = 0.6·3/2 = 0.9, using the final brilliance *)
  float_eq "diffuse albedo" 0.9 (finish "sphere { 0, 1 finish { diffuse albedo 0.6 brilliance 2 } }").diffuse;
  float_eq "diffuse albedo, brilliance first" 0.9 (finish "sphere { 0, 1 finish { brilliance 2 diffuse albedo 0.6 } }").diffuse;
  (* with brilliance 1: a·2/2 = a *)
  float_eq "diffuse albedo brilliance 1" 0.6 (finish "sphere { 0, 1 finish { diffuse albedo 0.6 } }").diffuse;
  (* phong albedo p → p·(phong_size+1)/2 = 0.5·10/2 = 2.5 *)
  float_eq "phong albedo" 2.5 (finish "sphere { 0, 1 finish { phong albedo 0.5 phong_size 9 } }").phong;
  (* specular albedo s, roughness 0.5 (e = 2): s·(e+2)/(4(2 − 2^(−e/2))) = 1·4/(4·(2 − 0.5)) = 2/3 *)
  float_eq "specular albedo" (2. /. 3.) (finish "sphere { 0, 1 finish { specular albedo 1 roughness 0.5 } }").specular;
  (* without albedo the value is as written *)
  float_eq "diffuse plain" 0.6 (finish "sphere { 0, 1 finish { diffuse 0.6 brilliance 2 } }").diffuse

let test_interior () =
  let o = the_object (scene "sphere { 0, 1 interior { ior 1.5 fade_distance 2 fade_power 3 fade_color rgb <1,0,0> } }") in
  float_eq "ior" 1.5 o.interior.ior;
  float_eq "fade_distance" 2. o.interior.fade_distance;
  float_eq "fade_power" 3. o.interior.fade_power;
  rgb_eq "fade_colour" (Rgb.make 1. 0. 0.) o.interior.fade_colour;
  (* §2.7: the legacy finish ior is copied into the interior *)
  float_eq "legacy finish ior" 1.33 (the_object (scene "sphere { 0, 1 finish { ior 1.33 } }")).interior.ior

(* str and vstr with a width or precision whose string would not fit in the memory limit: a limit
   error before the string is made (found by fuzzing: a width of 2^31 took 12 s and 2 GiB) *)
let test_str_width_limit () =
  let opts = { opts with limits = { opts.limits with memory_mb = 16 } } in
  let expect text col =
    match Interp.load_string opts ~file:"t.pov" text with
    | _ -> Alcotest.failf "%s: expected a limit error" text
    | exception Error.Scene_error e ->
        Alcotest.(check bool) (text ^ ": a limit") true (e.kind = Limit);
        Alcotest.(check (pair int int)) (text ^ ": location") (1, col) (e.loc.line, e.loc.col);
        check_contains text ~sub:"'str' would make a string of 95 MiB, more than povml's memory limit of 16 MiB" e.msg
  in
  expect "#declare S = str(1, 100000000, 0);" 14;
  expect "#declare S = str(1, -100000000, 0);" 14;
  expect "#declare S = str(1, 0, 100000000);" 14;
  (match Interp.load_string opts ~file:"t.pov" "#declare S = vstr(5, <1,2,3>, \",\", 4000000, 0);" with
  | _ -> Alcotest.fail "vstr: expected a limit error"
  | exception Error.Scene_error e -> check_contains "vstr" ~sub:"'vstr' would make a string of 19 MiB" e.msg);
  (* a width within the limit still pads *)
  ignore (Interp.load_string opts ~file:"t.pov" "#declare S = str(1, 1000000, 0);\n#if (strlen(S) != 1000000) #error \"width\" #end")

(* ---- errors (locations and "did you mean") ---- *)

let test_errors () =
  expect_scene_error "misspelt sphere" "sphre { 0, 1 }" ~line:1 ~col:1 ~sub:"did you mean 'sphere'";
  expect_scene_error "misspelt on line 2" "#version 3.7;\n  sphre {" ~line:2 ~col:3 ~sub:"did you mean 'sphere'";
  expect_scene_error "unknown identifier" "sphere { Foo, 1 }" ~line:1 ~col:10 ~sub:"unknown identifier 'Foo'";
  expect_scene_error "misspelt declared identifier" "#declare Radius = 1;\nsphere { 0, Radus }" ~line:2 ~col:13
    ~sub:"did you mean 'Radius'";
  expect_scene_error "composite not supported" "composite{}" ~line:1 ~col:1 ~sub:"not supported yet";
  expect_scene_error "media not supported" "sphere { 0, 1\n interior { media { } } }" ~line:2 ~col:13 ~sub:"not supported yet";
  expect_scene_error "#include of a missing file" "#include \"no_such_file_povml.inc\"" ~line:1 ~col:1 ~sub:"cannot find the include file";
  expect_scene_error "missing radius" "sphere { <0,0,0> ; }" ~line:1 ~col:18 ~sub:"numeric expression";
  (* end of file is reported just after the last visible character, '1' at column 13 *)
  expect_scene_error "unclosed block" "sphere { 0, 1 " ~line:1 ~col:14 ~sub:"end of file";
  expect_scene_error "unclosed block, blank lines after" "sphere {\n  0, 1\n\n\n" ~line:2 ~col:7 ~sub:"end of file";
  expect_scene_error "declare a keyword" "#declare sphere = 1;" ~line:1 ~col:10 ~sub:"keyword";
  expect_scene_error "unknown directive" "#frobnicate" ~line:1 ~col:1 ~sub:"unknown directive";
  expect_scene_error "arithmetic on a string" "sphere { 0, \"a\" + 1 }" ~line:1 ~col:17 ~sub:"cannot do arithmetic";
  expect_scene_error "object id is a float" "#declare A = 1;\nobject { A }" ~line:2 ~col:10 ~sub:"not an object";
  (* lexer errors surface through load_string with their location *)
  expect_scene_error "lexer error" "sphere { 0, 1 }\n/* open" ~line:2 ~col:1 ~sub:"unterminated comment"

let test_load_file () =
  let path = Filename.temp_file "povml-unit" ".pov" in
  let oc = open_out_bin path in
  output_string oc "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nsphere { <1,2,3>, 0.5 }\n";
  close_out oc;
  let s, w = Interp.load_file opts path in
  Sys.remove path;
  vec_eq "centre" (v 1. 2. 3.) (fst (sphere_of (the_object s)));
  Alcotest.(check int) "no warnings" 0 (List.length w);
  (* locations name the file *)
  let path = Filename.temp_file "povml-unit" ".pov" in
  let oc = open_out_bin path in
  output_string oc "sphere {\n  0, 1 $ }";
  close_out oc;
  expect_error ~file:path "error in a file" (fun () -> Interp.load_file opts path) ~line:2 ~col:8 ~sub:"unexpected character";
  Sys.remove path;
  (* a missing file is a located-nowhere scene error, not an exception of another kind *)
  match Interp.load_file opts "/nonexistent/povml/none.pov" with
  | _ -> Alcotest.fail "expected an error"
  | exception Error.Scene_error e -> check_contains "missing file" ~sub:"cannot open" e.msg

let test_warnings_order () =
  (* warnings come in the order they arose *)
  let w = warnings "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nsphere { 0, 1/0 }\nsphere { 0, 2/0 }" in
  Alcotest.(check (list int)) "lines" [ 3; 4 ] (List.map (fun (e : Error.t) -> e.loc.line) w);
  (* §11.3: a missing ';' after a float #declare warns in a 3.1 scene *)
  let w = warnings "#version 3.1;\nglobal_settings { assumed_gamma 1 }\n#declare A = 1\nsphere { 0, A }" in
  match w with
  | [ e ] -> check_contains "semicolon warning" ~sub:"';' at the end" e.msg; Alcotest.(check int) "at the next token" 4 e.loc.line
  | l -> Alcotest.failf "expected one warning, got %d" (List.length l)

let test_declare_semicolon_required () =
  (* from 3.5 on it is an error, at the token after the value, as in POV-Ray 3.7 *)
  expect_error "float" (fun () -> scene "#version 3.7;\n#declare A = 1\nsphere { 0, A }") ~line:3 ~col:1 ~sub:"require ';'";
  expect_error "vector before a directive" (fun () -> scene "#declare V = <1,2,3>\n#declare B = 2;\nsphere { V, B }") ~line:2 ~col:1 ~sub:"require ';'";
  expect_error "before a macro call, not run" (fun () -> scene "#macro M() #error \"ran\" #end\n#declare A = 1\nM()") ~line:3 ~col:1 ~sub:"require ';'"

let test_macro_after_declared_texture () =
  (* looking past a texture for another layer calls no macro: the call after it sees the new
     identifier (POV-Ray's incdemo/screen.pov) *)
  let m = "#macro Mk(T) sphere { 0, 2 texture { T } } #end\n" in
  let colour text = (pigment text).Colour.red in
  float_eq "one layer" 0.5 (colour (m ^ "#declare T = texture { pigment { rgb 0.5 } }\nMk(T)"));
  float_eq "the radius" 2. (radius (m ^ "#declare T = texture { pigment { rgb 0.5 } }\nMk(T)"));
  (* a macro called inside the value is still called where it stands *)
  float_eq "inside" 3. (radius "#macro R() 3 #end\n#declare A = R();\nsphere { 0, A }")

(* Parse_Object_Id: an object identifier right inside a shape's braces makes the shape a copy of
   that object with the modifiers that follow, whatever the keyword *)
let test_shape_of_identifier () =
  let dumps text = List.map Dump.obj (scene ("#version 3.7;\n#declare S = sphere { 0, 1 pigment { rgb x } }\n" ^ text)).objects in
  let as_object = dumps "object { S translate x scale 2 }" in
  Alcotest.(check (list string)) "sphere { S ... }" as_object (dumps "sphere { S translate x scale 2 }");
  Alcotest.(check (list string)) "box { S ... }: still the sphere" as_object (dumps "box { S translate x scale 2 }");
  Alcotest.(check (list string)) "superellipsoid { S ... }" as_object (dumps "superellipsoid { S translate x scale 2 }");
  Alcotest.(check (list string)) "mesh2 { S ... }" as_object (dumps "mesh2 { S translate x scale 2 }");
  Alcotest.(check (list string)) "height_field { S ... }" as_object (dumps "height_field { S translate x scale 2 }")

let tests =
  [
    Alcotest.test_case "a shape made of an object identifier" `Quick test_shape_of_identifier;
    Alcotest.test_case "promotion and operators" `Quick test_promotion;
    Alcotest.test_case "functions" `Quick test_functions;
    Alcotest.test_case "optional commas in vectors" `Quick test_optional_vector_commas;
    Alcotest.test_case "directives without '#'" `Quick test_directives_without_hash;
    Alcotest.test_case "array declared without ';'" `Quick test_array_declared_without_semicolon;
    Alcotest.test_case "string declared without ';'" `Quick test_string_declared_without_semicolon;
    Alcotest.test_case "';' required after a float from 3.5" `Quick test_declare_semicolon_required;
    Alcotest.test_case "macro call after a declared texture" `Quick test_macro_after_declared_texture;
    Alcotest.test_case "component selectors" `Quick test_components;
    Alcotest.test_case "division by zero" `Quick test_division_by_zero;
    Alcotest.test_case "colours" `Quick test_colours;
    Alcotest.test_case "plane" `Quick test_plane;
    Alcotest.test_case "translate" `Quick test_translate;
    Alcotest.test_case "declared objects" `Quick test_declare_object;
    Alcotest.test_case "declared textures" `Quick test_declare_values;
    Alcotest.test_case "camera defaults" `Quick test_camera_defaults;
    Alcotest.test_case "camera angle" `Quick test_camera_angle;
    Alcotest.test_case "camera look_at" `Quick test_camera_look_at;
    Alcotest.test_case "lights" `Quick test_lights;
    Alcotest.test_case "version and gamma" `Quick test_version_gamma;
    Alcotest.test_case "background" `Quick test_background;
    Alcotest.test_case "global_settings" `Quick test_global_settings;
    Alcotest.test_case "finish defaults" `Quick test_finish_defaults;
    Alcotest.test_case "reflection" `Quick test_reflection;
    Alcotest.test_case "albedo" `Quick test_albedo;
    Alcotest.test_case "interior" `Quick test_interior;
    Alcotest.test_case "errors" `Quick test_errors;
    Alcotest.test_case "str width and the memory limit" `Quick test_str_width_limit;
    Alcotest.test_case "warnings" `Quick test_warnings_order;
    Alcotest.test_case "load_file" `Quick test_load_file;
  ]

(* Found missing by this test, now fixed: POV-Ray's Parse_Sphere and Parse_Plane read the comma
   with Parse_Comma, which accepts a missing comma (it ungets any other token), so
   sphere { <0,0,0> 1 } is a valid unit sphere. povml requires the comma. Not in docs/povray-rules.md; from
   the POV-Ray source (parse.cpp). *)
let test_optional_comma () =
  float_eq "sphere without comma" 1. (radius "sphere { <0,0,0> 1 }");
  let _, d = plane_of (the_object (scene "plane { y 2 }")) in
  float_eq "plane without comma" 2. d

(* Found missing by this test, now fixed: in POV-Ray 3.7 (parse.cpp: Parse_Frame, CAMERA_TOKEN, for
   languageVersion ≥ 3.50) a second camera statement starts again from the default camera, with the
   warning "More than one camera in scene. Ignoring previous camera(s).". povml lets the second
   camera modify the first (interp.ml: parse_camera). Not in docs/povray-rules.md. *)
let test_second_camera () =
  let s, w = load (v37 ^ "camera { location <1,2,3> }\ncamera { right <2,0,0> }\nsphere { 0, 1 }") in
  vec_eq "the first camera's location is dropped" (v 0. 0. 0.) s.camera.location;
  vec_eq "the second camera's right" (v 2. 0. 0.) s.camera.right;
  Alcotest.(check int) "one warning" 1 (List.length w)

(* Found missing by this test, now fixed: POV-Ray's Parse_Global_Settings ignores a second
   assumed_gamma with the warning "New instance of assumed_gamma ignored" (the first one stays);
   povml keeps the last one. From the POV-Ray source (parse.cpp), not in docs/povray-rules.md. *)
let test_second_assumed_gamma () =
  let s, w = load "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\nglobal_settings { assumed_gamma 2.2 }\nsphere { 0, 1 }" in
  Alcotest.(check bool) "the first assumed_gamma stays" true (s.gamma = Scene.Working 1.);
  Alcotest.(check int) "one warning" 1 (List.length w)

(* POV-Ray's Parse_Initalizer (tokenize.cpp) reads each element with Parse_RValue and then
   Parse_Comma, which takes a comma if one comes and ungets anything else; each inner '}' and the
   outermost one are followed by Parse_Comma too. So the commas are optional, for every element
   type, and one may follow the last element and the closing brace (textures/patterns/tiling.pov:48
   and advanced/grenadine/lemon.inc:77 leave some out). Checked with POV-Ray: each scene below
   renders; { 1 -2 } is the one element 1-2, and POV-Ray refuses it too. *)
let test_array_initialiser_commas () =
  float_eq "floats" 3. (radius "#declare A = array[3] { 1, 2 3 }\nsphere { 0, A[2] }");
  vec_eq "vectors" (v 3. 4. 0.) (centre "#declare A = array[2] { <1,2>\n <3,4> }\nsphere { A[1], 1 }");
  float_eq "strings" 2. (radius "#declare A = array[2] { \"a\" \"bc\" }\nsphere { 0, strlen(A[1]) }");
  float_eq "identifiers" 0.5 (pigment "#declare C = rgb 0.5;\n#declare A = array[2] { C C }\nsphere { 0, 1 pigment { A[1] } }").blue;
  float_eq "nested levels" 3. (radius "#declare A = array[2][2] { {1, 2} {3, 4} }\nsphere { 0, A[1][0] }");
  float_eq "trailing commas" 4. (radius "#declare A = array[2][2] { {1, 2,}, {3, 4,}, },\nsphere { 0, A[1][1] }");
  let s = scene "#declare A = array[2] { sphere { 0, 1 } sphere { x, 2 } }\nobject { A[0] }\nobject { A[1] }" in
  Alcotest.(check int) "objects" 2 (List.length s.objects);
  expect_scene_error "1 -2 is one element" "#declare A = array[2] { 1 -2 }" ~line:1 ~col:23 ~sub:"this initialiser has 1 elements"

(* POV-Ray's Parse_Num_Factor (express.cpp) reads the terms of <…> with a Parse_Comma after each
   of the first four: a comma may follow the second, third or fourth term before the '>', not the
   first or the fifth (animations/float4/float4.pov:42 writes rgb<0.2,0.1,0.5,>). Checked with
   POV-Ray: <1,> says "Expected 'numeric expression', > found instead", <1,2,3,4,5,> "Expected '>'". *)
let test_vector_trailing_comma () =
  vec_eq "<1,2,3,>" (v 1. 2. 3.) (centre "sphere { <1,2,3,>, 1 }");
  vec_eq "<1,2,>" (v 1. 2. 0.) (centre "sphere { <1,2,>, 1 }");
  vec_eq "<1 2 3,>" (v 1. 2. 3.) (centre "sphere { <1 2 3,>, 1 }");
  colour_eq "rgb<0.2,0.1,0.5,>" (colour5 0.2 0.1 0.5 0. 0.) (pigment "sphere { 0, 1 pigment { rgb<0.2,0.1,0.5,> } }");
  colour_eq "rgbft <…,>" (colour5 0.1 0.2 0.3 0.4 0.) (pigment "sphere { 0, 1 pigment { rgbf <0.1,0.2,0.3,0.4,> } }");
  expect_scene_error "<1,>" "sphere { <1,>, 1 }" ~line:1 ~col:13 ~sub:"expected a numeric expression but found '>'";
  expect_scene_error "<1,2,3,4,5,>" "sphere { <1,2,3,4,5,>, 1 }" ~line:1 ~col:21 ~sub:"at most 5 terms";
  expect_scene_error "<1,2,,>" "sphere { <1,2,,>, 1 }" ~line:1 ~col:15 ~sub:"found ','"

(* POV-Ray's tokenizer (tokenize.cpp: Get_Token, '#', and Parse_Directive) reads the token after a
   '#'; when it is no directive name, that token is read as usual, so a '#' with nothing after it
   is ignored (language/image_size.pov:25 ends "look_at <0,2,0>#"). Checked with POV-Ray: the scene
   renders, without a message, and so it does in povml. *)
let test_lone_hash () =
  let s, w = load (v37 ^ "camera { location -5*z look_at 0#\n}\nsphere { 0, 1 # }") in
  vec_eq "the camera is read" (v 0. 0. (-5.)) s.camera.location;
  Alcotest.(check int) "the sphere is read" 1 (List.length s.objects);
  Alcotest.(check (list (pair int int))) "no warning" [] (List.map (fun (e : Error.t) -> (e.loc.line, e.loc.col)) w)

(* A declaration whose value calls a macro with an argument povml cannot make yet (POV-Ray's
   textures/pigments/blkhole.pov:51, Correct_Pigment_Gamma(pigment { DMFWood4 … }, 2.2)) is a value
   povml cannot make: it is skipped through the call's ')', so what follows is read, and using it
   is the error. Outside a declaration the argument is the error, at its keyword. POV-Ray renders
   these (it has wood and datetime). *)
let test_unsupported_macro_argument () =
  let m = "#macro M(P, G) pigment { P } #end\n#macro F(A) A #end\n#declare S = sphere { 0, 1 }\n" in
  let s, w = load (m ^ "#declare Tree = M(pigment { density_file df3 \"x.df3\" }, 2.2)\n#declare X = F(strlen(datetime(now))) * 2;\nsphere { 0, 1 }") in
  Alcotest.(check int) "the sphere after the declarations is read" 1 (List.length s.objects);
  Alcotest.(check (list int)) "a warning for each declaration" [ 4; 5 ]
    (List.map (fun (e : Error.t) -> e.loc.line) (List.filter (fun (e : Error.t) -> e.loc.line > 0) w));
  expect_scene_error "used" (m ^ "#declare Tree = M(pigment { density_file df3 \"x.df3\" }, 2.2)\nsphere { 0, 1 pigment { Tree } }") ~line:5 ~col:25
    ~sub:"not supported yet: 'density_file' as a pattern (used through 'Tree')";
  expect_scene_error "outside a declaration" (m ^ "sphere { 0, 1 M(pigment { density_file df3 \"x.df3\" }, 2.2) }") ~line:4 ~col:27
    ~sub:"not supported yet: 'density_file' as a pattern"

(* A directive read while a declaration looks past its value (array[3] with no initialiser looks
   for a '{') is no part of the value: an unsupported value in its condition is the error, there
   (incdemo/circletext.pov met it through Circle_Text in shapes.inc, when max_extent was not read
   yet). POV-Ray takes the branch the value decides. *)
let test_unsupported_in_directive () =
  let d = "#declare S = sphere { 0, 1 }\n#declare FW = strlen(datetime(now));\n" in
  expect_scene_error "#if after array[3]" (d ^ "#local C = array[3]\n#if (FW > 2)\n  #error \"too long\"\n#end\nsphere { 0, 1 }")
    ~line:4 ~col:6 ~sub:"not supported yet: the function 'datetime' (used through 'FW')";
  expect_scene_error "#if inside a declared pigment" (d ^ "#declare P = pigment { #if (FW > 1) rgb 1 #else rgb 0 #end }\nsphere { 0, 1 }")
    ~line:3 ~col:29 ~sub:"not supported yet: the function 'datetime'";
  expect_scene_error "a macro call after array[3]"
    ("#macro M(P) sphere { 0, 1 pigment { P } } #end\n#declare A = array[3]\nM(pigment { density_file df3 \"x.df3\" })") ~line:3 ~col:13
    ~sub:"not supported yet: 'density_file' as a pattern"

let source_rules =
  [
    Alcotest.test_case "array initialiser commas" `Quick test_array_initialiser_commas;
    Alcotest.test_case "trailing comma in a vector" `Quick test_vector_trailing_comma;
    Alcotest.test_case "lone '#'" `Quick test_lone_hash;
    Alcotest.test_case "unsupported macro argument" `Quick test_unsupported_macro_argument;
    Alcotest.test_case "unsupported value in a directive" `Quick test_unsupported_in_directive;
    Alcotest.test_case "second assumed_gamma" `Quick test_second_assumed_gamma;
    Alcotest.test_case "legacy background without #version" `Quick test_legacy_background;
    Alcotest.test_case "optional comma" `Quick test_optional_comma;
    Alcotest.test_case "second camera" `Quick test_second_camera;
  ]
