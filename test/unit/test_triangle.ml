(* Triangle: set-up, intersection and smooth normals of standalone triangles (docs/povray-rules.md §2.4,
   §2.5), against values computed by hand. *)

open Helpers

let s2 = sqrt 2.

(* The reference triangle in the plane z = 2: P1 = <-1,-1,2>, P2 = <1,-1,2>, P3 = <0,1,2>,
   counter-clockwise seen from above (signed area (P2−P1)×(P3−P1) = <2,0,0>×<1,2,0> = <0,0,4>). *)
let p1 = v (-1.) (-1.) 2.
let p2 = v 1. (-1.) 2.
let p3 = v 0. 1. 2.

let flat_exn a b c = match Triangle.flat a b c with Some t -> t | None -> Alcotest.fail "expected a triangle with area"
let tri = flat_exn p1 p2 p3
let plus_z = v 0. 0. 1.

(* [check_depth msg e a]: [a] is the depth [e], or a miss (infinity) when [e] is infinity. *)
let check_depth ?(eps = 1e-9) msg e a =
  if e = infinity then (if a <> infinity then Alcotest.failf "%s: expected a miss, got depth %g" msg a)
  else float_eq ~eps msg e a

(* ---- set-up ---- *)

let test_flat_setup () =
  (* N = normalize((P1 − P2) × (P3 − P2)) = normalize(<-2,0,0> × <-1,2,0>)
       = normalize(<0·0 − 0·2, 0·(−1) − (−2)·0, (−2)·2 − 0·(−1)>) = normalize(<0,0,-4>) = <0,0,-1> *)
  vec_eq "normal" (v 0. 0. (-1.)) (v tri.nx tri.ny tri.nz);
  (* Distance = −N·P1 = −(−1·2) = 2 *)
  float_eq "dist" 2. tri.dist;
  (* |N| = <0,0,1>: the dominant axis is z *)
  float_eq "axis" 2. tri.axis;
  (* a counter-clockwise projection needs no swap: the corners are kept in order *)
  vec_eq "P1 kept" p1 (v tri.x1 tri.y1 tri.z1);
  vec_eq "P2 kept" p2 (v tri.x2 tri.y2 tri.z2);
  vec_eq "P3 kept" p3 (v tri.x3 tri.y3 tri.z3);
  (* written clockwise (P1, P3, P2): the first two corners are swapped, giving P3, P1, P2 *)
  let t = flat_exn p1 p3 p2 in
  vec_eq "swapped: first corner" p3 (v t.x1 t.y1 t.z1);
  vec_eq "swapped: second corner" p1 (v t.x2 t.y2 t.z2);
  vec_eq "swapped: third corner" p2 (v t.x3 t.y3 t.z3);
  (* the normal flips with the winding: (P1 − P3) × (P2 − P3) = <-1,-2,0> × <1,-2,0> = <0,0,4> *)
  vec_eq "swapped: normal" (v 0. 0. 1.) (v t.nx t.ny t.nz);
  float_eq "swapped: dist = −<0,0,1>·P1 = −2" (-2.) t.dist

let test_flat_oblique () =
  (* P1 = <1,0,0>, P2 = <0,1,0>, P3 = <1,0,1>: (P1 − P2) × (P3 − P2) = <1,-1,0> × <1,-1,1>
     = <(−1)·1 − 0·(−1), 0·1 − 1·1, 1·(−1) − (−1)·1> = <-1,-1,0>, N = <-1,-1,0>/√2;
     |Nx| = |Ny| > |Nz|: the later of x and y wins, axis 1; Distance = −N·P1 = 1/√2 *)
  let t = flat_exn (v 1. 0. 0.) (v 0. 1. 0.) (v 1. 0. 1.) in
  vec_eq "normal" (v (-1. /. s2) (-1. /. s2) 0.) (v t.nx t.ny t.nz);
  float_eq "axis y" 1. t.axis;
  float_eq "dist" (1. /. s2) t.dist;
  (* the centroid is <2/3, 1/3, 1/3>; a ray towards it along <1,1,0>/√2 from centroid − <1,1,0>
     meets the plane x + y = 1 after √2 *)
  let c = v (2. /. 3.) (1. /. 3.) (1. /. 3.) in
  let d = v (1. /. s2) (1. /. s2) 0. in
  check_depth "hit projected on x,z" s2 (Triangle.intersect t (Vec.sub c (v 1. 1. 0.)) d);
  (* projected on (x, z) the triangle is <1,0>, <0,0>, <1,1>: 0 ≤ z ≤ x ≤ 1. From <-0.5,-0.5,0.9>
     the ray meets the plane at √2, at <0.5,0.5,0.9>, where z > x: outside *)
  check_depth "miss projected on x,z" infinity (Triangle.intersect t (v (-0.5) (-0.5) 0.9) d)

let test_degenerate () =
  (* collinear: <1,2,3> − <0,0,0> and <2,4,6> − <1,2,3> are parallel, the cross product is exactly 0 *)
  Alcotest.(check bool) "collinear" true (Triangle.flat (v 0. 0. 0.) (v 1. 2. 3.) (v 2. 4. 6.) = None);
  Alcotest.(check bool) "two equal corners" true (Triangle.flat p1 p1 p3 = None);
  Alcotest.(check bool) "a point" true (Triangle.flat p2 p2 p2 = None);
  let n = v 0. 0. 1. in
  Alcotest.(check bool) "smooth collinear" true (Triangle.smooth (v 0. 0. 0.) n (v 1. 2. 3.) n (v 2. 4. 6.) n = None)

let test_max3 () =
  let chk msg e x y z = Alcotest.(check int) msg e (Triangle.max3_coordinate x y z) in
  chk "x largest" 0 3. 2. 1.;
  chk "y largest" 1 1. 3. 2.;
  chk "z largest" 2 1. 2. 3.;
  (* ties: the later axis wins; equal x, y above z → 1; every other tie → 2 *)
  chk "x = y > z" 1 1. 1. 0.;
  chk "x = z > y" 2 1. 0. 1.;
  chk "y = z > x" 2 0. 1. 1.;
  chk "x = y = z" 2 1. 1. 1.;
  chk "all zero" 2 0. 0. 0.;
  (* a tie below the maximum does not matter *)
  chk "x > y = z" 0 2. 1. 1.

let test_needs_swap () =
  (* axis 2 projects on (x, y). With u = x, w = y the test is
     (P2u − P3u)(P2w − P1w) < (P2w − P3w)(P2u − P1u).
     P1, P2, P3: (1 − 0)(−1 + 1) = 0 < (−1 − 1)(1 + 1) = −4 is false: no swap *)
  Alcotest.(check bool) "ccw in x,y" false (Triangle.needs_swap 2 p1 p2 p3);
  (* P1, P3, P2: (0 − 1)(1 + 1) = −2 < (1 + 1)(0 + 1) = 2 is true: swap *)
  Alcotest.(check bool) "cw in x,y" true (Triangle.needs_swap 2 p1 p3 p2);
  (* axis 0 projects on (y, z): corners <0,0,0>, <0,1,0>, <0,0,1>:
     (1 − 0)(0 − 0) = 0 < (0 − 1)(1 − 0) = −1 false; reversed order <0,0,0>, <0,0,1>, <0,1,0>:
     (0 − 1)(1 − 0) = −1 < (1 − 0)(0 − 0) = 0 true *)
  let a = v 0. 0. 0. and b = v 0. 1. 0. and c = v 0. 0. 1. in
  Alcotest.(check bool) "axis 0, (y,z) ccw" false (Triangle.needs_swap 0 a b c);
  Alcotest.(check bool) "axis 0, (y,z) cw" true (Triangle.needs_swap 0 a c b);
  (* axis 1 projects on (x, z): <0,0,0>, <1,0,0>, <0,0,1>: (1 − 0)(0 − 0) = 0 < (0 − 1)(1 − 0) = −1
     false; <0,0,0>, <0,0,1>, <1,0,0>: (0 − 1)(1 − 0) = −1 < (1 − 0)(0 − 0) = 0 true *)
  let b = v 1. 0. 0. in
  Alcotest.(check bool) "axis 1, (x,z) ccw" false (Triangle.needs_swap 1 a b c);
  Alcotest.(check bool) "axis 1, (x,z) cw" true (Triangle.needs_swap 1 a c b)

(* ---- intersection ---- *)

let test_intersect () =
  (* t = −(Distance + N·O)/(N·D) = −(2 + 0)/(−1) = 2 *)
  check_depth "from the origin along +z" 2. (Triangle.intersect tri (v 0. 0. 0.) plus_z);
  (* the same from the other side: O = <0,0,5>, D = −z: −(2 + (−5))/1 = 3 *)
  check_depth "from above along −z" 3. (Triangle.intersect tri (v 0. 0. 5.) (v 0. 0. (-1.)));
  (* the clockwise (swapped) triangle is hit at the same depth *)
  check_depth "swapped winding" 2. (Triangle.intersect (flat_exn p1 p3 p2) (v 0. 0. 0.) plus_z);
  (* an oblique ray to <0.25,0,2> from the origin: depth |<0.25,0,2>| = √4.0625 *)
  check_depth "oblique" (sqrt 4.0625) (Triangle.intersect tri (v 0. 0. 0.) (Vec.normalize (v 0.25 0. 2.)));
  (* the plane is met at <2,0,2>, outside (x > 1) *)
  check_depth "outside" infinity (Triangle.intersect tri (v 2. 0. 0.) plus_z);
  check_depth "outside (swapped)" infinity (Triangle.intersect (flat_exn p1 p3 p2) (v 2. 0. 0.) plus_z);
  (* outside beyond the apex P3 = <0,1,2> *)
  check_depth "beyond the apex" infinity (Triangle.intersect tri (v 0. 1.5 0.) plus_z);
  (* the plane behind the origin: O = <0,0,3>, D = +z: t = −(2 + N·O)/(N·D) = −(2 − 3)/(−1) = −1 *)
  check_depth "behind" infinity (Triangle.intersect tri (v 0. 0. 3.) plus_z)

let test_edges () =
  (* <0,-1,2> lies on the edge P1P2 (y = −1): the three edge tests in (x, y) with s = 0, u = −1:
     (1 − 0)(−1 + 1) = 0 < (−1 + 1)(1 + 1) = 0 false; (0 − 0)(1 + 1) = 0 < (1 + 1)(0 − 1) = −2 false;
     (−1 − 0)(−1 − 1) = 2 < (−1 + 1)(−1 − 0) = 0 false → inside *)
  check_depth "on edge P1P2" 2. (Triangle.intersect tri (v 0. (-1.) 0.) plus_z);
  (* <0.5,0,2> is the middle of P2P3: (0 − 0.5)(1 + 1) = −1 < (1 − 0)(0 − 1) = −1 false → inside *)
  check_depth "on edge P2P3" 2. (Triangle.intersect tri (v 0.5 0. 0.) plus_z);
  (* a vertex *)
  check_depth "at P3" 2. (Triangle.intersect tri (v 0. 1. 0.) plus_z);
  (* just past the edge y = −1: first test (1)(0) = 0 < (−1 + 1.001)(2) = 0.002 true → outside *)
  check_depth "just outside P1P2" infinity (Triangle.intersect tri (v 0. (-1.001) 0.) plus_z)

let test_parallel_and_limits () =
  (* N·D = 0 *)
  check_depth "in-plane direction" infinity (Triangle.intersect tri (v (-5.) 0. 2.) (v 1. 0. 0.));
  (* Nearly parallel, from 1e-12 below the plane: D = <1,0,k>/|.|, N·D ≈ −k, t ≈ 1e-12/k.
     k = 2e-10: |N·D| ≥ 1e-10 → hit at ≈ 5e-3 (at x ≈ 0.005, inside).
     k = 5e-11: |N·D| < 1e-10 → no hit although t ≈ 0.02 would be inside. *)
  let o = v 0. 0. (2. -. 1e-12) in
  check_depth ~eps:1e-5 "|N·D| = 2e-10 hits" 5e-3 (Triangle.intersect tri o (Vec.normalize (v 1. 0. 2e-10)));
  check_depth "|N·D| = 5e-11 misses" infinity (Triangle.intersect tri o (Vec.normalize (v 1. 0. 5e-11)));
  (* depth limits 1e-6 … 1e7 *)
  check_depth "depth 5e-7 rejected" infinity (Triangle.intersect tri (v 0. 0. (2. -. 5e-7)) plus_z);
  check_depth ~eps:1e-12 "depth 2e-6 kept" 2e-6 (Triangle.intersect tri (v 0. 0. (2. -. 2e-6)) plus_z);
  check_depth "depth 5e6 kept" 5e6 (Triangle.intersect tri (v 0. 0. (2. -. 5e6)) plus_z);
  check_depth "depth 2e7 rejected" infinity (Triangle.intersect tri (v 0. 0. (2. -. 2e7)) plus_z)

(* ---- smooth triangles ---- *)

let n1 = v (1. /. s2) 0. (1. /. s2)
let n2 = v 0. (1. /. s2) (1. /. s2)
let n3 = v 0. 0. 1.

let smooth_exn a na b nb c nc =
  match Triangle.smooth a na b nb c nc with
  | Some (Ok t) -> t
  | Some (Error ()) -> Alcotest.fail "expected a visible smooth triangle, got Error"
  | None -> Alcotest.fail "expected a smooth triangle, got None"

let test_smooth_sides () =
  let up = v 0. 0. 1. and down = v 0. 0. (-1.) in
  let is_error = function Some (Error ()) -> true | Some (Ok _) | None -> false in
  let is_ok = function Some (Ok _) -> true | Some (Error ()) | None -> false in
  (* N = <0,0,-1>: N·up = −1 for all three: one side *)
  Alcotest.(check bool) "all up" true (is_ok (Triangle.smooth p1 up p2 up p3 up));
  Alcotest.(check bool) "all down" true (is_ok (Triangle.smooth p1 down p2 down p3 down));
  (* N·n1 = N·n2 = −1/√2, N·n3 = −1 *)
  Alcotest.(check bool) "tilted, same side" true (is_ok (Triangle.smooth p1 n1 p2 n2 p3 n3));
  (* −1, +1, −1: straddling *)
  Alcotest.(check bool) "straddling" true (is_error (Triangle.smooth p1 up p2 down p3 up));
  Alcotest.(check bool) "straddling (first differs)" true (is_error (Triangle.smooth p1 down p2 up p3 up));
  (* N·<1,0,0> = 0 is on neither side *)
  Alcotest.(check bool) "one normal in the plane" true (is_error (Triangle.smooth p1 up p2 up p3 (v 1. 0. 0.)))

let test_smooth_normal () =
  let t = smooth_exn p1 n1 p2 n2 p3 n3 in
  (* geometry as for the flat triangle *)
  vec_eq "face normal" (v 0. 0. (-1.)) (v t.nx t.ny t.nz);
  check_depth "smooth hit" 2. (Triangle.intersect t (v 0. 0. 0.) plus_z);
  (* at each vertex: that vertex's normal *)
  vec_eq "at P1" n1 (Triangle.smooth_normal t p1);
  vec_eq "at P2" n2 (Triangle.smooth_normal t p2);
  vec_eq "at P3" n3 (Triangle.smooth_normal t p3);
  (* centroid <0,-1/3,2>: weights 1/3 each, N ∝ n1 + n2 + n3 = <1/√2, 1/√2, 1 + √2>,
     |.|² = 1/2 + 1/2 + (1 + √2)² = 4 + 2√2 *)
  let k = sqrt (4. +. (2. *. s2)) in
  vec_eq "at the centroid" (v (1. /. s2 /. k) (1. /. s2 /. k) ((1. +. s2) /. k)) (Triangle.smooth_normal t (v 0. (-1. /. 3.) 2.));
  (* middle of P2P3 <0.5,0,2>: N ∝ n2 + n3 = <0, 1/√2, 1 + 1/√2>, |.|² = 1/2 + (1 + 1/√2)² = 2 + √2 *)
  let k = sqrt (2. +. s2) in
  vec_eq "middle of P2P3" (v 0. (1. /. s2 /. k) ((1. +. (1. /. s2)) /. k)) (Triangle.smooth_normal t (v 0.5 0. 2.));
  (* weights 1/2, 1/4, 1/4: P = P1/2 + P2/4 + P3/4 = <-0.25,-0.5,2>; N ∝ 2n1 + n2 + n3 =
     <√2, 1/√2, √2 + 1/√2 + 1>, |.|² = 2 + 1/2 + (1 + 3/√2)² *)
  let nz = 1. +. (3. /. s2) in
  let k = sqrt (2.5 +. (nz *. nz)) in
  vec_eq "weights 1/2,1/4,1/4" (v (s2 /. k) (1. /. s2 /. k) (nz /. k)) (Triangle.smooth_normal t (v (-0.25) (-0.5) 2.))

let test_smooth_swapped () =
  (* written clockwise: the corners are swapped, and the vertex normals must go with them *)
  let t = smooth_exn p1 n1 p3 n3 p2 n2 in
  vec_eq "at P1" n1 (Triangle.smooth_normal t p1);
  vec_eq "at P2" n2 (Triangle.smooth_normal t p2);
  vec_eq "at P3" n3 (Triangle.smooth_normal t p3);
  let k = sqrt (4. +. (2. *. s2)) in
  vec_eq "at the centroid" (v (1. /. s2 /. k) (1. /. s2 /. k) ((1. +. s2) /. k)) (Triangle.smooth_normal t (v 0. (-1. /. 3.) 2.))

let test_bounds () =
  let chk msg e a = Alcotest.(check (array (float 0.))) msg e a in
  chk "z = 2 triangle" [| -1.; -1.; 2.; 1.; 1.; 2. |] (Triangle.bounds tri);
  (* <0,5,-3>, <2,-1,4>, <-6,0,1>: min <-6,-1,-3>, max <2,5,4> *)
  chk "general" [| -6.; -1.; -3.; 2.; 5.; 4. |] (Triangle.bounds (flat_exn (v 0. 5. (-3.)) (v 2. (-1.) 4.) (v (-6.) 0. 1.)))

let tests =
  [
    Alcotest.test_case "flat set-up" `Quick test_flat_setup;
    Alcotest.test_case "oblique triangle, axis tie" `Quick test_flat_oblique;
    Alcotest.test_case "degenerate" `Quick test_degenerate;
    Alcotest.test_case "max3_coordinate" `Quick test_max3;
    Alcotest.test_case "needs_swap" `Quick test_needs_swap;
    Alcotest.test_case "intersect" `Quick test_intersect;
    Alcotest.test_case "points on edges" `Quick test_edges;
    Alcotest.test_case "parallel rays and depth limits" `Quick test_parallel_and_limits;
    Alcotest.test_case "smooth: normals on one side" `Quick test_smooth_sides;
    Alcotest.test_case "smooth normal" `Quick test_smooth_normal;
    Alcotest.test_case "smooth normal, swapped corners" `Quick test_smooth_swapped;
    Alcotest.test_case "bounds" `Quick test_bounds;
  ]
