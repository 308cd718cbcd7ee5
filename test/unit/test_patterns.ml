(* Pigment patterns (docs/povray-rules.md §17, §18.1, §14.7): each pattern at its boundaries, the value wrap
   and waves, the map lookup rules, parsing (maps, defaults, errors), transforms before and after
   an object's, and evaluation at hit points, shadow crossings and sky directions. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let pattern_of (o : Scene.obj) =
  match (layer_of o).pigment with Pattern p -> p | Solid _ | Solid_placed _ -> Alcotest.fail "expected a pattern pigment"

let the_pattern text = pattern_of (the_object (scene (v37 ^ text)))

let rgb r g b = colour5 r g b 0. 0.
let entry v c = Pigment.f32_entry v c

(* ---------------------------------------------------------------------------------------------- *)
(* checker (§17.4) *)

let test_checker () =
  let c x y z = Pigment.checker (v x y z) in
  float_eq "the unit cube [0,1)³ is 0" 0. (c 0.5 0.5 0.5);
  float_eq "one step in x" 1. (c 1.5 0.5 0.5);
  float_eq "two steps" 0. (c 1.5 1.5 0.5);
  float_eq "negative cell" 1. (c (-0.5) 0.5 0.5);
  float_eq "three negative steps" 1. (c (-0.5) (-0.5) (-0.5));
  (* a boundary belongs to the cell above, and so does a point less than 1e-10 below it *)
  float_eq "x = 1 exactly" 1. (c 1. 0.5 0.5);
  float_eq "x = 1 − 5e-11" 1. (c (1. -. 5e-11) 0.5 0.5);
  float_eq "x = 1 − 2e-10" 0. (c (1. -. 2e-10) 0.5 0.5);
  float_eq "x = 0 − 5e-11" 0. (c (-5e-11) 0.5 0.5);
  float_eq "corner <1,1,1>" 1. (c 1. 1. 1.);
  float_eq "corner <0,0,0>" 0. (c 0. 0. 0.)

(* ---------------------------------------------------------------------------------------------- *)
(* gradient (§17.5) and the wrap of §17.1 *)

let gradient_value x = Pigment.shape_value ~frequency:1. ~phase:0. Ramp (Pigment.gradient (v 1. 0. 0.) (v x 0. 0.))

let test_gradient () =
  float_eq "0.25" 0.25 (gradient_value 0.25);
  (* r ≤ 1 passes the pattern; fmod(1, 1.00001) = 1: exactly 1 is the top of the map *)
  float_eq "exactly 1" 1. (gradient_value 1.);
  (* r > 1: fmod(r, 1) first, so 2 gives 0 *)
  float_eq "exactly 2" 0. (gradient_value 2.);
  float_eq "2.5" 0.5 (gradient_value 2.5);
  (* −1: fmod(−1, 1.00001) = −1, then −1 − floor(−1) = 0 *)
  float_eq "exactly −1" 0. (gradient_value (-1.));
  float_eq "−0.25" 0.75 (gradient_value (-0.25));
  (* the direction is normalised when parsed: gradient <2,0,1> is <2,0,1>/√5 *)
  let p = the_pattern "plane { y, 0 pigment { gradient <2,0,1> } }" in
  (match p.pattern with
  | Gradient g -> vec_eq "normalised" (v (2. /. sqrt 5.) 0. (1. /. sqrt 5.)) g
  | _ -> Alcotest.fail "gradient expected");
  float_eq "gradient default frequency" 1. p.frequency;
  Alcotest.(check int) "default map: two entries" 2 (Array.length p.map);
  colour_eq "default map: black" Colour.black p.map.(0).colour;
  colour_eq "default map: white" (rgb 1. 1. 1.) p.map.(1).colour

let test_wrap_and_waves () =
  let sv ?(f = 1.) ?(ph = 0.) w x = Pigment.shape_value ~frequency:f ~phase:ph w x in
  (* the modulus is 1.00001: 1.000005 stays *)
  float_eq "1.000005 is not wrapped" 1.000005 (sv Ramp 1.000005);
  float_eq ~eps:1e-12 "1.00002 wraps by 1.00001" (1.00002 -. 1.00001) (sv Ramp 1.00002);
  (* frequency 2, phase 0.1 at 0.5: fmod(1.1, 1.00001) = 0.09999 *)
  float_eq ~eps:1e-12 "frequency 2 phase 0.1" (1.1 -. 1.00001) (sv ~f:2. ~ph:0.1 Ramp 0.5);
  (* frequency 0 (checker, hexagon, brick): no wrap, phase ignored *)
  float_eq "frequency 0 keeps 2" 2. (sv ~f:0. ~ph:0.3 Ramp 2.);
  float_eq "triangle rising" 0.5 (sv Triangle_wave 0.25);
  float_eq "triangle falling" 0.5 (sv Triangle_wave 0.75);
  float_eq "triangle peak" 1. (sv Triangle_wave 0.5);
  float_eq "sine at 0.25" 1. (sv Sine_wave 0.25);
  float_eq "sine at 0.75" 0. (sv Sine_wave 0.75);
  float_eq "scallop at 0.25: |sin(π/4)|" (sin (Float.pi /. 4.)) (sv Scallop_wave 0.25);
  float_eq "cubic at 0.5" 0.5 (sv Cubic_wave 0.5);
  float_eq "cubic at 0.25: 0.0625·2.5" 0.15625 (sv Cubic_wave 0.25);
  float_eq "poly 2 at 0.5" 0.25 (sv (Poly_wave 2.) 0.5)

(* ---------------------------------------------------------------------------------------------- *)
(* hexagon (§17.6) *)

let test_hexagon () =
  let h x z = Pigment.hexagon (v x 0. z) in
  (* the cell around the origin is 0; the centres of the neighbours in x (at x = ±1.5, z = ±√3/2)
     and in z (at z = ±√3) are 1 and 2 *)
  float_eq "origin" 0. (h 0. 0.);
  float_eq "near the origin" 0. (h 0.2 0.1);
  float_eq "y is ignored" 0. (Pigment.hexagon (v 0.2 7. 0.1));
  float_eq "neighbour up in z" 1. (h 0. 1.732);
  float_eq "neighbour at x 1.5, z 0.866" 2. (h 1.5 0.866);
  float_eq "mirror in x" 2. (h (-1.5) 0.866);
  float_eq "neighbour down in z" 2. (h 0. (-1.732));
  float_eq "neighbour at x 1.5, z −0.866" 1. (h 1.5 (-0.866));
  (* x in [0.5, 1), the column where the cells meet on slanted edges: z/x decides; each point
     takes the value of the nearest cell centre *)
  float_eq "slanted column, nearest the origin" 0. (h 0.6 0.5);
  float_eq "slanted column, nearest <1.5,0.866>" 2. (h 0.6 0.8);
  float_eq "slanted column, nearest <0,1.732>" 1. (h 0.6 1.3)

(* ---------------------------------------------------------------------------------------------- *)
(* brick (§17.7) *)

let test_brick () =
  let size = v 8. 3. 4.5 and m = 0.5 -. 2e-10 in
  let b x y z = Pigment.brick size m (v x y z) in
  (* z = 1 keeps clear of the depth joints: even courses have them just below z = 2.25, odd ones
     just below 4.5 *)
  float_eq "inside a brick" 1. (b 2. 1. 1.);
  (* the horizontal joint lies just below y = 3: [3 − 0.5, 3) *)
  float_eq "horizontal joint below 3" 0. (b 2. 2.8 1.);
  float_eq "just above 3" 1. (b 2. 3.1 1.);
  float_eq "y = 2.5 + 0.05: in the joint" 0. (b 2. 2.55 1.);
  float_eq "y = 2.45: brick" 1. (b 2. 2.45 1.);
  (* even course: vertical joints just below x = 8, 16 …; odd course: shifted by 4 *)
  float_eq "even course, joint below x = 8" 0. (b 7.8 1. 1.);
  float_eq "even course, x = 8.1" 1. (b 8.1 1. 1.);
  float_eq "odd course, no joint below x = 8" 1. (b 7.8 4. 1.);
  float_eq "odd course, joint below x = 4" 0. (b 3.8 4. 1.);
  (* depth joints: below z = 4.5 on odd courses, below z = 2.25 on even ones *)
  float_eq "odd course, joint below z = 4.5" 0. (b 2. 4. 4.3);
  float_eq "even course, joint below z = 2.25" 0. (b 2. 1. 2.1);
  float_eq "negative coordinates, brick" 1. (b (-2.) (-1.) (-1.));
  float_eq "negative x, joint below 0" 0. (b (-0.2) 1. 1.);
  let p = the_pattern "box { 0, 1 pigment { brick rgb 1 brick_size <1.6,0.6,1> mortar 0.1 } }" in
  (match p.pattern with
  | Brick { size; mortar } ->
      vec_eq "brick_size" (v 1.6 0.6 1.) size;
      float_eq ~eps:0. "mortar stored less 2e-10, in single precision" (Int32.float_of_bits (Int32.bits_of_float (0.1 -. 2e-10))) mortar
  | _ -> Alcotest.fail "brick expected");
  colour_eq "mortar colour given" (rgb 1. 1. 1.) p.map.(0).colour;
  colour_eq ~eps:1e-7 "default brick colour" (rgb 0.6 0.15 0.15) p.map.(1).colour;
  float_eq "brick frequency 0" 0. p.frequency

(* ---------------------------------------------------------------------------------------------- *)
(* Map lookup (§17.2) *)

let red = rgb 1. 0. 0. and blue = rgb 0. 0. 1. and green = rgb 0. 1. 0.

let test_lookup () =
  let m = [| entry 0.25 red; entry 0.75 blue |] in
  colour_eq ~eps:0. "below the first: first" red (Pigment.lookup m 0.1);
  colour_eq ~eps:0. "at the first" red (Pigment.lookup m 0.25);
  colour_eq ~eps:0. "at the last" blue (Pigment.lookup m 0.75);
  colour_eq ~eps:0. "above the last" blue (Pigment.lookup m 0.9);
  colour_eq ~eps:0. "halfway" (rgb 0.5 0. 0.5) (Pigment.lookup m 0.5);
  (* values are single precision: 0.6 is stored as 0.6000000238, so the double 0.6 is still just
     below the last entry and blends by (0.6 − 0.2f)/(0.6f − 0.2f) *)
  let m = [| entry 0.2 red; entry 0.6 blue |] in
  let f0 = Int32.float_of_bits (Int32.bits_of_float 0.2) and f1 = Int32.float_of_bits (Int32.bits_of_float 0.6) in
  let k = (0.6 -. f0) /. (f1 -. f0) in
  let f32 x = Int32.float_of_bits (Int32.bits_of_float x) in
  (* red: 1 + f32(k·(0 − 1)), each step in single precision *)
  float_eq ~eps:0. "0.6 below the stored 0.6: red channel" (f32 (1. +. f32 (-.k))) (Pigment.lookup m 0.6).red;
  Alcotest.(check bool) "0.6 is not exactly blue" true ((Pigment.lookup m 0.6).red > 0.);
  (* a duplicated value is a sharp step; the value itself takes the earlier entry *)
  let d = [| entry 0. red; entry 0.5 green; entry 0.5 blue; entry 1. red |] in
  colour_eq "step: at 0.5 the earlier entry" green (Pigment.lookup d 0.5);
  colour_eq ~eps:1e-6 "step: just above, the later entry blended towards red" (rgb 0.002 0. 0.998) (Pigment.lookup d 0.501);
  colour_eq ~eps:1e-6 "step: just below, green" (rgb 0.002 0.998 0.) (Pigment.lookup d 0.499);
  (* unsorted: [0.8 red][0.2 blue] is red below 0.2 and blue from 0.2 up *)
  let u = [| entry 0.8 red; entry 0.2 blue |] in
  colour_eq "unsorted: 0.1" red (Pigment.lookup u 0.1);
  colour_eq "unsorted: 0.5" blue (Pigment.lookup u 0.5);
  colour_eq "unsorted: 0.9" blue (Pigment.lookup u 0.9);
  colour_eq "single entry" green (Pigment.lookup [| entry 0.5 green |] 0.);
  (* filter and transmit blend like the colour channels *)
  let t = [| entry 0. (colour5 1. 1. 1. 0. 1.); entry 1. (colour5 0. 0. 0. 1. 0.) |] in
  colour_eq "filter and transmit blend" (colour5 0.5 0.5 0.5 0.5 0.5) (Pigment.lookup t 0.5)

(* ---------------------------------------------------------------------------------------------- *)
(* Parsing *)

let test_parse_maps () =
  let p = the_pattern "plane { y, 0 pigment { gradient x color_map { [0.3 rgb 1] [0.1, color red 1] } } }" in
  Alcotest.(check int) "two entries in the order written" 2 (Array.length p.map);
  float_eq ~eps:1e-7 "first value" 0.3 p.map.(0).value;
  Alcotest.(check bool) "values are single precision" true (p.map.(0).value = Int32.float_of_bits (Int32.bits_of_float 0.3));
  colour_eq "second colour" red p.map.(1).colour;
  (* the old form: [v1 v2 color C1 color C2] is two entries *)
  let p = the_pattern "plane { y, 0 pigment { gradient x colour_map { [0 0.5 color rgb 1 color rgb <1,0,0>] [0.5 1 color red 1 color blue 1] } } }" in
  Alcotest.(check int) "old form: four entries" 4 (Array.length p.map);
  colour_eq "old form: second" red p.map.(1).colour;
  colour_eq "old form: fourth" blue p.map.(3).colour;
  (* a declared map *)
  let p = the_pattern "#declare M = color_map { [0 rgb <0,1,0>] [1 rgb <0,0,1>] }\nplane { y, 0 pigment { gradient y color_map { M } } }" in
  colour_eq "declared map" green p.map.(0).colour;
  (* colour 0.5 in a map is rgbft 0.5 *)
  let p = the_pattern "plane { y, 0 pigment { gradient y color_map { [0 color 0.5] } } }" in
  colour_eq "color 0.5" (colour5 0.5 0.5 0.5 0.5 0.5) p.map.(0).colour;
  (* checker defaults: blue, green; one colour given keeps the default second *)
  let p = the_pattern "plane { y, 0 pigment { checker } }" in
  colour_eq "checker default 1" blue p.map.(0).colour;
  colour_eq "checker default 2" green p.map.(1).colour;
  float_eq "checker frequency 0" 0. p.frequency;
  let p = the_pattern "plane { y, 0 pigment { checker rgb <1,0,0> } }" in
  colour_eq "one colour" red p.map.(0).colour;
  colour_eq "default second" green p.map.(1).colour;
  (* a second rgb keyword starts the next colour: rgb 1 rgb <1,0,0> is two colours (checked) *)
  let p = the_pattern "plane { y, 0 pigment { checker rgb 1 rgb <1,0,0> } }" in
  colour_eq "no comma: first" (rgb 1. 1. 1.) p.map.(0).colour;
  colour_eq "no comma: second" red p.map.(1).colour;
  let p = the_pattern "plane { y, 0 pigment { hexagon rgb 1, rgb 0 } }" in
  colour_eq "hexagon default third: red" red p.map.(2).colour;
  colour_eq "hexagon second" Colour.black p.map.(1).colour

let test_parse_errors () =
  expect_scene_error "bare vector entry" "plane { y, 0 pigment { gradient x color_map { [0 <1,0,0>] } } }" ~line:1 ~col:50
    ~sub:"expected a colour";
  expect_scene_error "color_map on checker" "plane { y, 0 pigment { checker color_map { [0 rgb 1] } } }" ~line:1 ~col:32
    ~sub:"cannot use color_map with this pattern type";
  expect_scene_error "empty map" "plane { y, 0 pigment { gradient x color_map { } } }" ~line:1 ~col:45 ~sub:"at least one entry";
  expect_scene_error "mortar outside brick" "plane { y, 0 pigment { checker mortar 0.1 } }" ~line:1 ~col:32
    ~sub:"only valid in a brick pattern";
  expect_scene_error "pattern after a modifier" "plane { y, 0 pigment { scale 2 checker } }" ~line:1 ~col:32
    ~sub:"the colour or pattern comes first";
  expect_scene_error "two colours" "plane { y, 0 pigment { rgb 1 rgb 0 } }" ~line:1 ~col:30 ~sub:"the colour or pattern comes first";
  expect_scene_error "zero gradient" "plane { y, 0 pigment { gradient 0 } }" ~line:1 ~col:33 ~sub:"gradient vector"

let test_pigment_maps () =
  (* checker pigment {…}, pigment {…}: the cells take whole pigments, evaluated at the checker's
     own pattern-space point and then through each pigment's transform *)
  let o =
    the_object
      (scene (v37 ^ "plane { y, 0 pigment { checker pigment { checker rgb 1, rgb 0 scale 0.5 }, pigment { rgb <1,0,0> } scale 2 } }"))
  in
  (* world <0.5,0.5,0.5> is <0.25,0.25,0.25> for the outer checker (cell 0), <0.5,0.5,0.5> for the
     inner one (cell 0); world z = 1.5 is inner z = 1.5 (cell 1). An inner point computed from the
     world point instead (z = 3) would give cell 0. *)
  colour_eq "outer 0, inner 0" (rgb 1. 1. 1.) (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 0.5 0.5 0.5));
  colour_eq "outer 0, inner 1" Colour.black (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 0.5 0.5 1.5));
  colour_eq "outer 1" red (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 2.5 0.5 0.5));
  (* one pigment given: the second cell is the default texture's pigment (POV-Ray prints 0, 0, 0
     for F(1.5, 0.5, 0.5) with F = function { pigment { checker pigment { rgb 1 } } }, and 1, 0, 0
     after #default { pigment { rgb <1,0,0> } }) *)
  let o = the_object (scene (v37 ^ "plane { y, 0 pigment { checker pigment { rgb 1 } } }")) in
  colour_eq "default second pigment" Colour.black (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 1.5 0.5 0.5));
  let o = the_object (scene (v37 ^ "#default { pigment { rgb <1,0,0> } } plane { y, 0 pigment { checker pigment { rgb 1 } } }")) in
  colour_eq "the default texture's pigment" red (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 1.5 0.5 0.5));
  (* pigment_map: blended like a colour map, all five channels *)
  let o =
    the_object (scene (v37 ^ "plane { y, 0 pigment { gradient x pigment_map { [0.25 rgb <1,0,0>] [0.75 rgbt <0,0,1,1>] } } }"))
  in
  colour_eq ~eps:0. "pigment_map halfway" (colour5 0.5 0. 0.5 0. 0.5) (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 0.5 0. 0.));
  colour_eq ~eps:0. "pigment_map below the first" red (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 0.1 0. 0.));
  Alcotest.(check bool) "a transparent entry pigment: not opaque" false (Pigment.opaque (layer_of o).pigment);
  (* a declared pigment_map *)
  let o =
    the_object
      (scene (v37 ^ "#declare PM = pigment_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] }\nplane { y, 0 pigment { gradient x pigment_map { PM } } }"))
  in
  colour_eq ~eps:0. "declared pigment_map" (rgb 0.5 0. 0.5) (Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit (v 0.5 0. 0.));
  expect_scene_error "pigment_map on checker" "plane { y, 0 pigment { checker pigment_map { [0 rgb 1] } } }" ~line:1 ~col:32
    ~sub:"cannot use pigment_map with this pattern type"

(* ---------------------------------------------------------------------------------------------- *)
(* Transforms (§14.7, §17.1, §17.9) *)

let eval_at (o : Scene.obj) p = Pigment.colour_at 2 (layer_of o).pigment Patterns.no_hit p

let test_transforms () =
  (* the pattern is evaluated at the inverse of its transform: scale 2 doubles the cells *)
  let o = the_object (scene (v37 ^ "plane { y, 0 pigment { checker rgb 1, rgb 0 scale 2 } }")) in
  colour_eq "scaled: x 1.5 still in the first cell" (rgb 1. 1. 1.) (eval_at o (v 1.5 0.5 0.5));
  colour_eq "scaled: x 2.5 in the second" Colour.black (eval_at o (v 2.5 0.5 0.5));
  (* attached before the object's scale: the pattern is scaled; after it: not *)
  let before = the_object (scene (v37 ^ "sphere { 0, 1 pigment { checker rgb 1, rgb 0 } scale 2 }")) in
  let after = the_object (scene (v37 ^ "sphere { 0, 1 scale 2 pigment { checker rgb 1, rgb 0 } }")) in
  colour_eq "before: moves with the object" (rgb 1. 1. 1.) (eval_at before (v 1.5 0.5 0.5));
  colour_eq "after: stays in world space" Colour.black (eval_at after (v 1.5 0.5 0.5));
  (* translate in a texture block moves its pigment *)
  let o = the_object (scene (v37 ^ "sphere { 0, 1 texture { pigment { checker rgb 1, rgb 0 } translate x } }")) in
  colour_eq "texture translate" Colour.black (eval_at o (v 0.5 0.5 0.5));
  (* a union's texture is in the union's frame; a member's private scale does not touch it *)
  let s = scene (v37 ^ "union { sphere { 0, 1 scale 3 } sphere { 5*x, 1 } pigment { checker rgb 1, rgb 0 } translate y }") in
  let first = List.hd s.objects in
  colour_eq "union frame: translate y only" Colour.black (eval_at first (v 0.5 0.5 0.5));
  colour_eq "union frame: not the member's scale" (rgb 1. 1. 1.) (eval_at first (v 1.5 0.5 0.5));
  (* editing a copy's pigment keeps the old pigment's transform, object transforms included *)
  let o =
    the_object
      (scene (v37 ^ "#declare S = sphere { 0, 1 pigment { checker rgb 1, rgb 0 scale 0.5 } scale 2 }\nobject { S pigment { checker rgb <0,0,1>, rgb <0,1,0> } }"))
  in
  colour_eq "copy keeps scale 0.5·2" blue (eval_at o (v 0.5 0.5 0.5));
  colour_eq "copy: next cell at 1" green (eval_at o (v 1.5 0.5 0.5));
  (* a plain colour keeps the transforms it received, for an edit that gives it a pattern *)
  let o = the_object (scene (v37 ^ "sphere { 0, 1 finish { phong 1 } scale 2 pigment { checker rgb 1, rgb 0 } }")) in
  colour_eq "plain, scaled, then checker: scaled" (rgb 1. 1. 1.) (eval_at o (v 1.5 0.5 0.5));
  let o = the_object (scene (v37 ^ "sphere { 0, 1 pigment { rgb <1,0,0> } translate x }")) in
  (match (layer_of o).pigment with
  | Solid_placed { colour; strans } ->
      colour_eq "placed colour" red colour;
      vec_eq "placed transform" (v 1. 0. 0.) (Transform.point strans Vec.zero)
  | Solid _ | Pattern _ -> Alcotest.fail "a placed plain colour expected");
  (* a mesh's face textures move with the mesh *)
  let s =
    scene
      (v37
     ^ "#declare T = texture { pigment { checker rgb 1, rgb 0 } }\nmesh { triangle { 0, x, y texture { T } } translate x }")
  in
  match (the_object s).shape with
  | Mesh { textures; _ } -> colour_eq "mesh face texture moved" Colour.black (Pigment.colour_at 2 (match textures.(0) with Layers (l :: _) -> l.pigment | _ -> Alcotest.fail "not plain") Patterns.no_hit (v 0.5 0.5 0.5))
  | _ -> Alcotest.fail "a mesh expected"

(* ---------------------------------------------------------------------------------------------- *)
(* Compiled surfaces and tracing *)

let test_compile () =
  let c = compile (v37 ^ "plane { y, 0 pigment { rgb 1 } }") in
  Alcotest.(check bool) "a plain colour is Fixed" true ((surf_of c.objects.(0)).paint = Fixed);
  let c = compile (v37 ^ "plane { y, 0 pigment { checker rgb 1, rgb 0 } }") in
  (match (surf_of c.objects.(0)).paint with
  | Fixed -> Alcotest.fail "a pattern is Varying"
  | Varying at -> rgb_eq "surface at a point" Rgb.black (at Patterns.no_hit (v 1.5 0. 0.5)).colour);
  Alcotest.(check bool) "opaque map: opaque object" true c.objects.(0).opaque;
  Alcotest.(check bool) "opaque map: any-hit shadows" true (c.shadow_mode = Any_hit);
  let c = compile (v37 ^ "plane { y, 0 pigment { checker rgb 1, rgbt <1,1,1,0.5> } }") in
  Alcotest.(check bool) "a transparent entry: not opaque" false c.objects.(0).opaque;
  Alcotest.(check bool) "filtered shadows" true (c.shadow_mode = Filtered)

let test_trace () =
  (* a plane z = 5 facing the camera, ambient 1 diffuse 0: the colour is the pigment *)
  let text p = v37 ^ Printf.sprintf "plane { -z, -5 pigment { %s } finish { ambient 1 diffuse 0 } }" p in
  let chk = text "checker rgb 1, rgb <1,0,0>" in
  (* the hit points are at z = 5, an odd cell in z *)
  result_eq "checker at <0.5,0.5,5>: odd" (1., 0., 0.) (trace_text chk (v 0.5 0.5 0.) (v 0. 0. 1.));
  result_eq "checker at <1.5,0.5,5>: even" (1., 1., 1.) (trace_text chk (v 1.5 0.5 0.) (v 0. 0. 1.));
  let gr = text "gradient x color_map { [0 rgb 0] [1 rgb <0,0,1>] }" in
  result_eq "gradient 0.25" (0., 0., 0.25) (trace_text gr (v 0.25 0. 0.) (v 0. 0. 1.));
  (* shadows through a patterned, partly transparent plane: the light at y = 10 reaches the
     floor through the plane y = 5 where it is rgbt <1,1,1,1> (x in [1,2): 1 + 5 + 0 is even) and
     not where it is opaque (x in [0,1)) *)
  let sh cell =
    v37
    ^ "light_source { <" ^ cell ^ ",10,0.5> rgb 1 }\n\
       plane { y, 5 pigment { checker rgbt <1,1,1,1>, rgb 0 } finish { ambient 0 diffuse 0 } }\n\
       plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
  in
  result_eq "light through the clear cell" (1., 1., 1.) (trace_text (sh "1.5") (v 1.5 1. 0.5) (v 0. (-1.) 0.));
  result_eq "shadow of the opaque cell" (0., 0., 0.) (trace_text (sh "0.5") (v 0.5 1. 0.5) (v 0. (-1.) 0.));
  (* sky: gradient y at the direction as a point; straight up is r = 1: the last colour *)
  let sky t = v37 ^ "background { rgb 0 }\nsky_sphere { pigment { gradient y color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } " ^ t ^ " }" in
  result_eq "sky up" (0., 0., 1.) (trace_text (sky "") Vec.zero (v 0. 1. 0.));
  result_eq "sky horizon" (1., 0., 0.) (trace_text (sky "") Vec.zero (v 0. 0. 1.));
  (* below the horizon y = −0.5 wraps to 0.5 *)
  result_eq ~eps:1e-6 "sky below the horizon wraps" (0.5, 0., 0.5) (trace_text (sky "") Vec.zero (v 0. (-0.5) (sqrt 0.75)));
  (* a sky translate shifts the lookup point: at the horizon y = 0 − 0.25 → 0.75 *)
  result_eq ~eps:1e-6 "sky translate" (0.25, 0., 0.75) (trace_text (sky "translate 0.25*y") Vec.zero (v 0. 0. 1.))

let tests =
  [
    Alcotest.test_case "checker" `Quick test_checker;
    Alcotest.test_case "gradient" `Quick test_gradient;
    Alcotest.test_case "wrap and waves" `Quick test_wrap_and_waves;
    Alcotest.test_case "hexagon" `Quick test_hexagon;
    Alcotest.test_case "brick" `Quick test_brick;
    Alcotest.test_case "map lookup" `Quick test_lookup;
    Alcotest.test_case "parsing maps" `Quick test_parse_maps;
    Alcotest.test_case "parse errors" `Quick test_parse_errors;
    Alcotest.test_case "pigment maps" `Quick test_pigment_maps;
    Alcotest.test_case "transforms" `Quick test_transforms;
    Alcotest.test_case "compile" `Quick test_compile;
    Alcotest.test_case "trace" `Quick test_trace;
  ]
