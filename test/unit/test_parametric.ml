(* The parametric surface, parametric { … } (POV-Ray's fpmetric.cpp and Parse_Parametric): its
   reader's defaults, quirks and errors; the search against POV-Ray's own trace() (the numbers
   printed by test/unit/data/parametric_trace.pov); the precomputed table; the box it is bounded
   by; its statistics. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let param_of (o : Scene.obj) =
  match o.shape with
  | Parametric s -> s
  | _ -> Alcotest.fail "expected a parametric surface"

let parse text = param_of (the_object (scene (v37 ^ text)))

let torus_fns = "function { cos(u)*(1 + 0.35*cos(v)) }, function { 0.35*sin(v) }, function { sin(u)*(1 + 0.35*cos(v)) }"
let torus = "parametric { " ^ torus_fns ^ " <0, 0>, <2*pi, 2*pi> contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } } }"

let ball =
  "parametric { function { cos(u)*sin(v)*0.8 }, function { cos(v)*0.8 }, function { sin(u)*sin(v)*0.8 } <0, 0>, <2*pi, pi> \
   contained_by { sphere { 0, 0.85 } } accuracy 0.004 }"

let moved =
  "parametric { " ^ torus_fns
  ^ " <0, 0>, <2*pi, 2*pi> contained_by { sphere { 0, 1.4 } } accuracy 0.002 max_gradient 1.5 \
     rotate <50, 0, 20> scale <0.8, 1.2, 0.7> translate <-0.9, 0.3, 0> }"

let wave pre =
  "parametric { function { u } function { 0.12*sin(10*u)*sin(8*v) } function { v } <-1, -1>, <1, 1> \
   contained_by { box { <-1, -0.3, -1>, <1, 0.3, 1> } } accuracy 0.003 max_gradient 0.05 " ^ pre ^ " }"

let test_defaults () =
  let s = parse "parametric { function { u }, function { v }, function { 0 } <0, 0>, <1, 1> }" in
  float_eq ~eps:0. "accuracy" 0.001 s.accuracy;
  float_eq ~eps:0. "max_gradient" 1. s.max_gradient;
  (match s.container with
  | Box_container b -> vec_eq ~eps:0. "default box" (v (-1.) (-1.) (-1.)) (v b.x0 b.y0 b.z0); vec_eq ~eps:0. "default box" (v 1. 1. 1.) (v b.x1 b.y1 b.z1)
  | Sphere_container _ -> Alcotest.fail "a box by default");
  Alcotest.(check bool) "no precompute" true (s.precomputed = None);
  Alcotest.(check bool) "identity transform" true (Transform.is_identity s.trans)

let test_items () =
  (* the corners sorted; a sphere container; the items in any order, the last one winning *)
  let s = parse "parametric { function { u } function { v } function { 0 } <2, 5>, <1, -1> accuracy 0.01 contained_by { sphere { <1, 2, 3>, 4 } } max_gradient 3 accuracy 0.02 }" in
  float_eq ~eps:0. "umin" 1. s.umin;
  float_eq ~eps:0. "umax" 2. s.umax;
  float_eq ~eps:0. "vmin" (-1.) s.vmin;
  float_eq ~eps:0. "vmax" 5. s.vmax;
  float_eq ~eps:0. "accuracy" 0.02 s.accuracy;
  float_eq ~eps:0. "max_gradient" 3. s.max_gradient;
  (match s.container with
  | Sphere_container { centre; radius } -> vec_eq ~eps:0. "centre" (v 1. 2. 3.) centre; float_eq ~eps:0. "radius" 4. radius
  | Box_container _ -> Alcotest.fail "a sphere container");
  (* a box container's corners sorted per axis; an empty contained_by keeps the container *)
  let s = parse "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> contained_by { box { <1, -2, 3>, <-1, 2, -3> } } contained_by { } }" in
  match s.container with
  | Box_container b -> vec_eq ~eps:0. "low" (v (-1.) (-2.) (-3.)) (v b.x0 b.y0 b.z0); vec_eq ~eps:0. "high" (v 1. 2. 3.) (v b.x1 b.y1 b.z1)
  | Sphere_container _ -> Alcotest.fail "a box container"

(* Parse_FunctionContent starts after the token POV-Ray's EXPECT took: '9 u' is u *)
let test_bare_functions () =
  let s = parse "parametric { 9 u*2, 9 v, function { u*v } <0, 0>, <1, 1> }" in
  float_eq ~eps:0. "x" 0.8 (Fn.at_point s.fx 0.4 0.7 0.);
  float_eq ~eps:0. "y" 0.7 (Fn.at_point s.fy 0.4 0.7 0.);
  float_eq ~eps:1e-15 "z" 0.28 (Fn.at_point s.fz 0.4 0.7 0.)

let test_precompute_items () =
  let axes (s : Parametric.t) = match s.precomputed with Some p -> List.map (fun l -> Array.length l > 0) (Array.to_list p.low) | None -> [] in
  let s = parse "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 5.9, y, z }" in
  Alcotest.(check (list bool)) "y and z" [ false; true; true ] (axes s);
  (match s.precomputed with Some p -> Alcotest.(check int) "depth truncated" 5 p.levels; Alcotest.(check int) "pieces" 32 (Array.length p.low.(1)) | None -> Alcotest.fail "precomputed");
  let s = parse "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 3 x precompute 4 z }" in
  Alcotest.(check (list bool)) "flags accumulate" [ true; false; true ] (axes s);
  (* no axis chosen: nothing precomputed, and no check of the depth *)
  let s = parse "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 0 }" in
  Alcotest.(check bool) "nothing chosen" true (s.precomputed = None)

(* a precomputed piece's bounds are its halves' bounds joined; the last level's are evaluated *)
let test_precompute_table () =
  let s = parse "parametric { function { u*u } function { v } function { u+v } <0, 0>, <2, 1> precompute 3 x, z }" in
  match s.precomputed with
  | None -> Alcotest.fail "precomputed"
  | Some p ->
      let lo = p.low.(0) and hi = p.high.(0) in
      for k = 1 to 3 do
        float_eq ~eps:0. (Printf.sprintf "piece %d low" k) (Float.min lo.(2 * k) lo.((2 * k) + 1)) lo.(k);
        float_eq ~eps:0. (Printf.sprintf "piece %d high" k) (Float.max hi.(2 * k) hi.((2 * k) + 1)) hi.(k)
      done;
      (* piece 2 is u in [0, 1] (u, the longer side, halved first), piece 4 its half u in
         [0, 0.5] (a tie halves u), v in [0, 1]: x = u² less the accuracy is -a, -a, 0.25 - a,
         0.25 - a at the corners; each edge in v spreads by (1 - 0) / 2, the join in u by
         (0.5 - 0.25) / 2 *)
      let a = 0.001 in
      float_eq ~eps:0. "piece 4 high" (0.25 -. a +. 0.5 +. 0.125) hi.(4);
      float_eq ~eps:0. "piece 4 low" (0. -. a -. 0.5 -. 0.125) lo.(4);
      Alcotest.(check int) "y not chosen" 0 (Array.length p.low.(1))

let test_errors () =
  expect_scene_error "depth 0" (v37 ^ "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1>\n precompute 0 x }") ~line:4 ~col:13
    ~sub:"Precompute: invalid depth";
  expect_scene_error "depth 21" (v37 ^ "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 21, z }") ~line:3 ~col:85
    ~sub:"Precompute: invalid depth";
  expect_scene_error "accuracy 0" (v37 ^ "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> accuracy 0 }") ~line:3 ~col:83
    ~sub:"accuracy must be positive";
  expect_scene_error "other container" (v37 ^ "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> contained_by { cylinder { 0, y, 1 } } }")
    ~line:3 ~col:89 ~sub:"cylinder";
  expect_scene_error "item after a modifier" (v37 ^ "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> translate x accuracy 0.1 }")
    ~line:3 ~col:86 ~sub:"accuracy"

(* POV-Ray's trace(): the point and the normal (parametric_trace.pov), or a miss (None) *)
let trace_cases =
  let some (px, py, pz) (nx, ny, nz) = Some (v px py pz, v nx ny nz) in
  [
    ("torus, along z", torus, v 0.2 0. (-3.), v 0. 0. 1.,
     some (0.20000000000000001, 0.00000000000000000, -1.33677264606190405) (-0.14874201618242483, -0.00126698989588915, 0.98887522335155653));
    ("torus, from above", torus, v 0.2 3. (-0.9), v 0. (-1.) 0.,
     some (0.20000000000000001, 0.34093617982270663, -0.90000000000000002) (0.04887344109995464, -0.97474316599415445, -0.21791545861352193));
    ("torus, a slanted miss", torus, v (-3.) 2. (-1.), v 1. (-0.7) 0.35, None);
    ("torus, from inside the box", torus, v 0. 0. 0., v 1. 0.1 0.,
     some (0.65329414726823865, 0.06532941472682387, 0.00000000000000000) (0.98147499265482563, -0.19158966039397712, 0.00049073753726891));
    ("torus, through the hole", torus, v 0.2 3. (-0.9), v 0. (-1.) 0.1, None);
    ("sphere container", ball, v 0.1 0.2 (-3.), v 0. 0. 1.,
     some (0.10000000000000001, 0.20000000000000001, -0.77407766687721447) (0.12918082443902734, 0.25293072472037065, -0.95882134054769630));
    (* from inside the sphere the search starts behind the ray: the crossing it keeps is there *)
    ("sphere container, from inside", ball, v 0. 0. 0., v 0.3 0.5 (-1.), None);
    ("sphere container, diagonal", ball, v 2. 2. 2., v (-1.) (-1.) (-1.1),
     some (0.50579610705177558, 0.50579610705177558, 0.35637571775695287) (0.63214525299551705, 0.63284523671090309, 0.44710097907246282));
    ("moved, along z", moved, v (-0.3) 0.3 (-4.), v 0. 0. 1.,
     some (-0.29999999999999999, 0.29999999999999999, -0.05339960818980893) (0.64426351862589992, 0.35343637323198790, 0.67823834206301981));
    ("moved, from above", moved, v (-1.5) 3. 0., v 0. (-1.) 0.02,
     some (-1.50000000000000000, 0.28247389520457444, 0.05435052209590852) (-0.65523305253336128, -0.36533222251168768, -0.66121253320130291));
    ("moved, along x", moved, v (-3.) 0.3 0.1, v 1. 0.05 0.,
     some (-0.41512642088378238, 0.42924367895581084, 0.10000000000000001) (0.99466565883301949, 0.04053403324051830, 0.09485367303131716));
    ("precomputed, from above", wave "precompute 16 y, z", v 0.31 2. (-0.47), v 0. (-1.) 0.05,
     some (0.31000000000000000, 0.00472656250000081, -0.37023632812500001) (0.23628954019428353, -0.97156512353506019, -0.01511502315833880));
    ("not precomputed, from above", wave "", v 0.31 2. (-0.47), v 0. (-1.) 0.05,
     some (0.31000000000000000, 0.00472656250000081, -0.37023632812500001) (0.23628954019428353, -0.97156512353506019, -0.01511502315833880));
    ("precomputed, along x", wave "precompute 16 y, z", v (-3.) 1. 0.2, v 1. (-0.35) 0.,
     some (-0.47714997263397274, 0.11700249042189037, 0.20000000000000001) (0.02241942302754845, -0.99918717639227483, -0.03350158211704470));
    (* the table's joined bounds keep the piece the evaluated ones (max_gradient far too small) lose *)
    ("precomputed, slanted", wave "precompute 16 y, z", v (-0.42) 2. (-0.72), v 0.3 (-0.5) 0.45,
     some (0.72202994791666653, 0.09661675347222243, 0.99304492187499993) (0.55246275759213748, -0.82943150872148519, -0.08263336985559792));
    ("not precomputed, slanted", wave "", v (-0.42) 2. (-0.72), v 0.3 (-0.5) 0.45, None);
  ]

let test_trace () =
  List.iter
    (fun (name, text, o, d, expected) ->
      let s = parse text in
      let w = Scratch.create ~robust:false (Stats.create ()) in
      let d = Vec.normalize d in
      let t = Parametric.depth w s o d Precision.min_isect_depth in
      match expected with
      | None -> Alcotest.(check bool) (name ^ ": a miss") true (t = infinity)
      | Some (ep, en) ->
          Alcotest.(check bool) (name ^ ": a hit") true (t < infinity);
          let p = Vec.madd o t d in
          (* printed with 17 decimals: exact for the terms near 1, within 1e-17 for the small ones *)
          vec_eq ~eps:1e-17 (name ^ ": point") ep p;
          vec_eq ~eps:1e-17 (name ^ ": normal") en (Parametric.hit_normal s w.crossing))
    trace_cases

(* from inside a sphere container the crossing found is behind the ray *)
let test_behind () =
  let s = parse ball in
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let t = Parametric.depth w s Vec.zero (Vec.normalize (v 0.3 0.5 (-1.))) neg_infinity in
  Alcotest.(check bool) "behind the ray" true (t < 0. && t > -0.85)

(* the (u, v) reported is the found piece's lower corner, which uv_mapping sees *)
let test_uv () =
  let s = parse torus in
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let o = v 0.2 0. (-3.) and d = v 0. 0. 1. in
  let t = Parametric.depth w s o d 0. in
  let uv = Crossing.uv w.crossing in
  (* x(u, v) = 0.2 at the front of the torus's outer side: u near 3π/2, v near 0 (or 2π) *)
  Alcotest.(check bool) "u" true (Float.abs (uv.x -. (1.5 *. Float.pi)) < 0.2);
  float_eq ~eps:1e-9 "the normal from (u, v)" 0. (Vec.length (Vec.sub (Parametric.normal_at s uv.x uv.y) (Parametric.hit_normal s w.crossing)));
  vec_eq ~eps:0. "the point reported" (Vec.madd o t d) (Crossing.point w.crossing);
  (* in CSG the crossing is pushed with its report *)
  let w = Scratch.create ~robust:false (Stats.create ()) in
  Alcotest.(check int) "one hit pushed" 1 (Parametric.hits w s 0 o d 0. 0);
  Alcotest.(check bool) "with its report" true (Scratch.hit_report w 0);
  vec_eq ~eps:0. "the same (u, v)" uv (Crossing.uv w.crossing)

let test_box () =
  let s = parse "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> contained_by { sphere { <0.1, 0, 0>, 0.3 } } }" in
  let b = Parametric.pov_box s in
  float_eq ~eps:0. "lower x" (Precision.f32 (0.1 -. 0.3)) b.(0);
  float_eq ~eps:0. "length" (Precision.f32 0.6) b.(3);
  let s = parse "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> contained_by { box { -1, 2 } } scale 2 translate x }" in
  let b = Parametric.bounds s in
  vec_eq ~eps:0. "mapped low" (v (-1.) (-2.) (-2.)) (v b.(0) b.(1) b.(2));
  vec_eq ~eps:0. "mapped high" (v 5. 4. 4.) (v b.(3) b.(4) b.(5))

(* POV-Ray's counters: a bound test per call, a parametric test per met container; a sphere
   container takes one sphere test back *)
let test_stats () =
  let st = Stats.create () in
  let w = Scratch.create ~robust:false st in
  let s = parse ball in
  ignore (Parametric.depth w s (v 0.1 0.2 (-3.)) (v 0. 0. 1.) 0.);
  ignore (Parametric.depth w s (v 5. 5. (-3.)) (v 0. 0. 1.) 0.);
  Alcotest.(check (list int)) "bound tests, hits" [ 2; 1 ] [ Stats.tests st Stats.parametric_bound; Stats.hits st Stats.parametric_bound ];
  Alcotest.(check (list int)) "tests, hits" [ 1; 1 ] [ Stats.tests st Stats.parametric; Stats.hits st Stats.parametric ];
  Alcotest.(check (list int)) "sphere tests taken back" [ -2; -1 ] [ Stats.tests st Stats.sphere; Stats.hits st Stats.sphere ]

let test_patch_warning () =
  let ws = warnings (v37 ^ "intersection { " ^ torus ^ " sphere { 0, 1 } }") in
  Alcotest.(check bool) "patch in an intersection" true (List.exists (fun (w : Error.t) -> contains ~sub:"Patch objects not allowed in intersection" w.msg) ws)

let tests =
  [
    Alcotest.test_case "defaults" `Quick test_defaults;
    Alcotest.test_case "items" `Quick test_items;
    Alcotest.test_case "bare functions" `Quick test_bare_functions;
    Alcotest.test_case "precompute items" `Quick test_precompute_items;
    Alcotest.test_case "precompute table" `Quick test_precompute_table;
    Alcotest.test_case "errors" `Quick test_errors;
    Alcotest.test_case "POV-Ray's trace()" `Quick test_trace;
    Alcotest.test_case "a crossing behind the ray" `Quick test_behind;
    Alcotest.test_case "uv" `Quick test_uv;
    Alcotest.test_case "boxes" `Quick test_box;
    Alcotest.test_case "statistics" `Quick test_stats;
    Alcotest.test_case "patch warning" `Quick test_patch_warning;
  ]
