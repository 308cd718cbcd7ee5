(* Cylinders, cones and discs (docs/povray-rules.md §15.2–§15.4): the canonical set-up, every hit listed in
   POV-Ray's order with its part, the nearest one, normals, the inside tests, and the errors.
   Every expected value is worked out by hand in the comments. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let setup text =
  let c = compile (v37 ^ text) in
  (c.objects.(0), Trace.make_ctx c (Stats.create ()))

let cone_of (obj : Compiled.obj) = match obj.shape with Cone c -> c | _ -> Alcotest.fail "expected a cylinder or cone"
let disc_of (obj : Compiled.obj) = match obj.shape with Disc d -> d | _ -> Alcotest.fail "expected a disc"

(* Every hit of the ray from [o] along [d] (normalised here): (depth, part) in POV-Ray's order. *)
let all_hits (obj, ctx) o d =
  let d = Vec.normalize d in
  let out = Array.make 8 nan in
  let n =
    match obj.Compiled.shape with
    | Cone c -> Cone.crossings ctx.Context.shapes c o d out
    | Disc dc -> Disc.crossings ctx.Context.shapes dc o d out
    | _ -> Alcotest.fail "expected a quadric"
  in
  List.init n (fun i -> (out.(2 * i), int_of_float out.((2 * i) + 1)))

let hits_eq ?(eps = 1e-12) msg expected actual =
  Alcotest.(check int) (msg ^ ": count") (List.length expected) (List.length actual);
  List.iteri
    (fun i ((te, pe), (ta, pa)) ->
      float_eq ~eps (Printf.sprintf "%s: depth %d" msg i) te ta;
      Alcotest.(check int) (Printf.sprintf "%s: part %d" msg i) pe pa)
    (List.combine expected actual)

(* The nearest hit at least [lo]: depth, part and unit normal. *)
let hit ?(lo = 0.) (obj, ctx) o d =
  let d = Vec.normalize d in
  ctx.Context.shapes.part <- -1;
  let t = Shape.depth ctx.Context.shapes obj.Compiled.shape o d lo in
  let part = ctx.Context.shapes.part in
  (t, part, if t < infinity then Shape.normal ctx.Context.shapes obj part (Vec.madd o t d) else Vec.zero)

let inside (obj : Compiled.obj) p = Shape.inside (Array.make 512 0.) obj.shape p
let base = 1 and cap = 2 and side = 3

(* P2 at the origin, P1 = (0,0,2) along +z: the rotation is the identity (acos 1 = 0), so the
   transform is exactly scale <1,1,2>; canonical z = world z / 2. P2's end (world z = 0) is the
   base (part 1), P1's (world z = 2) the cap (part 2). *)
let c1 = "cylinder { <0,0,2>, <0,0,0>, 1 }"

let test_cylinder_setup () =
  (* §15.2: P2 maps to z = 0, P1 to z = 1, radius 1 along x and y *)
  let obj, _ = setup "cylinder { <1,2,3>, <1,2,5>, 0.5 }" in
  let c = cone_of obj in
  Alcotest.(check bool) "a cylinder" true c.cyl;
  Alcotest.(check bool) "closed" true c.closed;
  vec_eq ~eps:1e-12 "P2 at z = 0" (v 1. 2. 5.) (Transform.point c.ctr Vec.zero);
  vec_eq ~eps:1e-12 "P1 at z = 1" (v 1. 2. 3.) (Transform.point c.ctr (v 0. 0. 1.));
  vec_eq ~eps:1e-12 "radius along x" (v 1.5 2. 5.) (Transform.point c.ctr (v 1. 0. 0.));
  (* modifiers compose after the set-up *)
  let obj, _ = setup "cylinder { 0, y, 1 open translate x }" in
  let c = cone_of obj in
  Alcotest.(check bool) "open" false c.closed;
  vec_eq ~eps:1e-12 "moved P2" (v 1. 1. 0.) (Transform.point c.ctr Vec.zero);
  (* the exact canonical transform of an axis along +z: scale <1,1,2> *)
  let c = cone_of (fst (setup c1)) in
  vec_eq "exact" (v 1. 1. 2.) (Transform.point c.ctr (v 1. 1. 1.))

let test_cylinder_hits () =
  let s = setup c1 in
  (* along the axis from outside: no side (a = 0), the cap (s = 3.5 in canonical units, over
     len 0.5 → 7) then the base (s = 2.5 → 5), listed in that order *)
  hits_eq "along the axis" [ (7., cap); (5., base) ] (all_hits s (v 0. 0. (-5.)) (v 0. 0. 1.));
  let t, part, n = hit s (v 0. 0. (-5.)) (v 0. 0. 1.) in
  float_eq "nearest: the base" 5. t;
  Alcotest.(check int) "base part" base part;
  vec_eq "base normal" (v 0. 0. (-1.)) n;
  (* from inside along the axis: the cap at 1; the base is behind *)
  hits_eq "from inside to the cap" [ (1., cap) ] (all_hits s (v 0. 0. 1.) (v 0. 0. 1.));
  let _, part, n = hit s (v 0. 0. 1.) (v 0. 0. 1.) in
  Alcotest.(check int) "cap part" cap part;
  vec_eq "cap normal" (v 0. 0. 1.) n;
  (* across the side, parallel to the caps: a = 1, b = −5, c = 24, d = 1; roots 6 then 4 *)
  hits_eq "across" [ (6., side); (4., side) ] (all_hits s (v (-5.) 0. 1.) (v 1. 0. 0.));
  let t, part, n = hit s (v (-5.) 0. 1.) (v 1. 0. 0.) in
  float_eq "nearest side" 4. t;
  Alcotest.(check int) "side part" side part;
  vec_eq "side normal" (v (-1.) 0. 0.) n;
  (* from inside across: only the far root (the other is −1, behind) *)
  hits_eq "from inside across" [ (1., side) ] (all_hits s (v 0. 0. 1.) (v 1. 0. 0.));
  (* a miss: d = 25 − 1·28 < 0 *)
  hits_eq "miss" [] (all_hits s (v (-5.) 2. 1.) (v 1. 0. 0.));
  (* hits beyond [lo]: the far side *)
  let t, _, n = hit ~lo:5. s (v (-5.) 0. 1.) (v 1. 0. 0.) in
  float_eq "beyond lo" 6. t;
  vec_eq "far side normal" (v 1. 0. 0.) n

let test_cylinder_grazing () =
  let s = setup c1 in
  (* in the plane of the cap (canonical z = 1 exactly): |V.z| = 0, so no end is tested, and the
     side's z ≤ 1 holds: both side crossings count *)
  hits_eq "in the cap plane" [ (6., side); (4., side) ] (all_hits s (v (-5.) 0. 2.) (v 1. 0. 0.));
  (* tangent to the rim of the cap: d = 25 − 25 = 0, a double root at 5 *)
  hits_eq "tangent to the cap's rim" [ (5., side); (5., side) ] (all_hits s (v (-5.) 1. 2.) (v 1. 0. 0.));
  (* just above the cap plane: nothing *)
  hits_eq "above the cap" [] (all_hits s (v (-5.) 0. 2.000001) (v 1. 0. 0.));
  (* straight down the side wall (x = 1, a = 0): no side, and the ends' x² + y² = 1 ≤ 1 count *)
  hits_eq "down the wall" [ (7., cap); (5., base) ] (all_hits s (v 1. 0. (-5.)) (v 0. 0. 1.));
  (* starting on the side: the root at s = 0 is not beyond 1e-9 *)
  hits_eq "on the side, outward" [] (all_hits s (v 1. 0. 1.) (v 1. 0. 0.));
  hits_eq "on the side, inward" [ (2., side) ] (all_hits s (v 1. 0. 1.) (v (-1.) 0. 0.));
  (* an open cylinder has no ends: along the axis nothing, across only the side *)
  let o = setup "cylinder { <0,0,2>, <0,0,0>, 1 open }" in
  hits_eq "open, along the axis" [] (all_hits o (v 0. 0. (-5.)) (v 0. 0. 1.));
  hits_eq "open, inner wall from inside" [ (1., side) ] (all_hits o (v 0. 0. 1.) (v 1. 0. 0.))

(* The cone of radius 1 at world z = 1 and 0.5 at z = 0 (written small end second): h = 1,
   apex at z = −1, H = 2, dist = 0.5; the transform is exactly scale <1,1,2> then translate
   <0,0,−1>, so canonical z = (world z + 1)/2 and the radius at world z is (z + 1)/2. *)
let k1 = "cone { <0,0,1>, 1, <0,0,0>, 0.5 }"

let test_cone_setup () =
  let c = cone_of (fst (setup k1)) in
  Alcotest.(check bool) "a cone" false c.cyl;
  float_eq "dist = 0.5" 0.5 c.dist;
  vec_eq "apex" (v 0. 0. (-1.)) (Transform.point c.ctr Vec.zero);
  vec_eq "big end" (v 1. 0. 1.) (Transform.point c.ctr (v 1. 0. 1.));
  (* written small end first: swapped, the same cone *)
  let c' = cone_of (fst (setup "cone { <0,0,0>, 0.5, <0,0,1>, 1 }")) in
  float_eq "swapped dist" 0.5 c'.dist;
  vec_eq "swapped apex" (v 0. 0. (-1.)) (Transform.point c'.ctr Vec.zero);
  (* equal radii: a cylinder of that radius *)
  let c = cone_of (fst (setup "cone { <0,0,2>, 0.5, <0,0,0>, 0.5 }")) in
  Alcotest.(check bool) "equal radii: a cylinder" true c.cyl;
  vec_eq "its radius" (v 0.5 0. 0.) (Transform.point c.ctr (v 1. 0. 0.));
  (* radii 1e-11 apart: a cylinder; a taper of (rb − rs)·L/H = 1e-10 · 1e-9/(1 + 1e-9)… below
     1e-10: a cylinder of the big radius too, although the radii differ by more than 1e-10 *)
  let c = cone_of (fst (setup "cone { <0,0,2>, 0.5, <0,0,0>, 0.50000000001 }")) in
  Alcotest.(check bool) "radii within 1e-10" true c.cyl;
  let c = cone_of (fst (setup "cone { <0,0,1e-3>, 1, <0,0,0>, 0.9999999 }")) in
  (* h = 0.9999999·1e-3/1e-7 ≈ 1e4, H ≈ 1e4, so the taper is 1e-7·1e-3/1e4 = 1e-14 *)
  Alcotest.(check bool) "so thin a taper" true c.cyl;
  vec_eq ~eps:1e-12 "of the big radius, from the small end" (v 1. 0. 0.) (Transform.point c.ctr (v 1. 0. 0.));
  (* r1 = 0: the point at the small end, dist = 0 *)
  let c = cone_of (fst (setup "cone { <0,0,0>, 0, <0,0,1>, 1 }")) in
  Alcotest.(check bool) "pointed: a cone" false c.cyl;
  float_eq "pointed: dist 0" 0. c.dist

let test_cone_hits () =
  let s = setup k1 in
  (* along the axis: the side's double root is the apex (canonical z = 0 < dist: dropped); the cap
     at s = 3 → 6, the base at s = 2.5 → 5 *)
  hits_eq "along the axis" [ (6., cap); (5., base) ] (all_hits s (v 0. 0. (-5.)) (v 0. 0. 1.));
  (* across at world z = 0.5 (radius 0.75): a = 1, b = −5, c = 25 − 0.5625, d = 0.5625; the near
     root (5 − 0.75) first for a cone *)
  hits_eq "across" [ (4.25, side); (5.75, side) ] (all_hits s (v (-5.) 0. 0.5) (v 1. 0. 0.));
  (* the side normal (x, y, −z) = (−0.75, 0, −0.75) through the inverse transpose diag(1,1,½):
     (−0.75, 0, −0.375), normalised (−2, 0, −1)/√5 *)
  let t, part, n = hit s (v (-5.) 0. 0.5) (v 1. 0. 0.) in
  float_eq "nearest" 4.25 t;
  Alcotest.(check int) "side" side part;
  vec_eq ~eps:1e-12 "side normal" (Vec.scale (1. /. sqrt 5.) (v (-2.) 0. (-1.))) n;
  (* parallel to a generator (a = 0 exactly): one root −c/(2b). From canonical (−1.5, 0, 0) along
     (1,0,1)/√2 it meets x = −z at (−0.75, 0, 0.75): s = 0.75√2, over len √2/√5 → 0.75√5; the cap
     at s = √2 → √5 (x = −0.5 inside); the base misses (x = −1, r² = 1 > 0.25) *)
  hits_eq ~eps:1e-12 "parallel to a generator"
    [ (0.75 *. sqrt 5., side); (sqrt 5., cap) ]
    (all_hits s (v (-1.5) 0. (-1.)) (v 1. 0. 2.));
  (* below the small end: the lower nappe is cut away *)
  hits_eq "below" [] (all_hits s (v (-5.) 0. (-0.5)) (v 1. 0. 0.));
  (* the pointed cone along its axis: the double root at the apex (z = 0 = dist, kept twice), the
     cap at 6, the base point (r² = 0 ≤ dist² = 0) at 5; of the equal depths the last listed, the
     base, is the nearest *)
  let p = setup "cone { <0,0,0>, 0, <0,0,1>, 1 }" in
  hits_eq "pointed" [ (5., side); (5., side); (6., cap); (5., base) ] (all_hits p (v 0. 0. (-5.)) (v 0. 0. 1.));
  let t, part, _ = hit p (v 0. 0. (-5.)) (v 0. 0. 1.) in
  float_eq "pointed: nearest" 5. t;
  Alcotest.(check int) "pointed: the last of equal depths" base part

(* The ring 1 ≤ r ≤ 2 in the plane z = 0, normal +z: the canonical transform is the identity. *)
let d1 = "disc { <0,0,0>, <0,0,1>, 2, 1 }"

let test_disc () =
  let s = setup d1 in
  let t, _, n = hit s (v 1.5 0. (-3.)) (v 0. 0. 1.) in
  float_eq "front" 3. t;
  vec_eq "normal as given" (v 0. 0. 1.) n;
  let t, _, _ = hit s (v 1.5 0. 3.) (v 0. 0. (-1.)) in
  float_eq "from behind" 3. t;
  hits_eq "through the hole" [] (all_hits s (v 0. 0. (-3.)) (v 0. 0. 1.));
  hits_eq "on the hole's rim (r² = 1 = hole²)" [ (3., 0) ] (all_hits s (v 1. 0. (-3.)) (v 0. 0. 1.));
  hits_eq "on the outer rim (r² = 4)" [ (3., 0) ] (all_hits s (v 2. 0. (-3.)) (v 0. 0. 1.));
  hits_eq "just outside" [] (all_hits s (v 2.000001 0. (-3.)) (v 0. 0. 1.));
  hits_eq "parallel, in its plane" [] (all_hits s (v (-5.) 1.5 0.) (v 1. 0. 0.));
  (* world depth at most 1e-6 is not a hit *)
  hits_eq "within 1e-6" [] (all_hits s (v 1.5 0. (-5e-7)) (v 0. 0. 1.));
  (* the normal follows every modifier: the plane x + y = 0 scaled by <2,1,1> is x/2 + y = 0 *)
  let d = disc_of (fst (setup "disc { 0, <1,1,0>, 1 scale <2,1,1> }")) in
  vec_eq ~eps:1e-12 "moved normal" (Vec.scale (1. /. sqrt 1.25) (v 0.5 1. 0.)) (v d.dnx d.dny d.dnz);
  (* a normal within 1e-10 of ±z (here z = −1/√(1 + 1e-10)) is snapped to it by the set-up *)
  let d = disc_of (fst (setup "disc { 0, <1e-5, 0, -1>, 1 }")) in
  float_eq ~eps:0. "snapped z" (-1.) d.dnz;
  (* a disc without a hole: hole² = 0 *)
  let d = disc_of (fst (setup "disc { 0, y, 3 }")) in
  float_eq "no hole" 0. d.ir2;
  float_eq "radius²" 9. d.or2

let test_inside () =
  (* closed: shrunk by EPSILON *)
  let c, _ = setup c1 in
  Alcotest.(check bool) "centre" true (inside c (v 0. 0. 1.));
  Alcotest.(check bool) "on the side: out when closed" false (inside c (v 1. 0. 1.));
  Alcotest.(check bool) "on the cap: out when closed" false (inside c (v 0. 0. 2.));
  Alcotest.(check bool) "just inside the side" false (inside c (v 0.99999999996 0. 1.));
  Alcotest.(check bool) "inside the shrunk side" true (inside c (v 0.9999999999 0. 1.));
  (* open: grown by EPSILON, and still solid *)
  let o, _ = setup "cylinder { <0,0,2>, <0,0,0>, 1 open }" in
  Alcotest.(check bool) "open centre" true (inside o (v 0. 0. 1.));
  Alcotest.(check bool) "open: on the side is in" true (inside o (v 1. 0. 1.));
  Alcotest.(check bool) "open: a hair below the base is in" true (inside o (v 0. 0. (-1e-10)));
  Alcotest.(check bool) "open: beyond the growth" false (inside o (v 0. 0. (-1e-9)));
  (* inverse negates *)
  let i, _ = setup "cylinder { <0,0,2>, <0,0,0>, 1 inverse }" in
  Alcotest.(check bool) "inverse centre" false (inside i (v 0. 0. 1.));
  Alcotest.(check bool) "inverse outside" true (inside i (v 5. 0. 1.));
  (* the cone: radius (z + 1)/2 at world z *)
  let k, _ = setup k1 in
  Alcotest.(check bool) "cone axis" true (inside k (v 0. 0. 0.5));
  Alcotest.(check bool) "cone within" true (inside k (v 0.74 0. 0.5));
  Alcotest.(check bool) "cone beyond" false (inside k (v 0.76 0. 0.5));
  Alcotest.(check bool) "below the small end" false (inside k (v 0. 0. (-0.1)));
  (* the disc: the open half-space behind the normal, unbounded *)
  let d, _ = setup d1 in
  Alcotest.(check bool) "behind" true (inside d (v 0. 0. (-1.)));
  Alcotest.(check bool) "far behind, off the disc" true (inside d (v 100. 100. (-1.)));
  Alcotest.(check bool) "on the plane: out" false (inside d (v 1.5 0. 0.));
  Alcotest.(check bool) "in front" false (inside d (v 0. 0. 1.));
  let di, _ = setup "disc { <0,0,0>, <0,0,1>, 2 inverse }" in
  Alcotest.(check bool) "inverse disc in front" true (inside di (v 0. 0. 1.))

let test_camera_start () =
  (* §6.4: a camera inside a glass cylinder starts inside it; behind a disc but outside the disc's
     box it does not (POV-Ray asks the box first) *)
  let scene cam = compile (v37 ^ Printf.sprintf "camera { location %s look_at <0,0,5> }\n" cam ^ "cylinder { <0,0,-3>, <0,0,3>, 2 }\ndisc { <0,0,4>, z, 1 }\n") in
  Alcotest.(check (list int)) "inside the cylinder" [ 0 ] (scene "<0,0,0>").start_interiors;
  Alcotest.(check (list int)) "outside both" [] (scene "<0,5,0>").start_interiors;
  Alcotest.(check (list int)) "within the disc's box, behind it" [ 1 ] (scene "<0.5,0,3.9995>").start_interiors

let test_slab_tree () =
  (* three unit boxes along z, written out of order: find_axis picks z (its recorded spread is 4,
     x's and y's 0), they are sorted by centre, and three fit one node *)
  let b z = [| 0.; 0.; z; 1.; 1.; 1. |] in
  let t = Slab_tree.build [ (0, b 4.); (1, b 0.); (2, b 2.) ] [ 7 ] in
  Alcotest.(check (list int)) "sorted, the unbounded first" [ 7; 1; 2; 0 ] (Slab_tree.walk t (fun _ -> true));
  Alcotest.(check (list int)) "a box that does not hold the point" [ 7; 1; 0 ] (Slab_tree.walk t (fun bx -> bx.(2) <> 2.));
  (* six boxes along x, 10 apart: the surface-area rule splits after the third (costs 418, 298,
     258, 298, 418 against 309 unsplit), so the first three share a node of box x 0 … 21 *)
  let row = List.init 6 (fun i -> (5 - i, [| float_of_int (10 * (5 - i)); 0.; 0.; 1.; 1.; 1. |])) in
  let t = Slab_tree.build row [] in
  Alcotest.(check (list int)) "in x order" [ 0; 1; 2; 3; 4; 5 ] (Slab_tree.walk t (fun _ -> true));
  Alcotest.(check (list int)) "the first node left out" [ 3; 4; 5 ] (Slab_tree.walk t (fun bx -> not (bx.(0) = 0. && bx.(3) = 21.)))

let test_slab_queue () =
  (* Intersect_BBox_Tree's priority queue: four boxes in one node, three entered at depth 10 by
     a ray along z and one at depth 20. They are queued in the node's order 0, 1, 2, 3; the heap
     hands out 0, moves its last entry (3) to the top and lets it sink under the right child (2)
     of two equal ones; so 2 comes before 1. *)
  let b z len = [| 0.; 0.; z; 1.; 1.; len |] in
  let boxes = [ (0, b 0. 1.); (1, b 0. 2.); (2, b 0. 3.); (3, b 10. 1.) ] in
  let o = v 0.5 0.5 (-10.) and d = v 0. 0. 1. in
  let order t o =
    let l = ref [] in
    Slab_tree.search t (Slab_tree.room ()) o d (fun () -> infinity) (fun id -> l := id :: !l);
    List.rev !l
  in
  let t = Slab_tree.build boxes [] in
  Alcotest.(check (list int)) "0, 2, 1, 3" [ 0; 2; 1; 3 ] (order t o);
  (* from within the last box, beyond the others: they are never met *)
  Alcotest.(check (list int)) "boxes behind the ray are never met" [ 3 ] (order t (v 0.5 0.5 10.5));
  (* with two planes the root also holds their node, queued at −MAX_DISTANCE: the planes come
     first, and the moves they cause leave the boxes in the order 0, 2, 1, 3 again *)
  let t = Slab_tree.build boxes [ 7; 8 ] in
  Alcotest.(check (list int)) "7, 8, 0, 2, 1, 3" [ 7; 8; 0; 2; 1; 3 ] (order t o)

let test_slab_search () =
  (* the search in POV-Ray's order: the same boxes and ray as above, every leaf popped while
     the best depth stays beyond them; with the best at 15 the walk ends before box 3 (entered at
     20); Pov_box.entry_from, the Rayinfo computed once, gives entry's floats on random rays *)
  let b z len = [| 0.; 0.; z; 1.; 1.; len |] in
  let t = Slab_tree.build [ (0, b 0. 1.); (1, b 0. 2.); (2, b 0. 3.); (3, b 10. 1.) ] [ 7 ] in
  let room = Slab_tree.room () in
  let seen limit =
    let l = ref [] in
    Slab_tree.search t room (v 0.5 0.5 (-10.)) (v 0. 0. 1.) (fun () -> limit) (fun id -> l := id :: !l);
    List.rev !l
  in
  Alcotest.(check (list int)) "7, 0, 2, 1, 3" [ 7; 0; 2; 1; 3 ] (seen infinity);
  Alcotest.(check (list int)) "ends at the best depth" [ 7; 0; 2; 1 ] (seen 15.);
  let rng = Random.State.make [| 20 |] in
  let r () = Random.State.float rng 8. -. 4. in
  let ri = Pov_box.ray_info () in
  for _ = 1 to 2000 do
    let bx = Pov_box.of_min_max [| r (); r (); r () |] [| 4.5; 4.5; 4.5 |] in
    let o = v (r ()) (r ()) (r ()) in
    let d = Vec.normalize (v (if Random.State.bool rng then 0. else r ()) (r ()) (r ())) in
    Pov_box.set_ray ri o d;
    let e = Pov_box.entry bx o d and f = Pov_box.entry_from ri bx in
    if not (Int64.equal (Int64.bits_of_float e) (Int64.bits_of_float f)) then Alcotest.failf "entry %h, entry_from %h" e f
  done

let test_camera_order () =
  (* §6.4: the camera inside a closed glass cylinder (written first) and an open one: POV-Ray's
     tree sorts them along z, the open one (centre z = −1) before the closed one (z = −0.25), so
     the closed one is found last: it is the last entered, whatever the order written *)
  let text first second =
    "camera { location <0, 1, -1> look_at <0, 0.8, 3> }\nsphere { <0.8, 0.8, 4>, 0.7 }\nbox { <-1.8, 0, 3.5>, <-0.6, 1.6, 4.5> }\nplane { y, 0 }\n"
    ^ first ^ "\n" ^ second ^ "\n"
  in
  let closed = "cylinder { <0, 0.2, -2>, <0, 0.2, 1.5>, 1.5 }" and opened = "cylinder { <0, -1, -1>, <0, 3, -1>, 0.5 open }" in
  Alcotest.(check (list int)) "closed written first" [ 3; 4 ] (compile (v37 ^ text closed opened)).start_interiors;
  Alcotest.(check (list int)) "closed written last" [ 4; 3 ] (compile (v37 ^ text opened closed)).start_interiors

let test_errors () =
  expect_scene_error "degenerate cylinder" "cylinder { y, y, 1 }" ~line:1 ~col:1 ~sub:"degenerate cylinder";
  expect_scene_error "almost degenerate cylinder" "cylinder { 0, 1e-11*x, 1 }" ~line:1 ~col:1 ~sub:"degenerate cylinder";
  expect_scene_error "degenerate cone" "cone { y, 1, y, 2 }" ~line:1 ~col:1 ~sub:"degenerate cone";
  expect_scene_error "zero disc normal" "disc { 0, 0, 1 }" ~line:1 ~col:11 ~sub:"degenerate disc normal";
  (* a cylinder barely longer than 1e-10 is accepted *)
  ignore (scene "cylinder { 0, 1e-9*x, 1 }")

let test_stats () =
  let ((_, ctx) as s) = setup c1 in
  ignore (hit s (v 0. 0. (-5.)) (v 0. 0. 1.));
  ignore (hit s (v (-5.) 5. 1.) (v 1. 0. 0.));
  Alcotest.(check int) "tests" 2 (Stats.tests ctx.stats Stats.cone);
  Alcotest.(check int) "hits" 1 (Stats.hits ctx.stats Stats.cone);
  let ((_, ctx) as s) = setup d1 in
  ignore (hit s (v 1.5 0. (-3.)) (v 0. 0. 1.));
  ignore (hit s (v 0. 0. (-3.)) (v 0. 0. 1.));
  Alcotest.(check int) "disc tests" 2 (Stats.tests ctx.stats Stats.disc);
  Alcotest.(check int) "disc hits" 1 (Stats.hits ctx.stats Stats.disc)

let test_own_box () =
  (* four cylinders along y at x = −3, −1, 1, 3 (radius 0.4) share one leaf of the scene's
     hierarchy (leaves hold up to 4), whose box spans x in [−3.4, 3.4]; each is tried only when
     the ray meets its own box, x in [x − 0.4, x + 0.4], y in [0, 1], z in [−0.4, 0.4] *)
  let c =
    compile
      (v37 ^ "cylinder { <-3,0,0>, <-3,1,0>, 0.4 }\ncylinder { <-1,0,0>, <-1,1,0>, 0.4 }\n"
     ^ "cylinder { <1,0,0>, <1,1,0>, 0.4 }\ncylinder { <3,0,0>, <3,1,0>, 0.4 }\n")
  in
  let run o d =
    let ctx = Trace.make_ctx c (Stats.create ()) in
    ignore (Trace.trace ctx ~level:0 ~weight:1. ~interiors:[] ~continued:false o d);
    (Stats.tests ctx.stats Stats.cone, Stats.hits ctx.stats Stats.cone)
  in
  (* x = 0 lies in the leaf's box between the boxes of the cylinders at −1 and 1 *)
  Alcotest.(check (pair int int)) "through the gap" (0, 0) (run (v 0. 0.5 (-5.)) (v 0. 0. 1.));
  (* x = 1: only that cylinder's box is met *)
  Alcotest.(check (pair int int)) "on the cylinder at x = 1" (1, 1) (run (v 1. 0.5 (-5.)) (v 0. 0. 1.));
  (* along x at y = 0.5, z = 0: all four boxes are met; the nearest (x = −3, front at −3.4) is
     hit first, and the other boxes, beyond it, are not tried *)
  Alcotest.(check (pair int int)) "along the row" (1, 1) (run (v (-10.) 0.5 0.) (v 1. 0. 0.));
  (* grazing the top face of the boxes (y = 1 exactly) at x = 1: the box is met, the cylinder's
     cap is touched at its rim *)
  let tests, _ = run (v 1. 1. (-5.)) (v 0. 0. 1.) in
  Alcotest.(check int) "on the box face" 1 tests

let tests =
  [
    Alcotest.test_case "cylinder set-up" `Quick test_cylinder_setup;
    Alcotest.test_case "cylinder hits" `Quick test_cylinder_hits;
    Alcotest.test_case "cylinder grazing rays" `Quick test_cylinder_grazing;
    Alcotest.test_case "cone set-up" `Quick test_cone_setup;
    Alcotest.test_case "cone hits" `Quick test_cone_hits;
    Alcotest.test_case "disc" `Quick test_disc;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "camera's starting interiors" `Quick test_camera_start;
    Alcotest.test_case "POV-Ray's bounding-slab tree" `Quick test_slab_tree;
    Alcotest.test_case "POV-Ray's bounding-tree queue order" `Quick test_slab_queue;
    Alcotest.test_case "POV-Ray's search through its tree" `Quick test_slab_search;
    Alcotest.test_case "order of the camera's interiors" `Quick test_camera_order;
    Alcotest.test_case "errors" `Quick test_errors;
    Alcotest.test_case "statistics" `Quick test_stats;
    Alcotest.test_case "a shape's own box before the shape" `Quick test_own_box;
  ]
