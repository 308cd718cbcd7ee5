(* Compile: inside tests (§2.2, §2.3), shadow strategy (§4), starting interiors (§6.4), surfaces (§3.2). *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let shape_of_text text = (compile text).objects.(0).shape
let inside_t msg expected shape p = Alcotest.(check bool) msg expected (Shape.inside (Array.make 512 0.) shape p)

let test_sphere_inside () =
  let s = shape_of_text "sphere { <0,0,3>, 1 }" in
  (* |P − C|² < r² = 1 *)
  inside_t "centre" true s (v 0. 0. 3.);
  inside_t "|d|² = 0.25" true s (v 0. 0. 2.5);
  inside_t "|d|² = 2.25" false s (v 0. 0. 4.5);
  (* on the surface |d|² = 1 is not < 1 *)
  inside_t "surface point is outside" false s (v 0. 0. 2.);
  inside_t "origin" false s (v 0. 0. 0.);
  (* |<0.7,0.7,3>−C|² = 0.98 < 1 *)
  inside_t "off-axis inside" true s (v 0.7 0.7 3.);
  (* 0.8² + 0.8² = 1.28 ≥ 1 *)
  inside_t "off-axis outside" false s (v 0.8 0.8 3.);
  match s with
  | Compiled.Sphere sp ->
      float_eq "r2" 1. sp.r2;
      float_eq "radius" 1. sp.radius;
      float_eq "cz" 3. sp.cz
  | _ ->
      Alcotest.fail "expected a sphere"

let test_plane_inside () =
  (* plane { y, 1 }: inside is n̂·P − d < EPSILON, the side opposite the normal *)
  let p = shape_of_text "plane { y, 1 }" in
  inside_t "below (0 − 1 < 0)" true p (v 0. 0. 0.);
  inside_t "above (2 − 1 > 0)" false p (v 0. 2. 0.);
  inside_t "on the plane (0 < 1e-10)" true p (v 5. 1. 5.);
  (match p with
  | Compiled.Plane pl ->
      (* POV-Ray's Distance = −d *)
      float_eq "dist = -d" (-1.) pl.dist;
      float_eq "ny" 1. pl.ny
  | _ ->
      Alcotest.fail "expected a plane");
  (* plane { -y, 1 } is y = −1 with the normal down: inside is −y − 1 < 0, i.e. y > −1 *)
  let p = shape_of_text "plane { -y, 1 }" in
  inside_t "flipped: origin inside" true p (v 0. 0. 0.);
  inside_t "flipped: y = -2 outside" false p (v 0. (-2.) 0.);
  (* plane { <0,2,0>, 1 } lies at y = 1 (d not divided by |n|) *)
  let p = shape_of_text "plane { <0,2,0>, 1 }" in
  inside_t "y = 0.9 inside" true p (v 0. 0.9 0.);
  inside_t "y = 1.1 outside" false p (v 0. 1.1 0.)

let mode_t =
  Alcotest.testable
    (fun ppf m ->
      Format.pp_print_string ppf
        (match m with Compiled.No_occluders -> "No_occluders" | Any_hit -> "Any_hit" | Filtered -> "Filtered"))
    ( = )

let mode text = (compile text).shadow_mode

let test_shadow_mode () =
  Alcotest.check mode_t "empty scene" Compiled.No_occluders (mode "");
  Alcotest.check mode_t "only no_shadow objects" Compiled.No_occluders (mode "sphere { 0, 1 no_shadow }");
  Alcotest.check mode_t "opaque" Compiled.Any_hit (mode "sphere { 0, 1 } plane { y, 0 pigment { rgb 1 } }");
  Alcotest.check mode_t "one transmit" Compiled.Filtered
    (mode "sphere { 0, 1 } sphere { x, 1 pigment { rgbt <1,1,1,0.5> } }");
  Alcotest.check mode_t "one filter" Compiled.Filtered (mode "sphere { 0, 1 pigment { rgbf 0.5 } }");
  (* a transparent object that casts no shadow does not need the filtered walk *)
  Alcotest.check mode_t "transparent but no_shadow" Compiled.Any_hit
    (mode "sphere { 0, 1 } sphere { x, 1 pigment { rgbt 0.5 } no_shadow }");
  let c = compile "sphere { 0, 1 } sphere { x, 1 no_shadow } sphere { y, 1 }" in
  Alcotest.(check (list int)) "occluders are the objects without no_shadow" [ 0; 2 ]
    (List.sort compare (List.map (fun (o : Compiled.obj) -> o.id) (Array.to_list c.occluders.unbounded @ Array.to_list c.occluders.bounded)));
  Alcotest.(check (list bool)) "opaque flags" [ true; false ]
    (List.map (fun (o : Compiled.obj) -> o.opaque) (Array.to_list (compile "sphere { 0, 1 } sphere { 0, 1 pigment { rgbt 0.1 } }").objects))

let test_start_interiors () =
  (* camera at the origin (default): spheres 0 and 2 contain it, sphere 1 does not;
     the list has the last entered first *)
  let c = compile "sphere { 0, 1 } sphere { <5,0,0>, 1 } sphere { 0, 2 }" in
  Alcotest.(check (list int)) "camera inside spheres 0 and 2" [ 2; 0 ] c.start_interiors;
  let c = compile "camera { location <0,0,-5> } sphere { 0, 1 } sphere { 0, 2 }" in
  Alcotest.(check (list int)) "camera outside" [] c.start_interiors;
  (* §6.4: planes count: the camera under plane { y, 100 } starts inside it *)
  let c = compile "plane { y, 100 } plane { y, -1 }" in
  Alcotest.(check (list int)) "under plane y 100, above plane y -1" [ 0 ] c.start_interiors;
  (* the camera translate is taken into account *)
  let c = compile "camera { translate <10,0,0> } sphere { <10,0,0>, 1 }" in
  Alcotest.(check (list int)) "translated camera" [ 0 ] c.start_interiors

let test_surface () =
  (* §3.2: emitted = C·ambient·ambient_light·att + C·emission·att; 3.7 att = 1 − f − t *)
  let c =
    compile (v37 ^ "sphere { 0, 1 pigment { rgbf <0.5,0.5,0.5,0.4> } finish { ambient 1 diffuse 0 } }")
  in
  let s = (surf_of c.objects.(0)) in
  (* att = 1 − 0.4 = 0.6; emitted = 0.5·1·1·0.6 = 0.3 *)
  float_eq ~eps:1e-6 "3.7 att" 0.6 s.att;
  rgb_eq ~eps:1e-6 "3.7 emitted" (Rgb.grey 0.3) s.emitted;
  (* filcol = rgb·f + t = 0.5·0.4 = 0.2 *)
  rgb_eq ~eps:1e-6 "filcol" (Rgb.grey 0.2) s.filcol;
  Alcotest.(check bool) "transparent" true s.transparent;
  Alcotest.(check bool) "not lit (diffuse 0)" false s.lit;
  (* legacy att = 1 − (f·max(r,g,b) + t) = 1 − 0.4·0.5 = 0.8; emitted = 0.5·0.8 = 0.4 *)
  let c = compile "sphere { 0, 1 pigment { rgbf <0.5,0.5,0.5,0.4> } finish { ambient 1 diffuse 0 } }" in
  Alcotest.(check bool) "legacy" true c.legacy;
  float_eq ~eps:1e-6 "legacy att" 0.8 (surf_of c.objects.(0)).att;
  rgb_eq ~eps:1e-6 "legacy emitted" (Rgb.grey 0.4) (surf_of c.objects.(0)).emitted;
  (* ambient 0.2 on rgb <1,0.5,0.25>, ambient_light <0.5,1,1>, emission 0.1:
     r = 1·0.2·0.5 + 1·0.1 = 0.2; g = 0.5·0.2 + 0.5·0.1 = 0.15; b = 0.25·0.2 + 0.25·0.1 = 0.075 *)
  let c =
    compile
      (v37
     ^ "global_settings { ambient_light rgb <0.5,1,1> }\n\
        sphere { 0, 1 pigment { rgb <1,0.5,0.25> } finish { ambient 0.2 emission 0.1 } }")
  in
  let s = (surf_of c.objects.(0)) in
  rgb_eq ~eps:1e-6 "emitted with ambient_light and emission" (Rgb.make 0.2 0.15 0.075) s.emitted;
  Alcotest.(check bool) "lit (default diffuse 0.6)" true s.lit;
  (* spec exponent 1/roughness = 1/0.05 = 20 *)
  float_eq ~eps:1e-5 "spec_exp" 20. s.spec_exp;
  Alcotest.(check bool) "opaque" false s.transparent;
  Alcotest.(check bool) "no reflection" false s.reflects;
  Alcotest.(check bool) "reflects" true (surf_of (compile "sphere { 0, 1 finish { reflection 0.1 } }").objects.(0)).reflects

let test_lights () =
  let c = compile "light_source { <1,2,3>, rgb <1,0.5,0> fade_distance 2 fade_power 1 } light_source { 0, 1 fade_power 2 }" in
  Alcotest.(check int) "two lights" 2 (Array.length c.lights);
  let a = c.lights.(0) and b = c.lights.(1) in
  float_eq "lx" 1. a.lx;
  float_eq "lz" 3. a.lz;
  rgb_eq "colour" (Rgb.make 1. 0.5 0.) a.lcolour;
  (* §3.4: fade only if fade_power > 0 and |fade_distance| > EPSILON *)
  Alcotest.(check bool) "fade on" true a.fade;
  Alcotest.(check bool) "fade off without distance" false b.fade;
  (* camera, background and settings are passed through *)
  let c = compile "global_settings { max_trace_level 3 } camera { location <1,2,3> }" in
  Alcotest.(check int) "max_trace_level" 3 c.max_trace_level;
  vec_eq "camera" (v 1. 2. 3.) c.camera.location;
  colour_eq "background" Colour.black c.background

let tests =
  [
    Alcotest.test_case "sphere inside" `Quick test_sphere_inside;
    Alcotest.test_case "plane inside" `Quick test_plane_inside;
    Alcotest.test_case "shadow mode" `Quick test_shadow_mode;
    Alcotest.test_case "start interiors" `Quick test_start_interiors;
    Alcotest.test_case "surface" `Quick test_surface;
    Alcotest.test_case "lights and settings" `Quick test_lights;
  ]
