(* Transform (§14.1–§14.3) against matrices and points computed by hand, Place (§14.4) on each
   shape, and hits on transformed shapes against analytic answers (§14.5, §14.6). *)

open Helpers

let v = Vec.make
let tr_ok a = match Transform.matrix a with Ok (t, _) -> t | Error e -> Alcotest.fail e

let test_matrix () =
  (* §14.2 (checked with vtransform): rows in order, x' = a·x + d·y + g·z + j *)
  let t = tr_ok [| 1.; 2.; 3.; 4.; 5.; 6.; 7.; 8.; 10.; 10.; 20.; 30. |] in
  vec_eq ~eps:0. "x ↦ <11,22,33>" (v 11. 22. 33.) (Transform.point t (v 1. 0. 0.));
  vec_eq ~eps:0. "y ↦ <14,25,36>" (v 14. 25. 36.) (Transform.point t (v 0. 1. 0.));
  vec_eq ~eps:0. "direction ignores row 3" (v 1. 2. 3.) (Transform.direction t (v 1. 0. 0.));
  vec_eq ~eps:1e-12 "inverse maps back" (v 0.3 (-2.) 5.) (Transform.inv_point t (Transform.point t (v 0.3 (-2.) 5.)));
  (* det of the 3×3 part: 1(50−48) − 2(40−42) + 3(32−35) = −3; I[0][0] = (5·10 − 6·8)/−3 *)
  float_eq ~eps:1e-15 "I[0][0] by cofactors" (2. /. -3.) t.i00

let test_matrix_rules () =
  (* an all-zero column gets a 1 on the diagonal, with a warning *)
  (match Transform.matrix [| 0.; 2.; 0.; 0.; 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0. |] with
  | Ok (t, [ w ]) ->
      check_contains "warning" ~sub:"Illegal matrix column" w;
      vec_eq ~eps:0. "identity in x" (v 1. 2. 0.) (Transform.point t (v 1. 0. 0.))
  | Ok (_, ws) -> Alcotest.failf "expected one warning, got %d" (List.length ws)
  | Error e -> Alcotest.fail e);
  match Transform.matrix [| 1.; 2.; 3.; 2.; 4.; 6.; 0.; 0.; 1.; 0.; 0.; 0. |] with
  | Ok _ -> Alcotest.fail "a singular matrix must be an error"
  | Error e -> check_contains "singular" ~sub:"Singular matrix" e

let test_order () =
  (* §14.2: translate x rotate 90*z maps 0 to <0,1,0>; the other order to <1,0,0> *)
  let tz = Transform.rotate (v 0. 0. 90.) and tx = Transform.translate (v 1. 0. 0.) in
  vec_eq ~eps:1e-15 "translate then rotate" (v 0. 1. 0.) (Transform.point (Transform.compose tx tz) Vec.zero);
  vec_eq ~eps:1e-15 "rotate then translate" (v 1. 0. 0.) (Transform.point (Transform.compose tz tx) Vec.zero);
  (* rotate <90,90,0> is about x first: y ↦ z ↦ x *)
  vec_eq ~eps:1e-15 "rotate <90,90,0> maps y to x" (v 1. 0. 0.) (Transform.point (Transform.rotate (v 90. 90. 0.)) (v 0. 1. 0.));
  (* left-handed: rotate 90*y takes x to −z *)
  vec_eq ~eps:1e-15 "rotate 90*y maps x to -z" (v 0. 0. (-1.)) (Transform.point (Transform.rotate (v 0. 90. 0.)) (v 1. 0. 0.));
  (* the rotation's inverse is its exact transpose *)
  let r = Transform.rotate (v 20. 35. 10.) in
  float_eq ~eps:0. "I = Mᵀ (0,1)" r.m10 r.i01;
  float_eq ~eps:0. "I = Mᵀ (2,0)" r.m02 r.i20

let test_compose_inverse () =
  let t = Transform.compose (Transform.translate (v 1. 2. 3.)) (Transform.scale (v 2. 2. 2.)) in
  vec_eq ~eps:0. "translate <1,2,3> scale 2 maps 0 to <2,4,6>" (v 2. 4. 6.) (Transform.point t Vec.zero);
  (* §14.3: { translate <1,2,3> scale 2 inverse } maps 0 to <−1,−2,−3> *)
  vec_eq ~eps:1e-15 "inverse block" (v (-1.) (-2.) (-3.)) (Transform.point (Transform.inverse t) Vec.zero);
  let r = Transform.compose (Transform.rotate (v 20. 35. 10.)) (Transform.scale (v 1. 0.5 3.)) in
  let p = v 0.7 (-1.1) 2.5 in
  vec_eq ~eps:1e-14 "inverse after compose" p (Transform.point (Transform.compose r (Transform.inverse r)) p);
  vec_eq ~eps:1e-14 "inv_point undoes point" p (Transform.inv_point r (Transform.point r p));
  Alcotest.(check bool) "identity" true (Transform.is_identity Transform.identity);
  Alcotest.(check bool) "a rotation is not" false (Transform.is_identity r)

let test_normal () =
  (* inverse transpose: scale <1,2,1> makes the y normal half as long; shear keeps it normal *)
  vec_eq ~eps:0. "scaled normal" (v 0. 0.5 0.) (Transform.normal (Transform.scale (v 1. 2. 1.)) (v 0. 1. 0.));
  let sh = tr_ok [| 1.; 0.5; 0.; 0.; 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0. |] in
  (* the plane y = 0 becomes y = x/2; its normal ∝ <−0.5, 1, 0> *)
  vec_eq ~eps:1e-15 "sheared normal" (v (-0.5) 1. 0.) (Transform.normal sh (v 0. 1. 0.))

(* ---- Place and the tracer ---- *)

(* The compiled scene of [text] after applying [ops] to its first object. *)
let placed text ops =
  let s = scene text in
  let objects = List.mapi (fun i (o : Scene.obj) -> if i = 0 then { o with shape = List.fold_left Place.shape o.shape ops } else o) s.objects in
  Compile.scene { s with objects }

let hit c o d =
  let ctx = Trace.make_ctx c (Stats.create ()) in
  Shape.depth ctx.Context.shapes c.Compiled.objects.(0).shape o (Vec.normalize d) 1e-4

let test_place_sphere () =
  let shape ops = List.fold_left Place.shape (the_object (scene "sphere { <1,2,3>, 0.5 }")).shape ops in
  (match shape [ Place.Scale (v (-2.) (-2.) (-2.)) ] with
  | Sphere { centre; radius; trans = None; _ } ->
      vec_eq ~eps:0. "uniform scale moves the centre" (v (-2.) (-4.) (-6.)) centre;
      float_eq ~eps:0. "radius times |s|" 1. radius
  | _ -> Alcotest.fail "a uniform scale keeps a sphere");
  (match shape [ Place.Scale (v 2. 1. 1.); Place.Translate (v 1. 0. 0.) ] with
  | Sphere { centre; radius; trans = Some t; _ } ->
      vec_eq ~eps:0. "object-space centre kept" (v 1. 2. 3.) centre;
      float_eq ~eps:0. "object-space radius kept" 0.5 radius;
      vec_eq ~eps:0. "later modifiers compose into the transform" (v 3. 2. 3.) (Transform.point t centre)
  | _ -> Alcotest.fail "a non-uniform scale makes an ellipsoid")

let test_ellipsoid_hits () =
  (* unit sphere scaled <2,1,1>: x²/4 + y² + z² = 1 *)
  let c = placed "sphere { 0, 1 }" [ Place.Scale (v 2. 1. 1.) ] in
  float_eq ~eps:1e-12 "along x: surface at x = −2" 3. (hit c (v (-5.) 0. 0.) (v 1. 0. 0.));
  float_eq ~eps:1e-12 "along z: surface at z = −1" 4. (hit c (v 0. 0. (-5.)) (v 0. 0. 1.));
  (* a ray at y = 0.9 meets x = −2·sqrt(1 − 0.81) *)
  float_eq ~eps:1e-12 "off-axis" (5. -. (2. *. sqrt 0.19)) (hit c (v (-5.) 0.9 0.) (v 1. 0. 0.));
  Alcotest.(check bool) "miss above" true (hit c (v (-5.) 1.1 0.) (v 1. 0. 0.) = infinity);
  (* from inside, the far root *)
  float_eq ~eps:1e-12 "from the centre" 2. (hit c Vec.zero (v 1. 0. 0.));
  (* normal at (√2, √0.5, 0) ∝ (x/4, y) = (√2/4, √0.5): normalised (1, 2)/√5 *)
  let n = Shape.normal (Scratch.create ~robust:false (Stats.create ())) c.objects.(0) (-1) (v (sqrt 2.) (sqrt 0.5) 0.) in
  vec_eq ~eps:1e-12 "normal by the inverse transpose" (v (1. /. sqrt 5.) (2. /. sqrt 5.) 0.) n;
  (* Inside in object space *)
  let inside p = Shape.inside (Array.make 512 0.) c.objects.(0).shape p in
  Alcotest.(check bool) "inside at x = 1.9" true (inside (v 1.9 0. 0.));
  Alcotest.(check bool) "outside at y = 1.1" false (inside (v 0. 1.1 0.))

let test_plane () =
  (* baked: plane y, 1 scaled <1,2,1> is y = 2; rotated 90 about z it is x = −1 (y ↦ −x) *)
  (match List.fold_left Place.shape (the_object (scene "plane { y, 1 }")).shape [ Place.Scale (v 1. 2. 1.) ] with
  | Plane { normal; offset; trans = None } ->
      vec_eq ~eps:0. "normal" (v 0. 1. 0.) normal;
      float_eq ~eps:0. "offset" 2. offset
  | _ -> Alcotest.fail "a scale is baked into a plane");
  let c = placed "plane { y, 1 }" [ Place.Rotate (v 0. 0. 90.) ] in
  float_eq ~eps:1e-12 "rotated plane at x = −1" 4. (hit c (v 3. 0. 0.) (v (-1.) 0. 0.));
  (* under a matrix: the shear x ↦ (x, x/2) turns y = 0 into y = x/2; a ray down from (2,5,0) hits
     at y = 1, world depth 4, and the normal is normalize(−0.5, 1, 0) *)
  let sh = tr_ok [| 1.; 0.5; 0.; 0.; 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0. |] in
  let c = placed "plane { y, 0 }" [ Place.Transform sh ] in
  (match c.objects.(0).shape with Compiled.Plane_trans _ -> () | _ -> Alcotest.fail "a matrix gives the plane a transform");
  float_eq ~eps:1e-12 "sheared plane" 4. (hit c (v 2. 5. 0.) (v 0. (-1.) 0.));
  vec_eq ~eps:1e-12 "sheared normal" (Vec.normalize (v (-0.5) 1. 0.)) (Shape.normal (Scratch.create ~robust:false (Stats.create ())) c.objects.(0) (-1) (v 2. 1. 0.));
  let inside p = Shape.inside (Array.make 512 0.) c.objects.(0).shape p in
  Alcotest.(check bool) "below the sheared plane is inside" true (inside (v 2. 0.9 0.));
  Alcotest.(check bool) "above is outside" false (inside (v 2. 1.1 0.))

let test_triangle () =
  (* rotate 90*y: (x,y,z) ↦ (z, y, −x): the triangle (−1,0,0) (1,0,0) (0,1,0) lies in x = 0 *)
  let text = "triangle { <-1,0,0>, <1,0,0>, <0,1,0> }" in
  let c = placed text [ Place.Rotate (v 0. 90. 0.) ] in
  float_eq ~eps:1e-12 "hit at x = 0" 5. (hit c (v (-5.) 0.2 0.) (v 1. 0. 0.));
  (* at y = 0.2 the triangle spans z in [−0.8, 0.8] *)
  Alcotest.(check bool) "miss beside it" true (hit c (v (-5.) 0.2 0.9) (v 1. 0. 0.) = infinity);
  let n = Shape.normal (Scratch.create ~robust:false (Stats.create ())) c.objects.(0) (-1) (v 0. 0.2 0.) in
  vec_eq ~eps:1e-12 "normal along x (either sign)" (v 1. 0. 0.) (if n.x < 0. then Vec.neg n else n);
  (* a smooth triangle's normals go by the inverse transpose: scaling x by 2 halves a normal's x *)
  let s =
    List.fold_left Place.shape
      (the_object (scene "smooth_triangle { <0,0,0>, <1,0,-1>, <1,0,0>, <1,0,-1>, <0,1,0>, <1,0,-1> }")).shape
      [ Place.Transform (Transform.scale (v 2. 1. 1.)) ]
  in
  match s with
  | Smooth_triangle { n1; n2; n3; _ } ->
      (* the parsed normals are <1,0,-1>/√2; the first set-up may swap n1 and n2, all are equal *)
      List.iter (vec_eq ~eps:1e-15 "normal by MTransNormal, not renormalised" (v (0.5 /. sqrt 2.) 0. (-1. /. sqrt 2.))) [ n1; n2; n3 ]
  | _ -> Alcotest.fail "expected a smooth triangle"

let test_mesh () =
  let text = "mesh { triangle { <-1,0,0>, <1,0,0>, <0,1,0> } inside_vector z }" in
  let c = placed text [ Place.Rotate (v 0. 90. 0.); Place.Scale (v 1. 2. 1.); Place.Translate (v 3. 0. 0.) ] in
  (* the face now lies in x = 3, spans y in [0, 2] *)
  float_eq ~eps:1e-12 "hit the moved face" 8. (hit c (v (-5.) 1.5 0.) (v 1. 0. 0.));
  Alcotest.(check bool) "miss above it" true (hit c (v (-5.) 2.1 0.) (v 1. 0. 0.) = infinity);
  let n = Shape.normal (Scratch.create ~robust:false (Stats.create ())) c.objects.(0) 0 (v 3. 1.5 0.) in
  float_eq ~eps:1e-7 "normal along x" 1. (Float.abs n.x)

let tests =
  [
    Alcotest.test_case "matrix" `Quick test_matrix;
    Alcotest.test_case "matrix column and singular rules" `Quick test_matrix_rules;
    Alcotest.test_case "order of rotate and translate" `Quick test_order;
    Alcotest.test_case "compose and inverse" `Quick test_compose_inverse;
    Alcotest.test_case "normal" `Quick test_normal;
    Alcotest.test_case "sphere placement" `Quick test_place_sphere;
    Alcotest.test_case "ellipsoid hits" `Quick test_ellipsoid_hits;
    Alcotest.test_case "plane" `Quick test_plane;
    Alcotest.test_case "triangle" `Quick test_triangle;
    Alcotest.test_case "mesh" `Quick test_mesh;
  ]
