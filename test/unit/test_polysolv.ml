(* POV-Ray's polynomial solver (docs/povray-rules.md §15.6): each path on polynomials whose roots are known
   by hand, the quirks it must keep (root elimination, the pp = 0 sign slip, the signed "biggest"
   of difficult(), a quadruple root lost by the closed form), and Sturm against the quartic. *)

open Helpers

let w = Polysolv.create ()

(* the roots of [c] (degree [n]), sorted *)
let roots ?(sturm = false) ?(eps = 0.) c n =
  let r = Array.make 4 nan in
  let k = Polysolv.solve w c n ~sturm ~eps r in
  List.sort compare (Array.to_list (Array.sub r 0 k))

let check_roots ?(eps = 1e-9) msg expected actual =
  Alcotest.(check int) (msg ^ ": count") (List.length expected) (List.length actual);
  List.iter2 (fun e a -> float_eq ~eps msg e a) expected actual

let test_low_degrees () =
  (* x² − 3x + 2 = (x − 1)(x − 2): (b + √d)/2 first *)
  let r = Array.make 4 nan in
  Alcotest.(check int) "quadratic: two roots" 2 (Polysolv.quadratic [| 1.; -3.; 2. |] 0 r 0);
  float_eq ~eps:0. "quadratic: (b + √d)/2 = 2 first" 2. r.(0);
  float_eq ~eps:0. "quadratic: then 1" 1. r.(1);
  (* (x − 1)²: the discriminant is 0, one root *)
  check_roots "double root" [ 1. ] (roots [| 1.; -2.; 1. |] 2);
  (* a discriminant within 1e-10 of 0 counts as 0: x² − 2x + 1 − 1e-12 has one root *)
  check_roots "near-double root" [ 1. ] (roots [| 1.; -2.; 1. -. 1e-12 |] 2);
  check_roots "x² + 1: none" [] (roots [| 1.; 0.; 1. |] 2);
  (* a leading coefficient below 1e-10 drops the degree: 1e-11·x² + 2x − 4 is 2x − 4 *)
  check_roots "near-zero leading coefficient" [ 2. ] (roots [| 1e-11; 2.; -4. |] 2);
  check_roots "two near-zero leading coefficients" [ -0.5 ] (roots [| 1e-12; -1e-11; 4.; 2. |] 3);
  (* (x − 1)(x − 2)(x − 3): three real roots by the trigonometric form *)
  check_roots "cubic, three roots" [ 1.; 2.; 3. ] (roots [| 1.; -6.; 11.; -6. |] 3);
  check_roots "cubic, three roots, non-monic" [ 1.; 2.; 3. ] (roots [| 2.; -12.; 22.; -12. |] 3);
  (* x³ − 1: one real root by Cardano's *)
  check_roots "cubic, one root" [ 1. ] (roots [| 1.; 0.; 0.; -1. |] 3);
  check_roots "cubic by Sturm" [ 1.; 2.; 3. ] (roots ~sturm:true [| 1.; -6.; 11.; -6. |] 3)

let test_quartic () =
  (* (x − 1)(x − 2)(x − 3)(x − 4) *)
  let c = [| 1.; -10.; 35.; -50.; 24. |] in
  check_roots "quartic" [ 1.; 2.; 3.; 4. ] (roots c 4);
  check_roots "Sturm" [ 1.; 2.; 3.; 4. ] (roots ~sturm:true c 4);
  (* (x + 1)(x − 2)(x − 3)(x + 4): the closed form gives all four, Sturm only those in [0, 1e7] *)
  let c = [| 1.; 0.; -15.; 10.; 24. |] in
  check_roots "negative roots kept by the quartic" [ -4.; -1.; 2.; 3. ] (roots c 4);
  check_roots "Sturm: only positive roots" [ 2.; 3. ] (roots ~sturm:true c 4);
  (* (x − 1)²(x − 3)²: the closed form gives each double root twice, Sturm once (less exactly:
     regula falsi stops on |f(x)/x| < 1e-12, and f is flat at a double root) *)
  let c = [| 1.; -8.; 22.; -24.; 9. |] in
  check_roots "double roots, quartic" [ 1.; 1.; 3.; 3. ] (roots c 4);
  check_roots ~eps:1e-6 "double roots, Sturm" [ 1.; 3. ] (roots ~sturm:true c 4);
  (* (x − 1)⁴: the resolvent cubic is z³ = 0, whose trigonometric form divides 0 by 0: NaN, no
     root at all; Sturm finds it *)
  let c = [| 1.; -4.; 6.; -4.; 1. |] in
  check_roots "quadruple root lost by the quartic" [] (roots c 4);
  check_roots ~eps:1e-3 "quadruple root found by Sturm" [ 1. ] (roots ~sturm:true c 4)

let test_pp_zero_slip () =
  (* (x² − 4x − 4)(x² − 4x + 4) = x⁴ − 8x³ + 16x² − 16: roots 2 ± 2√2 and the double root 2.
     The factor of the double root has a discriminant of exactly 0, and that branch subtracts
     q2 = −c1/4 = 2 where it should add it: the double root comes out as −2, once. *)
  let c = [| 1.; -8.; 16.; 0.; -16. |] in
  let s = 2. *. sqrt 2. in
  check_roots "POV-Ray's slip: −2 for the double root 2" [ -2.; 2. -. s; 2. +. s ] (roots c 4);
  check_roots ~eps:1e-6 "Sturm: the true roots in [0, 1e7]" [ 2.; 2. +. s ] (roots ~sturm:true c 4)

let test_elimination () =
  (* x(x − 1)(x − 2)(x − 3): with eps > 0 the root 0 is dropped and the cubic solved *)
  let c = [| 1.; -6.; 11.; -6.; 0. |] in
  check_roots "root at 0 eliminated" [ 1.; 2.; 3. ] (roots ~eps:1e-4 c 4);
  Alcotest.(check bool) "eliminated" true (Polysolv.eliminated w);
  check_roots "eps = 0 keeps it" [ 0.; 1.; 2.; 3. ] (roots c 4);
  Alcotest.(check bool) "not eliminated" false (Polysolv.eliminated w);
  (* |c4/c3| = 3e-4/6 = 5e-5 < 1e-4: the small root (about 5e-5) is dropped although it is not 0 *)
  let c = [| 1.; -6.; 11.; -6.; 3e-4 |] in
  Alcotest.(check int) "small root dropped" 3 (List.length (roots ~eps:1e-4 c 4));
  Alcotest.(check int) "kept below the ratio" 4 (List.length (roots ~eps:1e-5 c 4));
  (* a cubic x(x − 1)(x − 2) likewise drops to the quadratic *)
  check_roots "cubic: root at 0 eliminated" [ 1.; 2. ] (roots ~eps:1e-4 [| 1.; -3.; 2.; 0. |] 3);
  check_roots "cubic, Sturm, eliminated too" [ 1.; 2. ] (roots ~sturm:true ~eps:1e-4 [| 1.; -3.; 2.; 0. |] 3)

let test_difficult () =
  Alcotest.(check bool) "close coefficients" false (Polysolv.difficult [| 1.; 2.; 3.; 4.; 5. |] 0);
  Alcotest.(check bool) "1/1e-13 > 1e12" true (Polysolv.difficult [| 1.; 0.; 0.; 0.; 1e-13 |] 0);
  Alcotest.(check bool) "exactly 1e12 is not more" false (Polysolv.difficult [| 1.; 0.; 0.; 0.; 1e-12 |] 0);
  Alcotest.(check bool) "1e7 biggest: 1e7/1e-6 > 1e12" true (Polysolv.difficult [| 1.; 1e7; 1.; -1.; 1e-6 |] 0);
  (* −1e7 is kept as the signed biggest, so the next coefficient 1 (|1| > −1e7) replaces it *)
  Alcotest.(check bool) "signed biggest: −1e7 forgotten" false (Polysolv.difficult [| 1.; -1e7; 1.; -1.; 1e-6 |] 0);
  Alcotest.(check bool) "all zero" false (Polysolv.difficult [| 0.; 0.; 0.; 0.; 0. |] 0);
  (* a difficult quartic goes to Sturm: only the non-negative roots come back *)
  let c = [| 1.; 1e7; 1.; -1.; 1e-6 |] in
  List.iter (fun x -> Alcotest.(check bool) "Sturm root in [0, 1e7]" true (x >= 0. && x <= 1e7)) (roots c 4);
  Alcotest.check_raises "degree 36" (Invalid_argument "Polysolv.solve: degree above 35") (fun () ->
      ignore (Polysolv.solve w (Array.make 37 1.) 36 ~sturm:false ~eps:0. (Array.make 36 0.)))

(* the quartic of a ray against the torus R = 1, r = 0.25 (§15.5) *)
let torus_quartic (px, py, pz) (vx, vy, vz) =
  let rr = 1. and r2 = 0.0625 in
  let k1 = (px *. px) +. (pz *. pz) +. (py *. py) -. rr -. r2 and k2 = (px *. vx) +. (pz *. vz) +. (py *. vy) in
  [| 1.; 4. *. k2; 2. *. (k1 +. (2. *. ((k2 *. k2) +. (rr *. vy *. vy)))); 4. *. ((k2 *. k1) +. (2. *. rr *. py *. vy));
     (k1 *. k1) +. (4. *. rr *. ((py *. py) -. r2)) |]

let test_sturm_agrees () =
  (* rays through the torus from outside: Sturm and the closed form give the same positive roots *)
  let rays =
    [ ((-3., 0., 0.), (1., 0., 0.)); ((-3., 0.1, 0.2), (1., 0., 0.)); ((0., 2., -2.), (0., -0.6, 0.8));
      ((-2., 0.5, -2.), (0.6, -0.2, 0.7745966692414834)) ]
  in
  List.iter
    (fun (p, d) ->
      let c = torus_quartic p d in
      let q = List.filter (fun x -> x >= 0.) (roots c 4) and s = roots ~sturm:true c 4 in
      check_roots ~eps:1e-9 "Sturm = quartic" q s)
    rays;
  (* x = -3 along +x: the tube is crossed at x = −1.25, −0.75, 0.75, 1.25 *)
  check_roots "through the torus" [ 1.75; 2.25; 3.75; 4.25 ] (roots (torus_quartic (-3., 0., 0.) (1., 0., 0.)) 4)

let tests =
  [
    Alcotest.test_case "degrees 1 to 3" `Quick test_low_degrees;
    Alcotest.test_case "quartic and Sturm" `Quick test_quartic;
    Alcotest.test_case "the pp = 0 slip" `Quick test_pp_zero_slip;
    Alcotest.test_case "root elimination" `Quick test_elimination;
    Alcotest.test_case "difficult coefficients" `Quick test_difficult;
    Alcotest.test_case "Sturm agrees with the quartic" `Quick test_sturm_agrees;
  ]
