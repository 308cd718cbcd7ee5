(* Small modules: Suggest, Value, Colour, Rgb, Stats, Error, Image, Output, Defaults. *)

open Helpers

(* ---- Suggest ---- *)

let test_suggest () =
  Alcotest.(check (list string)) "sphre" [ "sphere" ] (Suggest.nearest "sphre" Interp.keywords);
  Alcotest.(check (list string)) "ligth_source" [ "light_source" ] (Suggest.nearest "ligth_source" Interp.keywords);
  (* case is ignored in the distance *)
  Alcotest.(check (list string)) "SPHERE" [ "sphere" ] (Suggest.nearest "SPHERE" Interp.keywords);
  (* nothing close *)
  Alcotest.(check (list string)) "far" [] (Suggest.nearest "xyzzyplugh" Interp.keywords);
  (* the name itself is not suggested *)
  Alcotest.(check (list string)) "exact" [] (Suggest.nearest "abc" [ "abc" ]);
  (* up to three, closest first, ties in alphabetical order *)
  Alcotest.(check (list string)) "three" [ "abc"; "abd"; "abe" ] (Suggest.nearest "ab" [ "abf"; "abe"; "abd"; "abc" ]);
  (* phong: limit max(1, 5/3) = 1: phang and phon at 1, phong_size at 5 *)
  Alcotest.(check (list string)) "closest" [ "phang"; "phon" ] (Suggest.nearest "phong" [ "phong_size"; "phon"; "phang" ]);
  (* distance 2 allowed for 6+ letters: "difuse" → diffuse (1) *)
  Alcotest.(check (list string)) "difuse" [ "diffuse" ] (Suggest.nearest "difuse" [ "diffuse"; "pigment" ])

(* ---- Value (§11.2) ---- *)

let value_t =
  Alcotest.testable
    (fun ppf v ->
      match v with
      | Value.Float f -> Format.fprintf ppf "Float %g" f
      | Value.Vector a -> Format.fprintf ppf "Vector [%s]" (String.concat ";" (Array.to_list (Array.map string_of_float a)))
      | Value.Colour a -> Format.fprintf ppf "Colour [%s]" (String.concat ";" (Array.to_list (Array.map string_of_float a)))
      | v -> Format.pp_print_string ppf (Value.kind_name v))
    ( = )

let test_value () =
  Alcotest.(check (array (float 0.))) "float replicated" [| 2.; 2.; 2. |] (Value.promote (Value.Float 2.) 3);
  Alcotest.(check (array (float 0.))) "vector padded" [| 1.; 2.; 0.; 0.; 0. |] (Value.promote (Value.Vector [| 1.; 2. |]) 5);
  Alcotest.(check (option value_t)) "<1,2,3> + 1" (Some (Value.Vector [| 2.; 3.; 4. |]))
    (Value.arith ( +. ) (Value.Vector [| 1.; 2.; 3. |]) (Value.Float 1.));
  Alcotest.(check (option value_t)) "<1,2> + <1,1,1>" (Some (Value.Vector [| 2.; 3.; 1. |]))
    (Value.arith ( +. ) (Value.Vector [| 1.; 2. |]) (Value.Vector [| 1.; 1.; 1. |]));
  (* a colour operand makes a 5-term colour: (rgb 1)·0.5 keeps f = t = 0 *)
  Alcotest.(check (option value_t)) "colour * 0.5" (Some (Value.Colour [| 0.5; 0.5; 0.5; 0.; 0. |]))
    (Value.arith ( *. ) (Value.Colour [| 1.; 1.; 1.; 0.; 0. |]) (Value.Float 0.5));
  Alcotest.(check (option value_t)) "float op float" (Some (Value.Float 6.)) (Value.arith ( *. ) (Value.Float 2.) (Value.Float 3.));
  Alcotest.(check (option value_t)) "string" None (Value.arith ( +. ) (Value.String "a") (Value.Float 1.));
  Alcotest.(check (option value_t)) "map" (Some (Value.Vector [| -1.; -2. |])) (Value.map (fun x -> -.x) (Value.Vector [| 1.; 2. |]));
  Alcotest.(check int) "terms float" 1 (Value.terms (Value.Float 1.));
  Alcotest.(check int) "terms colour" 5 (Value.terms (Value.Colour [| 0.; 0.; 0.; 0.; 0. |]));
  Alcotest.(check int) "terms string" 0 (Value.terms (Value.String "s"));
  Alcotest.(check string) "kind_name" "a 3-term vector" (Value.kind_name (Value.Vector [| 1.; 2.; 3. |]))

(* ---- Colour, Rgb ---- *)

let test_colour () =
  colour_eq "of_array 3" (colour5 0.1 0.2 0.3 0. 0.) (Colour.of_array [| 0.1; 0.2; 0.3 |]);
  colour_eq "of_array 5" (colour5 0.1 0.2 0.3 0.4 0.5) (Colour.of_array [| 0.1; 0.2; 0.3; 0.4; 0.5 |]);
  rgb_eq "rgb" (Rgb.make 0.1 0.2 0.3) (Colour.rgb (colour5 0.1 0.2 0.3 0.4 0.5));
  (* §3.5: rgb·f + t = <1·0.5 + 0.2, 0.5·0.5 + 0.2, 0·0.5 + 0.2> = <0.7, 0.45, 0.2> *)
  rgb_eq "transmitted" (Rgb.make 0.7 0.45 0.2) (Colour.transmitted (colour5 1. 0.5 0. 0.5 0.2));
  (* grey = 0.297 r + 0.589 g + 0.114 b: white is 1, <1,0,0> is 0.297 *)
  float_eq "intensity white" 1. (Rgb.intensity Rgb.white);
  float_eq "intensity red" 0.297 (Rgb.intensity (Rgb.make 1. 0. 0.));
  float_eq "intensity <0.2,0.4,0.6>" 0.3634 (Rgb.intensity (Rgb.make 0.2 0.4 0.6));
  float_eq "max3" 0.7 (Rgb.max3 (Rgb.make 0.2 0.7 (-1.)));
  Alcotest.(check bool) "is_zero black" true (Rgb.is_zero Rgb.black);
  Alcotest.(check bool) "is_zero" false (Rgb.is_zero (Rgb.make 0. 0. 1e-30));
  rgb_eq "add" (Rgb.make 1.5 1. 0.5) (Rgb.add (Rgb.grey 0.5) (Rgb.make 1. 0.5 0.));
  rgb_eq "mul" (Rgb.make 0.5 0.25 0.) (Rgb.mul (Rgb.grey 0.5) (Rgb.make 1. 0.5 0.));
  rgb_eq "scale" (Rgb.make 2. 1. 0.) (Rgb.scale 2. (Rgb.make 1. 0.5 0.));
  (* f32 rounds to single precision: 0.1 becomes 0.100000001490116… *)
  float_eq ~eps:0. "f32 0.1" 0.100000001490116119384765625 (Precision.f32 0.1);
  float_eq ~eps:0. "f32 0.5 exact" 0.5 (Precision.f32 0.5)

let test_defaults () =
  let f = Defaults.finish in
  rgb_eq "ambient" (Rgb.grey 0.1) f.ambient;
  float_eq "diffuse" 0.6 f.diffuse;
  float_eq "phong_size" 40. f.phong_size;
  float_eq "roughness" 0.05 f.roughness;
  float_eq "refraction" 1. f.refraction;
  float_eq "interior ior" 1. Defaults.interior.ior;
  colour_eq "texture pigment black" Colour.black (match Defaults.layer.pigment with Solid c | Solid_placed { colour = c; _ } -> c | Pattern _ -> Alcotest.fail "a pattern")

(* ---- Stats ---- *)

let test_stats () =
  let a = Stats.create () and b = Stats.create () in
  Alcotest.(check int) "fresh" 0 a.camera_rays;
  a.camera_rays <- 3;
  a.max_level <- 4;
  a.samples <- 2;
  b.camera_rays <- 5;
  b.max_level <- 2;
  b.shadow_rays <- 7;
  let m = Stats.merge a b in
  Alcotest.(check int) "camera rays added" 8 m.camera_rays;
  Alcotest.(check int) "shadow rays added" 7 m.shadow_rays;
  Alcotest.(check int) "samples" 2 m.samples;
  Alcotest.(check int) "max_level is the larger" 4 m.max_level;
  Alcotest.(check int) "inputs unchanged" 3 a.camera_rays;
  Stats.test a Stats.torus;
  Stats.test b Stats.torus;
  Stats.hit b Stats.torus;
  Stats.test b Stats.roots;
  let m = Stats.merge a b in
  Alcotest.(check (pair int int)) "a counter's tests and hits added" (2, 1) (Stats.tests m Stats.torus, Stats.hits m Stats.torus);
  Alcotest.(check int) "the solvers' counter added" 1 (Stats.tests m Stats.roots);
  Alcotest.(check int) "a counter of a's unchanged" 1 (Stats.tests a Stats.torus)

(* every line of the table has a counter of its own, which the solvers' counters are not *)
let test_stats_table () =
  let counted s = List.filter_map (fun (r : Stats.row) -> if r.tests <> 0 || r.hits <> 0 then Some (r.name, r.tests, r.hits) else None) (Stats.rows s) in
  List.iter
    (fun (name, k) ->
      let s = Stats.create () in
      Stats.test s k;
      Stats.test s k;
      Stats.hit s k;
      Alcotest.(check (list (triple string int int))) name [ (name, 2, 1) ] (counted s))
    Stats.table;
  List.iter
    (fun k ->
      let s = Stats.create () in
      Stats.test s k;
      Stats.hit s k;
      Alcotest.(check (list (triple string int int))) "a solver's counter is no line" [] (counted s))
    [ Stats.roots; Stats.isosurface_roots; Stats.parametric_cut ];
  let names = List.map fst Stats.table in
  Alcotest.(check int) "names differ" (List.length names) (List.length (List.sort_uniq compare names));
  Alcotest.(check (list string)) "POV-Ray's first and last lines" [ "Blob"; "Bounding Object" ] [ List.hd names; List.nth names (List.length names - 1) ]

(* ---- Error, Loc ---- *)

let test_error_render () =
  let e = { Error.loc = { Loc.file = "t.pov"; line = 2; col = 3 }; msg = "bad thing"; notes = []; kind = Scene } in
  let source = function "t.pov" -> Some "first line\nab cd\n" | _ -> None in
  Alcotest.(check string) "rendered" "t.pov:2:3: error: bad thing\n    2 | ab cd\n      |   ^\n" (Error.render ~source ~kind:"error" e);
  (* no source: just the head; a note with a location *)
  let e = { e with notes = [ ({ Loc.file = "u.pov"; line = 1; col = 1 }, "see here") ] } in
  Alcotest.(check string) "with a note" "t.pov:2:3: warning: bad thing\nu.pov:1:1: note: see here\n"
    (Error.render ~source:(fun _ -> None) ~kind:"warning" e);
  (* no location *)
  Alcotest.(check string) "located nowhere" "error: oops\n"
    (Error.render ~source ~kind:"error" { Error.loc = Loc.none; msg = "oops"; notes = []; kind = Scene });
  Alcotest.(check string) "Loc.to_string" "a.pov:3:14" (Loc.to_string { Loc.file = "a.pov"; line = 3; col = 14 });
  (* raise_at formats its message *)
  match Error.raise_at { Loc.file = "x"; line = 1; col = 2 } "n = %d" 42 with
  | () -> Alcotest.fail "raise_at returned"
  | exception Error.Scene_error e -> Alcotest.(check string) "raise_at" "n = 42" e.msg

(* ---- Image, Output ---- *)

let test_image () =
  let img = Image.create 3 2 in
  Alcotest.(check (triple (float 0.) (float 0.) (float 0.))) "black" (0., 0., 0.) (Image.get img 2 1);
  Image.set img 2 1 0.1 0.2 0.3;
  (* single precision: what Encode reads anyway *)
  let f32 = Precision.f32 in
  Alcotest.(check (triple (float 0.) (float 0.) (float 0.))) "set/get" (f32 0.1, f32 0.2, f32 0.3) (Image.get img 2 1);
  Alcotest.(check bool) "rounded to single precision" true (let r, _, _ = Image.get img 2 1 in r <> 0.1);
  (* row-major from the top: (2,1) is pixel 5, floats 15..17 *)
  Alcotest.(check (float 0.)) "layout" (f32 0.2) (Image.channel img 16);
  Alcotest.(check int) "channels" 18 (Image.channels img)

let test_output () =
  let e = { Encode.width = 2; height = 1; pixels = Bytes.of_string "\001\002\003\250\251\252" } in
  let ppm = Filename.temp_file "povml-unit" ".ppm" in
  (match Output.write Output.Ppm ppm e with Ok () -> () | Error m -> Alcotest.failf "write ppm: %s" m);
  let ic = open_in_bin ppm in
  let s = really_input_string ic (in_channel_length ic) in
  close_in ic;
  Sys.remove ppm;
  Alcotest.(check string) "ppm bytes" "P6\n2 1\n255\n\001\002\003\250\251\252" s;
  let png = Filename.temp_file "povml-unit" ".png" in
  (match Output.write Output.Png png e with Ok () -> () | Error m -> Alcotest.failf "write png: %s" m);
  let back = Output.read_png png in
  Sys.remove png;
  match back with
  | Ok b ->
      Alcotest.(check (pair int int)) "png size" (2, 1) (b.width, b.height);
      Alcotest.(check string) "png round trip" (Bytes.to_string e.pixels) (Bytes.to_string b.pixels)
  | Error m -> Alcotest.failf "read png: %s" m

let tests_suggest = [ Alcotest.test_case "nearest" `Quick test_suggest ]
let tests_value = [ Alcotest.test_case "promote and arith" `Quick test_value ]
let tests_colour = [ Alcotest.test_case "colour and rgb" `Quick test_colour ]
let tests_defaults = [ Alcotest.test_case "defaults" `Quick test_defaults ]
let tests_stats = [ Alcotest.test_case "merge" `Quick test_stats; Alcotest.test_case "the table's lines" `Quick test_stats_table ]
let tests_error = [ Alcotest.test_case "render" `Quick test_error_render ]
let tests_image = [ Alcotest.test_case "create/get/set" `Quick test_image ]
let tests_output = [ Alcotest.test_case "ppm and png" `Quick test_output ]

(* ---- Pipeline ---- *)

let test_pipeline () =
  let path = Filename.temp_file "povml-unit" ".pov" in
  let oc = open_out_bin path in
  (* a legacy scene (gamma off): the background <0.2,0.4,0.6> encodes as floor(v·255 + 0.5) =
     51, 102, 153; the sphere in the middle of a 3×1 image has ambient 1 on rgb <1,0.5,0>: 255, 128, 0 *)
  output_string oc "background { rgb <0.2,0.4,0.6> }\nsphere { <0,0,5>, 1 pigment { rgb <1,0.5,0> } finish { ambient 1 diffuse 0 } }\n";
  close_out oc;
  let opts = render_opts 3 1 in
  let r = Pipeline.run opts path in
  Sys.remove path;
  Alcotest.(check bool) "gamma off" true (r.scene.gamma = Scene.Gamma_off);
  Alcotest.(check (list int)) "bytes"
    [ 51; 102; 153; 255; 128; 0; 51; 102; 153 ]
    (List.init 9 (fun i -> Char.code (Bytes.get r.image.pixels i)));
  Alcotest.(check int) "camera rays" 3 r.stats.camera_rays

let tests_pipeline = [ Alcotest.test_case "run" `Quick test_pipeline ]
