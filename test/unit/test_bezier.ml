(* The bicubic patch, bicubic_patch { … } (POV-Ray's bezier.cpp): its reader's defaults, warnings
   and errors; crossings and interpolated normals against POV-Ray's own trace() (the numbers
   printed by test/unit/data/bicubic_trace.pov); the crossing on the patch's triangles; no inside. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let points =
  "<-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>,\n\
  \  <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>,\n\
  \  <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>,\n\
  \  <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5>"

let patch_of (o : Scene.obj) =
  match o.shape with
  | Bicubic { patch_type; u_steps; v_steps; flatness; points; uv_vectors } -> Bezier.make ~patch_type ~u_steps ~v_steps ~flatness ~st:uv_vectors points
  | _ ->
      Alcotest.fail "expected a bicubic patch"

let parse text = patch_of (the_object (scene (v37 ^ text)))

let test_reader () =
  let b = parse ("bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 2.9 " ^ points ^ " }") in
  Alcotest.(check int) "type" 1 b.patch_type;
  Alcotest.(check int) "u_steps" 3 b.u_steps;
  Alcotest.(check int) "v_steps truncated" 2 b.v_steps;
  float_eq "flatness" 0.05 b.flatness;
  vec_eq "P[1][2]" (v 0.5 0.5 (-0.5)) b.cp.(6);
  Alcotest.(check bool) "type 1 keeps a tree" true (b.tree <> None);
  let old = parse ("bicubic_patch { 0, 3, 4, " ^ points ^ " }") in
  Alcotest.(check (triple int int int)) "old syntax" (0, 3, 4) (old.patch_type, old.u_steps, old.v_steps);
  float_eq "old syntax flatness" 0.1 old.flatness;
  Alcotest.(check bool) "a warning for the old syntax" true
    (List.exists (fun (_, m) -> contains ~sub:"keywords for bicubic" m) (List.map (fun (w : Error.t) -> (w.loc, w.msg)) (warnings (v37 ^ "bicubic_patch { 0, 3, 4, " ^ points ^ " }"))));
  let t2 = parse ("bicubic_patch { type 2 " ^ points ^ " }") in
  Alcotest.(check int) "type 2 is type 1" 1 t2.patch_type;
  expect_scene_error "no type" (v37 ^ "bicubic_patch { flatness 0.1 " ^ points ^ " }") ~line:3 ~col:1 ~sub:"Undefined bicubic patch type"

let first_hit b o d =
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let d = Vec.normalize d in
  let t = Bezier.depth w b o d 0. in
  if t = infinity then None
  else
    let p = Vec.madd o t d in
    Some (p, Crossing.normal w.crossing)

let test_trace () =
  let p1 = parse ("bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 3 " ^ points ^ " }") in
  let p0 = parse ("bicubic_patch { type 0 flatness 0.02 u_steps 4 v_steps 2 " ^ points ^ " rotate <20, 30, 0> }") in
  let cases =
    [ (p1, v 0.1 5. 0.2, v 0. (-1.) 0., v 0.10000000000000001 0.50049743652343714 0.20000000000000001,
       v (-0.09858909712476033) 0.98894110803034518 0.11079564420968055);
      (p1, v (-0.7) (-3.) 0.9, v 0.1 1. (-0.05), v (-0.37762260508257611) 0.22377394917423832 0.73881130254128813,
       v (-0.33030803652921381) 0.87626067433994059 0.35080454901487240);
      (p0, v 0.3 5. (-0.4), v 0. (-1.) 0.1, v 0.29999999999999999 0.46238980863409651 0.05376101913659037,
       v 0.18285779900669294 0.94183024881061117 0.28199079376421149) ]
  in
  List.iteri
    (fun i (b, o, d, ep, en) ->
      match first_hit b o d with
      | None -> Alcotest.failf "case %d: no hit" i
      | Some (p, n) ->
          vec_eq ~eps:1e-15 (Printf.sprintf "case %d: point" i) ep p;
          vec_eq ~eps:1e-15 (Printf.sprintf "case %d: normal" i) en n)
    cases

(* Sampling: the crossing lies on the patch's surface within the flatness (the subpatch's
   triangles stay within it of its control points' plane), and a ray missing the bounding
   box finds nothing. *)
(* the patch's point at (u, v), by the Bernstein polynomials *)
let surface (b : Bezier.t) u v =
  let bern t = [| (1. -. t) ** 3.; 3. *. t *. ((1. -. t) ** 2.); 3. *. t *. t *. (1. -. t); t ** 3. |] in
  let bu = bern u and bv = bern v in
  let acc = ref Vec.zero in
  for i = 0 to 3 do
    for j = 0 to 3 do
      acc := Vec.add !acc (Vec.scale (bu.(i) *. bv.(j)) b.cp.((4 * i) + j))
    done
  done;
  !acc

let distance_to_surface b (p : Vec.t) =
  let best = ref infinity in
  for i = 0 to 200 do
    for j = 0 to 200 do
      let q = surface b (Float.of_int i /. 200.) (Float.of_int j /. 200.) in
      best := Float.min !best (Vec.length (Vec.sub p q))
    done
  done;
  !best

let test_sampling () =
  let b = parse ("bicubic_patch { type 1 flatness 0.01 u_steps 4 v_steps 4 " ^ points ^ " }") in
  let rng = Random.State.make [| 3 |] in
  for _ = 1 to 12 do
    let x = Random.State.float rng 2. -. 1. and z = Random.State.float rng 2. -. 1. in
    match first_hit b (v x 5. z) (v 0. (-1.) 0.) with
    | None -> Alcotest.fail "a vertical ray over the patch must hit it"
    | Some (p, n) ->
        Alcotest.(check bool) "on the ray" true (Float.abs (p.x -. x) < 1e-12 && Float.abs (p.z -. z) < 1e-12);
        Alcotest.(check bool) "a unit normal" true (Float.abs (Vec.length n -. 1.) < 1e-12);
        (* within the flatness of the true surface (the grid's spacing adds its own bit) *)
        let dist = distance_to_surface b p in
        if dist > 0.03 then Alcotest.failf "the crossing %s is %g from the surface" (Vec.to_string p) dist
  done;
  Alcotest.(check bool) "outside the box" true (first_hit b (v 3. 5. 0.) (v 0. (-1.) 0.) = None)

(* A type 1 patch whose tree could have more than 2^16 leaves is subdivided for every ray (POV-Ray's
   tree for u_steps 12 v_steps 12 takes 3.7 GB); the subdivision crosses the same subpatches in the
   same order as the tree, so the depths, normals and uv are the tree's to the bit. *)
let test_big_tree () =
  let big = parse ("bicubic_patch { type 1 u_steps 12 v_steps 12 " ^ points ^ " }") in
  Alcotest.(check bool) "u_steps 12 v_steps 12: no tree" true (big.tree = None);
  Alcotest.(check bool) "u_steps 8 v_steps 8: a tree" true ((parse ("bicubic_patch { type 1 u_steps 8 v_steps 8 " ^ points ^ " }")).tree <> None);
  let tree = parse ("bicubic_patch { type 1 u_steps 5 v_steps 4 " ^ points ^ " }") in
  let walked = { tree with tree = None } in
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let at b o d =
    let t = Bezier.depth w b o d 0. in
    if t = infinity then None
    else Some (t, Crossing.normal w.crossing, Crossing.uv w.crossing)
  in
  let hits = ref 0 in
  for i = 0 to 20 do
    for j = 0 to 20 do
      let o = v ((float_of_int i /. 10.) -. 1.) 5. ((float_of_int j /. 10.) -. 1.) and d = Vec.normalize (v 0.1 (-1.) 0.05) in
      match (at tree o d, at walked o d) with
      | None, None -> ()
      | Some (t1, n1, uv1), Some (t2, n2, uv2) ->
          incr hits;
          float_eq ~eps:0. "depth" t1 t2;
          vec_eq ~eps:0. "normal" n1 n2;
          vec_eq ~eps:0. "uv" uv1 uv2
      | _ -> Alcotest.failf "ray %d, %d: the tree and the subdivision disagree on a hit" i j
    done
  done;
  Alcotest.(check bool) "most rays hit" true (!hits > 300)

let test_no_inside () =
  let c = compile (v37 ^ "bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 3 " ^ points ^ " }") in
  let o = c.objects.(0) in
  Alcotest.(check bool) "no inside" false (Shape.inside (Array.make 512 0.) o.shape (v 0. 0.3 0.))

(* Compute_Texture_UV: the default uv_vectors give (v, u); the corners map to the uv_vectors *)
let test_texture_uv () =
  let pair msg (eu, ev) (u, v) = float_eq (msg ^ " u") eu u; float_eq (msg ^ " v") ev v in
  let d = parse ("bicubic_patch { type 1 u_steps 1 v_steps 1 " ^ points ^ " }") in
  pair "default" (0.75, 0.25) (Bezier.texture_uv d 0.25 0.75);
  let b = parse ("bicubic_patch { type 1 u_steps 1 v_steps 1 uv_vectors <0.1, 0.2>, <2, 0.3>, <1.8, 1.9>, 0.4 " ^ points ^ " }") in
  pair "u = v = 0: the first" (0.1, 0.2) (Bezier.texture_uv b 0. 0.);
  pair "v = 1: the second" (2., 0.3) (Bezier.texture_uv b 0. 1.);
  pair "u = v = 1: the third" (1.8, 1.9) (Bezier.texture_uv b 1. 1.);
  pair "u = 1: the fourth (a float for both terms)" (0.4, 0.4) (Bezier.texture_uv b 1. 0.);
  pair "the middle" ((0.1 +. 2. +. 1.8 +. 0.4) /. 4., (0.2 +. 0.3 +. 1.9 +. 0.4) /. 4.) (Bezier.texture_uv b 0.5 0.5)

let tests =
  [
    Alcotest.test_case "uv_vectors" `Quick test_texture_uv;
    Alcotest.test_case "reader" `Quick test_reader;
    Alcotest.test_case "trace() points and normals" `Quick test_trace;
    Alcotest.test_case "crossings by sampling" `Quick test_sampling;
    Alcotest.test_case "no inside" `Quick test_no_inside;
    Alcotest.test_case "type 1 too big for a tree: the same crossings" `Quick test_big_tree;
  ]
