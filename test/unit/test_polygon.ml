(* The polygon (docs/povray-rules.md §15.7): how Parse_Polygon closes outlines, the frame Compute_Polygon
   builds, the even-odd test with a hole and an island, the depth limits, transforms and the normal,
   no inside (in CSG too), POV-Ray's box, the errors and warnings. Expected values are worked out
   by hand in the comments. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
let v2 x y = v x y 0.

(* a square of side 4 about the origin in z = 0, a square hole of side 2 in it, and a square
   island of side 1 in the hole: three outlines of five points each *)
let ring =
  [| v2 (-2.) (-2.); v2 2. (-2.); v2 2. 2.; v2 (-2.) 2.; v2 (-2.) (-2.);
     v2 (-1.) (-1.); v2 1. (-1.); v2 1. 1.; v2 (-1.) 1.; v2 (-1.) (-1.);
     v2 (-0.5) (-0.5); v2 0.5 (-0.5); v2 0.5 0.5; v2 (-0.5) 0.5; v2 (-0.5) (-0.5) |]

let ring_text =
  "polygon { 15, <-2,-2>, <2,-2>, <2,2>, <-2,2>, <-2,-2>, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1>,\n"
  ^ "  <-0.5,-0.5>, <0.5,-0.5>, <0.5,0.5>, <-0.5,0.5>, <-0.5,-0.5>"

(* the depths of the crossing of the ray from [o] along [d] (normalised here) *)
let crossing ?(lim = Limits.pov) ?(stats = Stats.create ()) p o d =
  let out = Array.make 1 nan in
  let n = Polygon.intersect stats lim p o (Vec.normalize d) out in
  List.init n (fun i -> out.(i))

let depths_eq msg e a = Alcotest.(check (list (float 1e-12))) msg e a
let polygon_of (o : Scene.obj) =
  match o.shape with
  | Polygon p -> p
  | _ ->
      Alcotest.fail "expected a polygon"

let test_close () =
  let pts l = Array.of_list (List.map (fun (x, y) -> v2 x y) l) in
  let closed, appended = Polygon.close (pts [ (0., 0.); (1., 0.); (1., 1.); (0., 0.) ]) in
  Alcotest.(check bool) "closed: nothing appended" false appended;
  Alcotest.(check int) "closed: as many points" 4 (Array.length closed);
  let closed, appended = Polygon.close (pts [ (0., 0.); (1., 0.); (1., 1.) ]) in
  Alcotest.(check bool) "open: the first point appended" true appended;
  vec_eq "open: it is the first" Vec.zero closed.(3);
  (* a point within EPSILON of the first is snapped onto it exactly *)
  let closed, _ = Polygon.close [| Vec.zero; v2 1. 0.; v2 1. 1.; v2 1e-11 (-1e-11) |] in
  Alcotest.(check bool) "snapped" true (closed.(3) = Vec.zero);
  (* two outlines: the second starts after the first closing point and ends at its own first *)
  let _, appended = Polygon.close (pts [ (0., 0.); (4., 0.); (4., 4.); (0., 0.); (1., 1.); (2., 1.); (2., 2.) ]) in
  Alcotest.(check bool) "second outline open: appended" true appended;
  let closed, appended = Polygon.close (pts [ (0., 0.); (4., 0.); (4., 4.); (0., 0.); (1., 1.); (2., 1.); (2., 2.) ]) in
  vec_eq "closed with the second outline's first point" (v2 1. 1.) closed.(7);
  ignore appended;
  (* one point after a closed outline leaves the polygon "closed" (POV-Ray's loop steps over it) *)
  let _, appended = Polygon.close (pts [ (0., 0.); (1., 0.); (0., 1.); (0., 0.); (5., 5.) ]) in
  Alcotest.(check bool) "a trailing point" false appended

let test_frame () =
  (* o = (−2,−2,0), u = (4,0,0), v the next point off the line, (4,4,0); w = u × v = (0,0,16),
     then u := v × w = (64,−64,0) and v := w × u = (1024,1024,0): the frame turned by −45° *)
  let p = Polygon.make ring in
  Alcotest.(check bool) "not degenerate" false p.degenerate;
  let s = 1. /. sqrt 2. in
  vec_eq ~eps:1e-12 "u" (v s (-.s) 0.) (Transform.direction p.tr (v 1. 0. 0.));
  vec_eq ~eps:1e-12 "v" (v s s 0.) (Transform.direction p.tr (v 0. 1. 0.));
  vec_eq ~eps:1e-12 "w" (v 0. 0. 1.) (Transform.direction p.tr (v 0. 0. 1.));
  vec_eq ~eps:1e-12 "the origin is the first point" (v (-2.) (-2.) 0.) (Transform.point p.tr Vec.zero);
  (* the third point (2, 2) is 4√2 along v from o *)
  float_eq ~eps:1e-12 "projected u" 0. p.points.(4);
  float_eq ~eps:1e-12 "projected v" (4. *. sqrt 2.) p.points.(5);
  (* collinear points, or one off the plane of the first three: degenerate *)
  Alcotest.(check bool) "collinear" true (Polygon.make [| Vec.zero; v2 1. 1.; v2 2. 2.; Vec.zero |]).degenerate;
  Alcotest.(check bool) "not coplanar" true (Polygon.make [| Vec.zero; v2 1. 0.; v2 1. 1.; v 0. 1. 1e-9; Vec.zero |]).degenerate;
  Alcotest.(check bool) "within 1e-10 of the plane" false (Polygon.make [| Vec.zero; v2 1. 0.; v2 1. 1.; v 0. 1. 1e-11; Vec.zero |]).degenerate

let test_hits () =
  let p = Polygon.make ring in
  let along x y = crossing p (v x y (-5.)) (v 0. 0. 1.) in
  depths_eq "on the ring" [ 5. ] (along 1.5 0.);
  depths_eq "in the hole" [] (along 0.75 0.);
  depths_eq "on the island" [ 5. ] (along 0.2 0.3);
  depths_eq "outside" [] (along 3. 0.);
  (* left of the diagonal through the first points (u < 0 in polygon space), the +u test ray
     crosses the line of the outlines' first points: the walk must jump from one outline to the
     next there, not count an edge between them *)
  depths_eq "on the ring, left" [ 5. ] (along (-1.5) 0.);
  depths_eq "in the hole, left" [] (along (-0.75) 0.);
  depths_eq "on the island, left" [ 5. ] (along (-0.2) 0.3);
  depths_eq "from behind" [ 5. ] (crossing p (v 1.5 1.5 5.) (v 0. 0. (-1.)));
  (* slanted: the depth along the unit direction *)
  depths_eq "slanted" [ 5. *. sqrt 2. ] (crossing p (v (-3.5) 0. (-5.)) (v 1. 0. 1.));
  (* in the plane (|V.z| < 1e-10), or starting on it (s = 0 < 1e-8): no hit *)
  depths_eq "in its plane" [] (crossing p (v (-5.) 1.5 0.) (v 1. 0. 0.));
  depths_eq "from its plane" [] (crossing p (v 1.5 0. 0.) (v 0. 0. 1.));
  depths_eq "just off it (1e-8 is enough)" [ 1e-8 ] (crossing p (v 1.5 0. (-1e-8)) (v 0. 0. 1.));
  (* a degenerate polygon is never tested *)
  let stats = Stats.create () in
  depths_eq "degenerate" [] (crossing ~stats (Polygon.make [| Vec.zero; v2 1. 1.; v2 2. 2.; Vec.zero |]) (v 0.5 0.5 (-1.)) (v 0. 0. 1.));
  Alcotest.(check int) "degenerate: no test counted" 0 (Stats.tests stats Stats.polygon);
  ignore (crossing ~stats p (v 1.5 0. (-5.)) (v 0. 0. 1.));
  ignore (crossing ~stats p (v 0.75 0. (-5.)) (v 0. 0. 1.));
  Alcotest.(check (pair int int)) "tests and hits" (2, 1) (Stats.tests stats Stats.polygon, Stats.hits stats Stats.polygon)

let test_transform () =
  (* scale <2,2,3> then translate z*2: the hole is now |x|, |y| < 2, the plane z = 2; in polygon
     space the ray's direction has length 1/3 and is renormalised, the depth divided back *)
  let o = the_object (scene (ring_text ^ " scale <2,2,3> translate z*2 }")) in
  let p = polygon_of o in
  depths_eq "moved: on the ring" [ 7. ] (crossing p (v 3. 0. (-5.)) (v 0. 0. 1.));
  depths_eq "moved: in the hole" [] (crossing p (v 1.5 0. (-5.)) (v 0. 0. 1.));
  (* the normal: (0,0,1) by the inverse transpose; rotate x*90 turns +z to −y *)
  vec_eq "normal" (v 0. 0. 1.) (Polygon.normal p Vec.zero);
  let r = polygon_of (the_object (scene (ring_text ^ " rotate x*90 }"))) in
  vec_eq ~eps:1e-12 "turned normal" (v 0. (-1.) 0.) (Polygon.normal r Vec.zero);
  depths_eq "turned: hit from above" [ 5. ] (crossing r (v 1.5 5. 0.) (v 0. (-1.) 0.));
  (* a shear tilts the plane to z = x/2: the normal (−½, 0, 1) by the inverse transpose, normalised *)
  let h = polygon_of (the_object (scene (ring_text ^ " matrix <1,0,0.5, 0,1,0, 0,0,1, 0,0,0> }"))) in
  vec_eq ~eps:1e-12 "sheared normal" (Vec.normalize (v (-0.5) 0. 1.)) (Polygon.normal h Vec.zero);
  (* inverse does nothing to a polygon, not even the flag *)
  let i = the_object (scene (ring_text ^ " inverse }")) in
  Alcotest.(check bool) "inverse: still a polygon" true (match i.shape with Polygon _ -> true | _ -> false)

let test_inside_and_csg () =
  let p = Polygon.make ring in
  Alcotest.(check bool) "no inside" false (Polygon.inside p Vec.zero);
  (* intersection { polygon sphere }: the polygon's hits inside the sphere, no sphere hit *)
  let c = compile (v37 ^ "intersection { " ^ ring_text ^ " } sphere { 0, 1.8 } }") in
  let top = c.objects.(0) in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  let hit x y = Shape.depth ctx.Context.shapes top.shape (v x y (-5.)) (v 0. 0. 1.) 0. in
  float_eq "the polygon inside the sphere" 5. (hit 1.5 0.);
  Alcotest.(check (float 0.)) "the sphere alone (in the hole)" infinity (hit 0.75 0.);
  Alcotest.(check (float 0.)) "the polygon outside the sphere" infinity (hit 1.5 1.5);
  Alcotest.(check bool) "the CSG has no inside" false (Shape.inside (Array.make 512 0.) top.shape Vec.zero);
  (* difference { sphere polygon }: the polygon is not inverted, so the same *)
  let c = compile (v37 ^ "difference { sphere { 0, 1.8 } " ^ ring_text ^ " } }") in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  float_eq "difference: the polygon inside" 5. (Shape.depth ctx.Context.shapes c.objects.(0).shape (v 1.5 0. (-5.)) (v 0. 0. 1.) 0.);
  (* merge { sphere polygon }: the sphere, and the polygon outside it *)
  let c = compile (v37 ^ "merge { sphere { 0, 1.8 } " ^ ring_text ^ " } }") in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  float_eq "merge: the sphere" (5. -. sqrt (1.8 *. 1.8 -. 2.25)) (Shape.depth ctx.Context.shapes c.objects.(0).shape (v 1.5 0. (-5.)) (v 0. 0. 1.) 0.);
  float_eq "merge: the polygon outside" 5. (Shape.depth ctx.Context.shapes c.objects.(0).shape (v 1.5 1.5 (-5.)) (v 0. 0. 1.) 0.)

let test_box () =
  let f32 = Precision.f32 in
  let p = Polygon.make ring in
  (* the points' extent; z is flat, so widened by 1e-3 on each side, in single precision *)
  let b = Polygon.pov_box p in
  let e = [| -2.; -2.; f32 (-1e-3); 4.; 4.; f32 (f32 0. +. 2e-3) |] in
  Array.iteri (fun i x -> float_eq ~eps:1e-9 (Printf.sprintf "box %d" i) x b.(i)) e;
  (match Polygon.bounds p with
  | Some bb -> Alcotest.(check (array (float 1e-12))) "bounds" [| -2.; -2.; -1e-3; 2.; 2.; 1e-3 |] bb
  | None -> Alcotest.fail "bounded");
  let d = Polygon.make [| Vec.zero; v2 1. 1.; v2 2. 2.; Vec.zero |] in
  Alcotest.(check bool) "degenerate: no box" true (Polygon.pov_box d = [||] && Polygon.bounds d = None)

let test_errors () =
  expect_scene_error "too few points" "polygon { 2, <0,0>, <1,0> }" ~line:1 ~col:11 ~sub:"at least three points";
  expect_scene_error "a count below 3 after truncation" "polygon { 2.9, <0,0>, <1,0>, <0,1> }" ~line:1 ~col:11 ~sub:"at least three points";
  expect_scene_error "fewer points than it says" "polygon { 4, <0,0>, <1,0>, <0,1> }" ~line:1 ~col:34 ~sub:"only 3 are written";
  let w = warnings "polygon { 3, <0,0>, <1,0>, <0,1> }" in
  Alcotest.(check bool) "not closed: a warning" true (List.exists (fun (e : Error.t) -> contains ~sub:"not closed" e.msg) w);
  let w = warnings "polygon { 4 <0,0> <1,0> <0,1> <0,0> }" in
  Alcotest.(check bool) "closed, commas optional: no warning" false (List.exists (fun (e : Error.t) -> contains ~sub:"polygon" e.msg) w);
  let p = polygon_of (the_object (scene "polygon { 3.9, <0,0>, <1,0>, <0,1> }")) in
  Alcotest.(check int) "3.9 points are 3, and the closing one" 4 (Array.length p.points / 2)

(* the intersection allocates nothing: the crossing stays unboxed and goes into the array *)
let test_no_allocation () =
  let p = Polygon.make ring in
  let stats = Stats.create () and out = Array.make 1 0. and o = v (-0.2) 0.3 (-5.) and d = v 0. 0. 1. in
  let before = Gc.minor_words () in
  for _ = 1 to 10_000 do
    ignore (Polygon.intersect stats Limits.pov p o d out)
  done;
  let words = Gc.minor_words () -. before in
  if words > 100. then Alcotest.failf "10,000 intersections allocated %.0f words" words

let tests =
  [
    Alcotest.test_case "closing outlines" `Quick test_close;
    Alcotest.test_case "frame" `Quick test_frame;
    Alcotest.test_case "hits (hole and island)" `Quick test_hits;
    Alcotest.test_case "transforms and normal" `Quick test_transform;
    Alcotest.test_case "no inside, in CSG" `Quick test_inside_and_csg;
    Alcotest.test_case "POV-Ray's box" `Quick test_box;
    Alcotest.test_case "errors and warnings" `Quick test_errors;
    Alcotest.test_case "no allocation" `Quick test_no_allocation;
  ]
