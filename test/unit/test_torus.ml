(* The torus (docs/povray-rules.md §15.5): parsing and placing, the intersection (every depth, the nearest,
   the thick-cylinder pre-test, the closer shift, the 1e-4 world depth limit, root elimination
   for rays leaving the surface), the normal, the closed inside test, the bounding box and the
   statistics. Depths are computed by hand for R = 1, r = 0.25: the tube crosses the X axis at
   x = ±0.75 and ±1.25. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

(* A torus's parameters and whether it is inside out: an inverted primitive enters the scene as an
   intersection of itself alone with the member inverted (§16.3). *)
let rec torus_of (o : Scene.obj) =
  match o.shape with
  | Torus { major; minor; sturm; trans } -> (major, minor, sturm, false, trans)
  | Csg { kind = Intersection; members = [ m ]; _ } ->
      let major, minor, sturm, inverse, trans = torus_of m.mobj in
      (major, minor, sturm, inverse <> m.inverted, trans)
  | _ -> Alcotest.fail "expected a torus"

let vec_eq ?(eps = 1e-12) msg (e : Vec.t) (a : Vec.t) =
  float_eq ~eps (msg ^ " x") e.x a.x;
  float_eq ~eps (msg ^ " y") e.y a.y;
  float_eq ~eps (msg ^ " z") e.z a.z

let setup ?(robust = false) text =
  let c = compile (v37 ^ text) in
  (c.objects.(0), Trace.make_ctx ~robust c (Stats.create ()))

let tor (obj : Compiled.obj) = match obj.shape with Torus t -> t | _ -> Alcotest.fail "expected a compiled torus"

(* the nearest depth at least [lo] and the normal there *)
let hit ?(lo = 0.) (obj, ctx) o d =
  let d = Vec.normalize d in
  let t = Shape.depth ctx.Context.shapes obj.Compiled.shape o d lo in
  (t, if t < infinity then Shape.normal ctx.Context.shapes obj (-1) (Vec.madd o t d) else Vec.zero)

(* every depth, sorted *)
let all (obj, ctx) o d =
  let out = Array.make 4 nan in
  let n = Torus.crossings ctx.Context.shapes (tor obj) o (Vec.normalize d) out in
  List.sort compare (Array.to_list (Array.sub out 0 n))

let check_depths ?(eps = 1e-9) msg expected actual =
  Alcotest.(check int) (msg ^ ": count") (List.length expected) (List.length actual);
  List.iter2 (fun e a -> float_eq ~eps msg e a) expected actual

let ring = "torus { 1, 0.25 }"

let test_parse () =
  let major, minor, sturm, inverse, trans = torus_of (the_object (scene "torus { 2, 0.5 }")) in
  float_eq "R" 2. major;
  float_eq "r" 0.5 minor;
  Alcotest.(check bool) "no sturm" false sturm;
  Alcotest.(check bool) "not inverse" false inverse;
  Alcotest.(check bool) "identity" true (Transform.is_identity trans);
  (* the comma is optional; sturm and inverse anywhere among the modifiers; inverse toggles *)
  let _, minor, sturm, inverse, _ = torus_of (the_object (scene "torus { 2 0.5 translate x sturm inverse pigment { rgb 1 } }")) in
  float_eq "r without comma" 0.5 minor;
  Alcotest.(check bool) "sturm" true sturm;
  Alcotest.(check bool) "inverse" true inverse;
  let _, _, _, inverse, _ = torus_of (the_object (scene "torus { 2 0.5 inverse inverse }")) in
  Alcotest.(check bool) "inverse twice" false inverse;
  (* every modifier composes into the transform: translate then scale maps the origin to 2x *)
  let _, _, _, _, trans = torus_of (the_object (scene "torus { 1, 0.25 translate x scale 2 }")) in
  vec_eq "translate then scale" (v 2. 0. 0.) (Transform.point trans Vec.zero);
  (* an object copy keeps the flags and can add one *)
  let _, _, sturm, inverse, _ = torus_of (the_object (scene "#declare T = torus { 1, 0.25 sturm }\nobject { T inverse }")) in
  Alcotest.(check bool) "copy: sturm" true sturm;
  Alcotest.(check bool) "copy: inverse" true inverse;
  (* bad syntax: located errors *)
  expect_scene_error "missing minor radius" "torus { 1 }" ~line:1 ~col:11 ~sub:"numeric expression";
  expect_scene_error "three numbers" "torus { 1, 0.25, 2 }" ~line:1 ~col:16 ~sub:"closing 'torus'";
  expect_scene_error "sturm on a sphere" "sphere { 0, 1 sturm }" ~line:1 ~col:15 ~sub:"not supported yet"

let test_all_depths () =
  let t = setup ring in
  (* along the X axis: four crossings, from outside *)
  check_depths "along X" [ 3.75; 4.25; 5.75; 6.25 ] (all t (v (-5.) 0. 0.) (v 1. 0. 0.));
  (* the same with Sturm sequences *)
  check_depths "along X, sturm" [ 3.75; 4.25; 5.75; 6.25 ] (all (setup "torus { 1, 0.25 sturm }") (v (-5.) 0. 0.) (v 1. 0. 0.));
  (* x = 1 along Z: (√(1 + z²) − 1)² ≤ 1/16 for |z| ≤ 0.75 *)
  check_depths "across the tube along Z" [ 4.25; 5.75 ] (all t (v 1. 0. (-5.)) (v 0. 0. 1.));
  (* the geometry module's own entry points agree (for CSG, without statistics) *)
  let obj, _ = t in
  let w = Scratch.create ~robust:false (Stats.create ()) and out = Array.make 4 nan in
  let n = Torus.intersections w (tor obj) ~near:1e-4 (v (-5.) 0. 0.) (v 1. 0. 0.) out in
  check_depths "Torus.intersections" [ 3.75; 4.25; 5.75; 6.25 ] (List.sort compare (Array.to_list (Array.sub out 0 n)));
  float_eq "Torus.nearest beyond 4" 4.25 (Torus.nearest w (tor obj) ~near:1e-4 (v (-5.) 0. 0.) (v 1. 0. 0.) 4.);
  (* the nearest is the first *)
  let d, n = hit t (v (-5.) 0. 0.) (v 1. 0. 0.) in
  float_eq "nearest" 3.75 d;
  vec_eq "outer normal" (v (-1.) 0. 0.) n;
  let d, n = hit ~lo:4. t (v (-5.) 0. 0.) (v 1. 0. 0.) in
  float_eq "nearest beyond lo" 4.25 d;
  vec_eq "inner wall's normal points to the axis" (v 1. 0. 0.) n

let test_thick_cylinder () =
  (* the annulus 0.75 ≤ √(x² + z²) ≤ 1.25, |y| ≤ 0.25 of the ring, squared radii 0.5625 and 1.5625 *)
  let tc p d = Torus.thick_cylinder p (Vec.normalize d) (-0.25) 0.25 0.5625 1.5625 in
  Alcotest.(check bool) "down onto the top cap" true (tc (v 1. 5. 0.) (v 0. (-1.) 0.));
  Alcotest.(check bool) "down the hole" false (tc (v 0. 5. 0.) (v 0. (-1.) 0.));
  Alcotest.(check bool) "down past the outside" false (tc (v 1.3 5. 0.) (v 0. (-1.) 0.));
  Alcotest.(check bool) "level, through the walls" true (tc (v (-5.) 0. 0.) (v 1. 0. 0.));
  Alcotest.(check bool) "level, above the slab" false (tc (v (-5.) 0.3 0.) (v 1. 0. 0.));
  Alcotest.(check bool) "level, on the top plane (closed)" true (tc (v (-5.) 0.25 0.) (v 1. 0. 0.));
  Alcotest.(check bool) "away from it" false (tc (v (-5.) 0. 0.) (v (-1.) 0. 0.));
  Alcotest.(check bool) "from inside the hole, outwards" true (tc (v 0. 0. 0.) (v 1. 0. 0.));
  Alcotest.(check bool) "from inside the slab material, upwards" true (tc (v 1. 0. 0.) (v 0. 1. 0.))

let test_hole_and_axis () =
  let obj, ctx = setup ring in
  (* down the axis through the hole: the pre-test rejects it, the solver is not called *)
  let d, _ = hit (obj, ctx) (v 0. 5. 0.) (v 0. (-1.) 0.) in
  Alcotest.(check bool) "through the hole" true (d = infinity);
  Alcotest.(check int) "pre-test rejected" 0 (Stats.hits ctx.stats Stats.torus_bound);
  (* through the hole at an angle, between the inner walls *)
  let d, _ = hit (obj, ctx) (v (-0.5) 5. 0.) (v 0.1 (-1.) 0.) in
  Alcotest.(check bool) "through the hole, slanted" true (d = infinity);
  (* down the core circle at x = 1: the top and bottom of the tube *)
  check_depths "through the tube from above" [ 4.75; 5.25 ] (all (obj, ctx) (v 1. 5. 0.) (v 0. (-1.) 0.));
  let _, n = hit (obj, ctx) (v 1. 5. 0.) (v 0. (-1.) 0.) in
  vec_eq "top normal" (v 0. 1. 0.) n;
  (* a spindle torus (R < r) meets its own axis at y = ±√(r² − R²) = ±0.4; on the axis the
     core-circle point is taken as 0, so the normal is P itself *)
  let s = setup "torus { 0.3, 0.5 }" in
  (* both are double roots of the quartic (the inner, "lemon" part of the spindle touches the
     outer there), so each comes twice *)
  check_depths ~eps:1e-6 "spindle along its axis" [ 4.6; 4.6; 5.4; 5.4 ] (all s (v 0. 5. 0.) (v 0. (-1.) 0.));
  let _, n = hit s (v 0. 5. 0.) (v 0. (-1.) 0.) in
  vec_eq ~eps:1e-9 "spindle normal on the axis" (v 0. 1. 0.) n

let test_grazing () =
  let t = setup ring in
  (* y = 0.25 touches the top of the tube along the circle of radius 1: just below, the ray
     enters at x = −1 − √(0.25² − y²) *)
  let y = 0.2499 in
  let d, _ = hit t (v (-5.) y 0.) (v 1. 0. 0.) in
  float_eq ~eps:1e-7 "just below the top" (4. -. sqrt ((0.25 *. 0.25) -. (y *. y))) d;
  let d, _ = hit t (v (-5.) 0.2501 0.) (v 1. 0. 0.) in
  Alcotest.(check bool) "just above the top" true (d = infinity);
  (* past the outer equator along Z, x = 1.25 + 1e-6: miss; x = 1.25 − 1e-4: a short chord *)
  let d, _ = hit t (v (1.25 +. 1e-6) 0. (-5.)) (v 0. 0. 1.) in
  Alcotest.(check bool) "just outside the equator" true (d = infinity);
  let d, _ = hit t (v (1.25 -. 1e-4) 0. (-5.)) (v 0. 0. 1.) in
  Alcotest.(check bool) "just inside the equator" true (d > 4.9 && d < 5.)

let test_inside_tube () =
  let t = setup ring in
  (* from the core circle: the tube's wall at distance r in every direction across it *)
  check_depths "from the core along +X" [ 0.25 ] (all t (v 1. 0. 0.) (v 1. 0. 0.));
  check_depths "from the core along −X, across the hole" [ 0.25; 1.75; 2.25 ] (all t (v 1. 0. 0.) (v (-1.) 0. 0.));
  let d, n = hit t (v 1. 0. 0.) (v 0. 1. 0.) in
  float_eq "from the core upwards" 0.25 d;
  vec_eq "top normal" (v 0. 1. 0.) n;
  (* a ray leaving the surface: the root at 0 is eliminated (|c4/c3| < 1e-4), the next crossing
     is found *)
  let obj, ctx = t in
  let d, _ = hit t (v (-1.25) 0. 0.) (v 1. 0. 0.) in
  float_eq "from the surface inwards" 0.5 d;
  Alcotest.(check bool) "root eliminated" true (Torus.eliminated ctx.Context.shapes);
  ignore obj;
  (* a crossing 5e-5 ahead is no hit: its root is eliminated (|c4/c3| ≈ 5e-5 < 1e-4), and the
     1e-4 world depth limit would drop it anyway. Dropping the constant term moves the other
     roots by about the dropped root's size: the next crossing, at 0.50005, comes out near 0.50013 *)
  let d, _ = hit t (v (-1.25 -. 5e-5) 0. 0.) (v 1. 0. 0.) in
  Alcotest.(check bool) "a crossing at 5e-5 is skipped" true (d > 0.5 && d < 0.5003);
  Alcotest.(check bool) "… by root elimination" true (Torus.eliminated ctx.Context.shapes)

let test_transformed () =
  (* scale 2: the world depths are object depths over |V| (§14.5 (b)) *)
  let t = setup "torus { 1, 0.25 scale 2 translate y }" in
  check_depths "scaled" [ 7.5; 8.5; 11.5; 12.5 ] (all t (v (-10.) 1. 0.) (v 1. 0. 0.));
  (* non-uniformly scaled, rotated: the tube of scale <2,1,1> rotated 90° about X stands in the
     XY plane *)
  let t = setup "torus { 1, 0.25 scale <2,1,1> rotate x*90 }" in
  check_depths "non-uniform, rotated" [ 7.5; 8.5; 11.5; 12.5 ] (all t (v (-10.) 0. 0.) (v 1. 0. 0.));
  let d, n = hit t (v 0. 5. 0.) (v 0. (-1.) 0.) in
  float_eq "down the rotated ring" 3.75 d;
  vec_eq ~eps:1e-12 "normal by the inverse transpose" (v 0. 1. 0.) n;
  (* a mirrored torus: outward normals stay outward *)
  let t = setup "torus { 1, 0.25 scale <1,-1.5,0.8> }" in
  let d, n = hit t (v 0.8 5. 0.) (v 0. (-1.) 0.) in
  Alcotest.(check bool) "mirrored: hit from above" true (d < infinity);
  Alcotest.(check bool) "mirrored: normal up" true (n.y > 0.);
  (* a tiny torus scaled up: R = 0.001, r = 0.0001 in torus space. From (−5, 0, 0) along +X the
     origin is moved to x = −(R + 2r) = −0.0012, so k1 = 0.0012² − R² − r² = 4.3e-7, k2 = −0.0012,
     and the constant term k1² − 4R²r² ≈ 1.45e-13 is more than 1e12 times smaller than 1:
     difficult() hands the quartic to Sturm. The ring's crossings are at 3.9, 4.1, 5.9 and 6.1,
     but the Sturm sequence of so small a polynomial loses its remainders' coefficients below
     1e-10, and POV-Ray's solver returns 3 wrong roots: the nearest hit lies beyond 4.1 (the
     scene torus_tiny shows the same pixels as POV-Ray, and 540 differ if difficult() is off) *)
  let t = setup "torus { 0.001, 0.0001 scale 1000 }" in
  let k1 = (0.0012 *. 0.0012) -. (0.001 *. 0.001) -. (0.0001 *. 0.0001) and k2 = -0.0012 in
  let c = [| 1.; 4. *. k2; 2. *. (k1 +. (2. *. k2 *. k2)); 4. *. k2 *. k1; (k1 *. k1) -. (4. *. 1e-6 *. 1e-8) |] in
  Alcotest.(check bool) "tiny torus: difficult" true (Polysolv.difficult c 0);
  let depths = all t (v (-5.) 0. 0.) (v 1. 0. 0.) in
  Alcotest.(check int) "tiny torus: 3 roots" 3 (List.length depths);
  Alcotest.(check bool) "tiny torus: 3.9 and 4.1 lost" true (List.hd depths > 4.1);
  (* the closed form, asked directly, finds the four (in shifted torus units: 1e-4 … 2.3e-3) *)
  let r = Array.make 4 nan in
  Alcotest.(check int) "tiny torus: the quartic finds 4" 4 (Polysolv.quartic (Polysolv.create ()) c 0 r 0);
  List.iter2 (fun e a -> float_eq ~eps:1e-12 "tiny quartic root" e a) [ 0.0001; 0.0003; 0.0021; 0.0023 ] (List.sort compare (Array.to_list r));
  (* from 1000 units: the closer shift keeps the roots exact to 1e-9 *)
  let t = setup ring in
  check_depths ~eps:1e-9 "from far away" [ 999.25; 1000.75 ] (all t (v 1. 0. (-1000.)) (v 0. 0. 1.))

let test_inside () =
  let obj, _ = setup ring in
  let inside p = Shape.inside [||] obj.shape p in
  Alcotest.(check bool) "core circle" true (inside (v 1. 0. 0.));
  Alcotest.(check bool) "outer equator (closed)" true (inside (v 1.25 0. 0.));
  Alcotest.(check bool) "top (closed)" true (inside (v 0. 0.25 (-1.)));
  Alcotest.(check bool) "the hole" false (inside Vec.zero);
  Alcotest.(check bool) "outside" false (inside (v 1.25 0.01 0.));
  let obj, _ = setup "torus { 1, 0.25 inverse }" in
  Alcotest.(check bool) "inverse: core" false (Shape.inside [||] obj.shape (v 1. 0. 0.));
  Alcotest.(check bool) "inverse: the hole" true (Shape.inside [||] obj.shape Vec.zero);
  let obj, _ = setup "torus { 1, 0.25 scale 2 translate x }" in
  Alcotest.(check bool) "transformed: core" true (Shape.inside [||] obj.shape (v 3. 0. 0.))

let test_camera_interiors () =
  (* §6.4: the camera is inside an object only within its bounding box: in the hole of an inverse
     torus it is, far outside the box it is not, though Inside holds there too *)
  let start text = (compile (v37 ^ "camera { location <0, 0.4, 0> look_at z }\n" ^ text)).start_interiors in
  Alcotest.(check (list int)) "in the hole of an inverse torus" [ 0 ] (start "torus { 4, 1 inverse }");
  Alcotest.(check (list int)) "in the hole of a plain torus" [] (start "torus { 4, 1 }");
  Alcotest.(check (list int)) "outside the box of an inverse torus" [] (start "torus { 0.5, 0.2 inverse translate 3*z }");
  Alcotest.(check (list int)) "in the tube" [ 0 ] (start "torus { 0.4, 0.1 rotate x*90 }")

let test_box_and_stats () =
  let obj, ctx = setup ring in
  (* Make_BBox of the torus-space box (single precision), through the identity Trans *)
  Alcotest.(check (array (float 0.))) "bounding box" [| -1.25; -0.25; -1.25; 2.5; 0.5; 2.5 |] obj.pbox;
  ignore (hit (obj, ctx) (v (-5.) 0. 0.) (v 1. 0. 0.));
  ignore (hit (obj, ctx) (v 0. 5. 0.) (v 0. (-1.) 0.));
  ignore (hit (obj, ctx) (v (-1.25) 0. 0.) (v 1. 0. 0.));
  ignore (hit (obj, ctx) (v (-5.) 0.3 0.) (v 1. 0. 0.));
  let s = ctx.stats in
  Alcotest.(check int) "tests" 4 (Stats.tests s Stats.torus);
  (* the ray down the axis and the one above the tube fail the pre-test *)
  Alcotest.(check int) "pre-test passed" 2 (Stats.hits s Stats.torus_bound);
  Alcotest.(check int) "roots tested" 2 (Stats.tests s Stats.roots);
  Alcotest.(check int) "roots eliminated" 1 (Stats.hits s Stats.roots);
  Alcotest.(check int) "found roots" 2 (Stats.hits s Stats.torus)

let tests =
  [
    Alcotest.test_case "parse and place" `Quick test_parse;
    Alcotest.test_case "every depth" `Quick test_all_depths;
    Alcotest.test_case "thick-cylinder pre-test" `Quick test_thick_cylinder;
    Alcotest.test_case "hole and axis" `Quick test_hole_and_axis;
    Alcotest.test_case "grazing rays" `Quick test_grazing;
    Alcotest.test_case "from inside the tube" `Quick test_inside_tube;
    Alcotest.test_case "transformed" `Quick test_transformed;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "interiors around the camera" `Quick test_camera_interiors;
    Alcotest.test_case "bounding box and statistics" `Quick test_box_and_stats;
  ]
