(* The box (docs/povray-rules.md §15.1): parsing and placing, the slab intersection with its side tie rule
   and depth limits, the normal of the side hit, the closed inside test. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let box_of (o : Scene.obj) =
  match o.shape with
  | Box { lo; hi; trans } -> (lo, hi, trans)
  | _ -> Alcotest.fail "expected a box"

let vec_eq ?(eps = 1e-12) msg (e : Vec.t) (a : Vec.t) =
  float_eq ~eps (msg ^ " x") e.x a.x;
  float_eq ~eps (msg ^ " y") e.y a.y;
  float_eq ~eps (msg ^ " z") e.z a.z

(* The first object of [text], compiled, and a context to trace it in. *)
let setup ?(robust = false) text =
  let c = compile (v37 ^ text) in
  (c.objects.(0), Trace.make_ctx ~robust c (Stats.create ()))

(* The depth, side and unit normal where the ray from [o] along [d] (normalised) meets the object,
   for hits at least [lo]. *)
let hit ?(lo = 0.) (obj, ctx) o d =
  let d = Vec.normalize d in
  ctx.Context.shapes.part <- -1;
  let t = Shape.depth ctx.Context.shapes obj.Compiled.shape o d lo in
  let side = ctx.Context.shapes.part in
  (t, side, if t < infinity then Shape.normal ctx.Context.shapes obj side (Vec.madd o t d) else Vec.zero)

let unit_box = "box { <-1,-1,-1>, <1,1,1> }"

let test_parse () =
  (* the corners are sorted per axis *)
  let lo, hi, trans = box_of (the_object (scene "box { <1,-2,3>, <-1,2,-3> }")) in
  vec_eq "lo" (v (-1.) (-2.) (-3.)) lo;
  vec_eq "hi" (v 1. 2. 3.) hi;
  Alcotest.(check bool) "no transform" true (trans = None);
  (* translate and scale move the corners; a negative scale re-sorts them *)
  let lo, hi, trans = box_of (the_object (scene "box { 0, 1 scale <2,-1,1> translate <1,0,0> }")) in
  vec_eq "scaled lo" (v 1. (-1.) 0.) lo;
  vec_eq "scaled hi" (v 3. 0. 1.) hi;
  Alcotest.(check bool) "still no transform" true (trans = None);
  (* rotate attaches a transform; later translations compose into it *)
  let lo, hi, trans = box_of (the_object (scene "box { 0, 1 rotate y*90 translate x }")) in
  vec_eq "rotated lo" Vec.zero lo;
  vec_eq "rotated hi" (v 1. 1. 1.) hi;
  Alcotest.(check bool) "transform" true (trans <> None);
  (* a flat box is accepted silently, as POV-Ray does *)
  let lo, hi, _ = box_of (the_object (scene "box { <0,1,0>, <2,1,2> }")) in
  float_eq "flat" lo.y hi.y

let test_outside_and_inside () =
  let b = setup unit_box in
  let t, side, n = hit b (v 0. 0. (-5.)) (v 0. 0. 1.) in
  float_eq "from outside: depth" 4. t;
  Alcotest.(check int) "from outside: Z- side" 5 side;
  vec_eq "from outside: normal" (v 0. 0. (-1.)) n;
  let t, side, n = hit b Vec.zero (v 0. 0. 1.) in
  float_eq "from inside: depth" 1. t;
  Alcotest.(check int) "from inside: Z+ side" 6 side;
  vec_eq "from inside: normal" (v 0. 0. 1.) n;
  let t, _, _ = hit b (v 0. 0. 5.) (v 0. 0. 1.) in
  Alcotest.(check bool) "behind the ray" true (t = infinity);
  (* hits below [lo] give way to the far one *)
  let t, side, _ = hit ~lo:4.5 b (v 0. 0. (-5.)) (v 0. 0. 1.) in
  float_eq "far hit beyond lo" 6. t;
  Alcotest.(check int) "far side" 6 side;
  (* the near crossing counts only beyond 1e-6 (DEPTH_TOLERANCE), the far one always *)
  let t, side, _ = hit b (v 0. 0. (-1. -. 5e-7)) (v 0. 0. 1.) in
  float_eq ~eps:1e-15 "near crossing within 1e-6 skipped" (2. +. 5e-7) t;
  Alcotest.(check int) "so the far side" 6 side

let test_face_normals () =
  let b = setup unit_box in
  let cases =
    [
      ("X-", v (-5.) 0.2 0.1, v 1. 0. 0., 1, v (-1.) 0. 0.);
      ("X+", v 5. 0.2 0.1, v (-1.) 0. 0., 2, v 1. 0. 0.);
      ("Y-", v 0.2 (-5.) 0.1, v 0. 1. 0., 3, v 0. (-1.) 0.);
      ("Y+", v 0.2 5. 0.1, v 0. (-1.) 0., 4, v 0. 1. 0.);
      ("Z-", v 0.2 0.1 (-5.), v 0. 0. 1., 5, v 0. 0. (-1.));
      ("Z+", v 0.2 0.1 5., v 0. 0. (-1.), 6, v 0. 0. 1.);
    ]
  in
  List.iter
    (fun (name, o, d, s, n) ->
      let t, side, nn = hit b o d in
      float_eq (name ^ " depth") 4. t;
      Alcotest.(check int) (name ^ " side") s side;
      vec_eq (name ^ " normal") n nn)
    cases

let test_parallel () =
  let b = setup unit_box in
  (* along a face's plane: the slab test is inclusive, so the face's own plane is in the box *)
  let t, side, _ = hit b (v (-5.) 1. 0.) (v 1. 0. 0.) in
  float_eq "in the top face's plane" 4. t;
  Alcotest.(check int) "enters through X-" 1 side;
  let t, _, _ = hit b (v (-5.) (1. +. 1e-12) 0.) (v 1. 0. 0.) in
  Alcotest.(check bool) "just above the top face" true (t = infinity);
  let t, _, _ = hit b (v (-5.) 0. (-1. -. 1e-12)) (v 1. 0. 0.) in
  Alcotest.(check bool) "just outside the front face" true (t = infinity)

let test_edges_and_corners () =
  let b = setup unit_box in
  (* a ray along the edge x = 1 of the front face grazes it: it enters through Z- *)
  let t, side, _ = hit b (v 1. 0. (-5.)) (v 0. 0. 1.) in
  float_eq "edge graze depth" 4. t;
  Alcotest.(check int) "edge graze side" 5 side;
  let t, _, _ = hit b (v (1. +. 1e-9) 0. (-5.)) (v 0. 0. 1.) in
  Alcotest.(check bool) "past the edge" true (t = infinity);
  (* through the edge x = z = −1: crossings within 1e-6 keep the side found first (X-) unless the
     ray is steeper towards the new one *)
  let edge = v (-1.) 0. (-1.) in
  let through d = Vec.madd edge (-3.) (Vec.normalize d) in
  let t, side, _ = hit b (through (v 1. 0. 1.)) (v 1. 0. 1.) in
  float_eq ~eps:1e-12 "edge, equally steep: depth" 3. t;
  Alcotest.(check int) "edge, equally steep: X- kept" 1 side;
  let _, side, _ = hit b (through (v 1. 0. 1.01)) (v 1. 0. 1.01) in
  Alcotest.(check int) "edge, steeper in z: Z-" 5 side;
  (* through the corner −1,−1,−1: Y steeper than X takes the side; Z is compared with Y then *)
  let corner = v (-1.) (-1.) (-1.) in
  let through d = Vec.madd corner (-3.) (Vec.normalize d) in
  let _, side, _ = hit b (through (v 1. 1. 1.)) (v 1. 1. 1.) in
  Alcotest.(check int) "corner, equally steep: X-" 1 side;
  let _, side, _ = hit b (through (v 1. 1.02 1.01)) (v 1. 1.02 1.01) in
  Alcotest.(check int) "corner, steepest in y: Y-" 3 side;
  let _, side, _ = hit b (through (v 1. 1.01 1.02)) (v 1. 1.01 1.02) in
  Alcotest.(check int) "corner, steepest in z: Z-" 5 side;
  (* a ray that only touches the edge x = −1, y = 1 enters and leaves at the same depth: of the two
     equal crossings POV-Ray keeps the far one (pushed last, taken first), whose side is Y+ *)
  let t, side, _ = hit b (v (-2.) 0. 0.) (v 1. 1. 0.) in
  float_eq ~eps:1e-12 "touching an edge: depth" (sqrt 2.) t;
  Alcotest.(check int) "touching an edge: the far crossing's Y+" 4 side;
  (* the robust mode decides the tie exactly: a ray that crosses the plane x = −1 1e-7 inside the
     front face's edge enters through X-, which POV-Ray gives to the steeper Z- *)
  let rb = setup ~robust:true unit_box in
  let o = Vec.madd (v (-1.) 0. (-1. +. 1e-7)) (-3.) (Vec.normalize (v 1. 0. 1.01)) in
  let _, side, _ = hit b o (v 1. 0. 1.01) in
  Alcotest.(check int) "POV-Ray: within 1e-6, the steeper Z-" 5 side;
  let _, side, _ = hit rb o (v 1. 0. 1.01) in
  Alcotest.(check int) "robust: X- entered last" 1 side

let test_transformed () =
  (* scale is baked (x from −2 to 2), then rotate y*90 maps object x to world −z *)
  let b = setup "box { <-1,-1,-1>, <1,1,1> scale <2,1,1> rotate y*90 translate <0,0,1> }" in
  let t, side, n = hit b (v 0. 0. (-5.)) (v 0. 0. 1.) in
  float_eq ~eps:1e-12 "depth" 4. t;
  Alcotest.(check int) "object side X+" 2 side;
  vec_eq ~eps:1e-12 "world normal" (v 0. 0. (-1.)) n;
  let t, _, n = hit b (v 5. 0.5 1.5) (v (-1.) 0. 0.) in
  float_eq ~eps:1e-12 "from +x: depth" 4. t;
  vec_eq ~eps:1e-12 "from +x: normal" (v 1. 0. 0.) n;
  (* a non-uniform scale after the rotation: the normal goes through the inverse transpose *)
  let b = setup "box { 0, 1 rotate z*45 scale <1,2,1> }" in
  let _, _, n = hit b (v (-5.) 0.5 0.5) (v 1. 0. 0.) in
  (* the face x' = 0 after rotate z*45 has normal <−1,−1,0>/√2; scaled by <1,2,1> its normal is
     ∝ <−1,−1/2,0> *)
  vec_eq ~eps:1e-12 "sheared normal" (Vec.normalize (v (-1.) (-0.5) 0.)) n

let test_inside () =
  let inside_t msg expected text p =
    Alcotest.(check bool) msg expected (Shape.inside (Array.make 512 0.) (fst (setup text)).shape p)
  in
  inside_t "centre" true unit_box Vec.zero;
  inside_t "on a face" true unit_box (v 1. 0. 0.);
  inside_t "on a corner" true unit_box (v 1. 1. 1.);
  inside_t "just outside" false unit_box (v (1. +. 1e-12) 0. 0.);
  let rotated = "box { <0,0,0>, <2,1,1> rotate y*90 }" in
  (* rotate y*90: object <x,y,z> is world <z,y,−x>; world <0.5,0.5,−1.5> is object <1.5,0.5,0.5> *)
  inside_t "rotated: inside" true rotated (v 0.5 0.5 (-1.5));
  inside_t "rotated: outside" false rotated (v 1.5 0.5 0.5)

let test_stats () =
  let ((_, ctx) as b) = setup unit_box in
  ignore (hit b (v 0. 0. (-5.)) (v 0. 0. 1.));
  ignore (hit b (v 0. 5. (-5.)) (v 0. 0. 1.));
  Alcotest.(check int) "tests" 2 (Stats.tests ctx.stats Stats.box);
  Alcotest.(check int) "hits" 1 (Stats.hits ctx.stats Stats.box)

let tests =
  [
    Alcotest.test_case "parse and place" `Quick test_parse;
    Alcotest.test_case "from outside and inside" `Quick test_outside_and_inside;
    Alcotest.test_case "face normals" `Quick test_face_normals;
    Alcotest.test_case "parallel to a face" `Quick test_parallel;
    Alcotest.test_case "edges and corners" `Quick test_edges_and_corners;
    Alcotest.test_case "transformed" `Quick test_transformed;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "statistics" `Quick test_stats;
  ]
