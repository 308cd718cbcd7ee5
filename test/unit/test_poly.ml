(* poly, cubic, quartic and polynomial (POV-Ray's shape/poly.cpp): parsing (the term order, the
   coefficient counts, sturm, inverse, the located errors), the crossings against POV-Ray's own
   trace() (test/unit/data/poly_trace.pov) and against a brute-force search of the implicit
   surface, the gradient normal, the inside test, the statistics, and Sturm sequences above
   degree 4. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

(* the coefficients of [n]'s terms in POV-Ray's order from a list of ((i, j, k), c) *)
let coeffs n terms =
  let c = Array.make (Poly.term_count n) 0. in
  List.iter (fun ((i, j, k), x) -> match Poly.index n i j k with Some p -> c.(p) <- x | None -> Alcotest.fail "bad powers") terms;
  c

let vec_text c = String.concat ", " (Array.to_list (Array.map (Printf.sprintf "%.17g") c))

(* the quartic torus R = 0.7, r = 0.25 about y, and x⁶ + y⁶ + z⁶ = 1 *)
let torus4 =
  let r2 = 0.49 and s2 = 0.0625 in
  let k = r2 -. s2 in
  coeffs 4
    [ ((4, 0, 0), 1.); ((0, 4, 0), 1.); ((0, 0, 4), 1.); ((2, 2, 0), 2.); ((2, 0, 2), 2.); ((0, 2, 2), 2.);
      ((2, 0, 0), (2. *. k) -. (4. *. r2)); ((0, 2, 0), 2. *. k); ((0, 0, 2), (2. *. k) -. (4. *. r2)); ((0, 0, 0), k *. k) ]

let sextic = coeffs 6 [ ((6, 0, 0), 1.); ((0, 6, 0), 1.); ((0, 0, 6), 1.); ((0, 0, 0), -1.) ]

let rec poly_of (o : Scene.obj) =
  match o.shape with
  | Poly p -> (p, false)
  | Csg { kind = Intersection; members = [ m ]; _ } ->
      let p, inv = poly_of m.mobj in
      (p, inv <> m.inverted)
  | _ ->
      Alcotest.fail "expected a poly"

let parsed text = poly_of (the_object (scene (v37 ^ text)))

let test_parse () =
  (* Set_Coeff's index is the place of the term in POV-Ray's order *)
  Alcotest.(check (option int)) "x² first" (Some 0) (Poly.index 2 2 0 0);
  Alcotest.(check (option int)) "x then y" (Some 1) (Poly.index 2 1 1 0);
  Alcotest.(check (option int)) "y² at 4" (Some 4) (Poly.index 2 0 2 0);
  Alcotest.(check (option int)) "the constant last" (Some 9) (Poly.index 2 0 0 0);
  Alcotest.(check (option int)) "quartic y²: 25 (as shapesq.inc's Piriform)" (Some 25) (Poly.index 4 0 2 0);
  Alcotest.(check (option int)) "quartic z²: 32" (Some 32) (Poly.index 4 0 0 2);
  Alcotest.(check (option int)) "too high" None (Poly.index 2 2 1 0);
  Alcotest.(check (list int)) "term counts" [ 10; 20; 35; 84; 8436 ] (List.map Poly.term_count [ 2; 3; 4; 6; 35 ]);
  let p, inv = parsed (Printf.sprintf "quartic { <%s> }" (vec_text torus4)) in
  Alcotest.(check int) "quartic: order 4" 4 p.order;
  Alcotest.(check bool) "the coefficients as written" true (p.coeffs = torus4);
  Alcotest.(check bool) "no sturm" false p.sturm;
  Alcotest.(check bool) "not inverted" false inv;
  let p, _ = parsed "cubic { <1,0,0,0,0,0,0,0,0,0, -3,0,0,0,0,0,0,0,-1,0> sturm }" in
  Alcotest.(check int) "cubic: order 3" 3 p.order;
  Alcotest.(check bool) "sturm" true p.sturm;
  float_eq "y³ is term 10" (-3.) p.coeffs.(10);
  let p, _ = parsed "cubic { <1 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0, -1 0> sturm off }" in
  Alcotest.(check bool) "sturm off; commas optional" false p.sturm;
  let p, inv = parsed (Printf.sprintf "poly { 6.9, <%s> translate x inverse }" (vec_text sextic)) in
  Alcotest.(check int) "poly: the order truncated" 6 p.order;
  Alcotest.(check bool) "inverse toggles the flag" true inv;
  float_eq "translated" (-1.) (Transform.inv_point p.tr (v 0. 0. 0.)).x;
  let p, _ = parsed "polynomial { 2, xyz(2, 0, 0): 1, xyz(0,2,0): 1 xyz(0, 0, 2): 1, xyz(0,0,0): -1, xyz(2,0,0): 4 }" in
  Alcotest.(check bool) "polynomial: its terms, the later x² kept" true (p.coeffs = [| 4.; 0.; 0.; 0.; 1.; 0.; 0.; 1.; 0.; -1. |])

let test_errors () =
  expect_scene_error "order 1" "poly { 1, <1,2,3,4> }" ~line:1 ~col:8 ~sub:"Order of poly is out of range";
  expect_scene_error "order 36" "poly { 36, <1> }" ~line:1 ~col:8 ~sub:"Order of poly is out of range";
  expect_scene_error "no '<'" "cubic { 1, 2 }" ~line:1 ~col:9 ~sub:"'<' starting the 20 coefficients";
  expect_scene_error "too few" "cubic { <1,2,3> }" ~line:1 ~col:15 ~sub:"numeric expression";
  expect_scene_error "too many" "poly { 2, <1,0,0,0,1,0,0,1,0,-1,5> }" ~line:1 ~col:32 ~sub:"'>' after the 10 coefficients";
  expect_scene_error "polynomial powers" "polynomial { 2, xyz(2,1,0): 1 }" ~line:1 ~col:21 ~sub:"Coefficient of polynom is out of range";
  expect_scene_error "polynomial order" "polynomial { 40, xyz(0,0,0): 1 }" ~line:1 ~col:14 ~sub:"Order of polynomial is out of range"

(* the compiled poly of [text] and a scratch to intersect it with *)
let setup text =
  let c = compile (v37 ^ text) in
  let p = match c.objects.(0).shape with Compiled.Poly p -> p | _ -> Alcotest.fail "expected a compiled poly" in
  (p, Scratch.create ~robust:false (Stats.create ()))

(* the nearest crossing's world point and normal, as trace() gives them *)
let traced (p, w) o d =
  let d = Transform.normalize d in
  let t = Poly.depth w p o d 0. in
  if t = infinity then (Vec.zero, Vec.zero)
  else
    let q = Poly.hit_point w p o d t in
    (q, Poly.normal p q)

(* test/unit/data/poly_trace.pov: POV-Ray's trace() of the same polys and rays *)
let declared =
  Printf.sprintf
    "poly { 4, <%s> rotate <60, 0, 30> scale <1.2, 0.6, 1> translate <0.1, 0.2, 0.3> }\n" (vec_text torus4),
  Printf.sprintf "poly { 6, <%s> scale <0.3, 0.5, 0.4> rotate <30, 45, 0> }\n" (vec_text sextic),
  "cubic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0, -1, 0> sturm rotate x*-90 }",
  "poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -0.25> matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> }"

let test_pov_trace () =
  let p1, p2, p3, p4 = declared in
  let check name text o d (ex, ey, ez) (nx, ny, nz) =
    let q, n = traced (setup text) o d in
    vec_eq ~eps:1e-16 (name ^ ": point") (v ex ey ez) q;
    vec_eq ~eps:1e-16 (name ^ ": normal") (v nx ny nz) n
  in
  check "P1a" p1 (v 0.3 3. (-4.)) (v (-0.05) (-0.6) 1.) (0.10804630078237679, 0.69655560938851058, -0.16092601564751829)
    (0.02178884390476917, 0.91590031315181730, -0.40081400006698431);
  check "P1b" p1 (v (-3.) 0.1 0.2) (v 1. 0.05 0.02) (-0.97421077774549303, 0.20128946111272539, 0.24051578444509009)
    (-0.77782734488853800, 0.42922248411128722, 0.45907807688560232);
  check "P2a" p2 (v 0.1 0.2 (-3.)) (v 0. 0. 1.) (0.10000000000000012, 0.19999999999999984, -0.32126361543418502)
    (0.67248685032797673, 0.02757414047204020, -0.73959522910385644);
  check "P2b" p2 (v 2. 1.5 (-1.)) (v (-1.) (-0.8) 0.6) (0.38769346591964271, 0.21015477273571417, -0.03261607955178557)
    (0.72640577207498958, 0.04717644053164099, -0.68564497938430402);
  check "P3a" p3 (v 0.3 2. (-0.4)) (v 0.1 (-1.) 0.2) (0.48835684790949130, 0.11643152090508702, -0.02328630418101734)
    (0.58187508623965711, -0.81326848660662876, 0.00396896789546419);
  check "P4a" p4 (v (-2.) 0.1 (-0.1)) (v 1. 0.05 0.02) (-0.37025409261350539, 0.18148729536932473, -0.06740508185227012)
    (-0.74123922291912103, 0.66243341016113721, -0.10838077093536468);
  (* a ray grazing the tube: the source's order of the sums would give x = 0.832315801875882 *)
  let p5 = Printf.sprintf "poly { 4, <%s> }" (vec_text torus4) in
  let o5 = v 1.6 5.613139720814413 (-1.2777568135664554) and d5 = v (-0.1361893369949414) (-0.9591521508170833) 0.2479508339809358 in
  check "P5a" p5 o5 d5 (0.83231580187577714, 0.20650535408358461, 0.11991455600601908) (0.55787848849680721, 0.82602141633402049, 0.08037544295402933);
  check "P6a (sturm)" (Printf.sprintf "poly { 4, <%s> sturm }" (vec_text torus4)) o5 d5 (0.83231580187576659, 0.20650535408351089, 0.11991455600603840)
    (0.55787848849686816, 0.82602141633397719, 0.08037544295405201)

(* the sign changes of the polynomial along the ray, found by sampling and refined by bisection:
   the crossings of the surface, in world depths (the ray's direction is unit, the poly has no
   transform) *)
let brute (p : Poly.t) (o : Vec.t) (d : Vec.t) =
  let f t = Poly.value p (Vec.madd o t d) in
  let steps = 20000 and far = 10. in
  let roots = ref [] in
  for s = 0 to steps - 1 do
    let a = far *. float_of_int s /. float_of_int steps and b = far *. float_of_int (s + 1) /. float_of_int steps in
    if f a *. f b < 0. then begin
      let lo = ref a and hi = ref b in
      for _ = 1 to 60 do
        let m = (!lo +. !hi) /. 2. in
        if f !lo *. f m <= 0. then hi := m else lo := m
      done;
      roots := !lo :: !roots
    end
  done;
  List.rev !roots

let test_brute_force () =
  let rays =
    [ (v (-3.) 0.1 0.05, v 1. 0. 0.); (v (-2.) 0.5 (-2.), v 1. (-0.2) 1.); (v 0.3 3. (-0.2), v 0. (-1.) 0.1); (v 2. 2. 2., v (-1.) (-1.) (-1.));
      (v 0. 0. 0., v 0.3 0.1 1.) ]
  in
  List.iter
    (fun (name, c, order, sturm) ->
      let text = Printf.sprintf "poly { %d, <%s>%s }" order (vec_text c) (if sturm then " sturm" else "") in
      let p, w = setup text in
      List.iter
        (fun (o, d) ->
          let d = Transform.normalize d in
          let n = Poly.crossings w p o d in
          let found = List.sort compare (List.init n (fun i -> Poly.crossing w i)) in
          let expected = brute p o d in
          Alcotest.(check int) (name ^ ": as many crossings as sign changes") (List.length expected) (List.length found);
          List.iter2 (fun e a -> float_eq ~eps:1e-7 (name ^ ": crossing") e a) expected found;
          (* each crossing is on the surface and the normal is the unit gradient there *)
          List.iter
            (fun t ->
              let q = Vec.madd o t d in
              let g = Poly.gradient p q and h = 1e-6 in
              let num =
                v ((Poly.value p (Vec.add q (v h 0. 0.)) -. Poly.value p (Vec.sub q (v h 0. 0.))) /. (2. *. h))
                  ((Poly.value p (Vec.add q (v 0. h 0.)) -. Poly.value p (Vec.sub q (v 0. h 0.))) /. (2. *. h))
                  ((Poly.value p (Vec.add q (v 0. 0. h)) -. Poly.value p (Vec.sub q (v 0. 0. h))) /. (2. *. h))
              in
              vec_eq ~eps:1e-5 (name ^ ": gradient") num g;
              vec_eq ~eps:1e-9 (name ^ ": unit normal") (Transform.normalize g) (Poly.normal p q))
            found)
        rays)
    [ ("quartic torus", torus4, 4, false); ("quartic torus, Sturm", torus4, 4, true); ("sextic", sextic, 6, false);
      ("ball", coeffs 2 [ ((2, 0, 0), 1.); ((0, 2, 0), 1.); ((0, 0, 2), 1.); ((0, 0, 0), -1.) ], 2, false) ]

let test_inside_and_stats () =
  let p, w = setup (Printf.sprintf "poly { 6, <%s> scale 2 }" (vec_text sextic)) in
  Alcotest.(check bool) "centre inside" true (Poly.inside p (v 0. 0. 0.));
  Alcotest.(check bool) "corner region inside (x⁶ + y⁶ + z⁶ < 1 in poly space)" true (Poly.inside p (v 1.8 1.2 0.5));
  Alcotest.(check bool) "outside" false (Poly.inside p (v 2.1 0. 0.));
  (* the surface itself counts as inside: the value is below INSIDE_TOLERANCE *)
  Alcotest.(check bool) "on the surface" true (Poly.inside p (v 2. 0. 0.));
  let n = Poly.crossings w p (v (-5.) 0. 0.) (v 1. 0. 0.) in
  Alcotest.(check int) "two crossings" 2 n;
  float_eq ~eps:1e-9 "the world depths (the scale undone)" 3. (Float.min (Poly.crossing w 0) (Poly.crossing w 1));
  ignore (Poly.crossings w p (v (-5.) 5. 0.) (v 1. 0. 0.));
  Alcotest.(check (pair int int)) "Quartic/Poly: 2 tests, 1 succeeded" (2, 1) (Stats.tests w.stats Stats.poly, Stats.hits w.stats Stats.poly);
  Alcotest.(check int) "both went to the solver" 2 (Stats.tests w.stats Stats.roots);
  (* a ray leaving the surface: its root at 0 is dropped (eliminated, then below 1e-4) *)
  let n = Poly.crossings w p (v 2. 0. 0.) (v (-1.) 0. 0.) in
  Alcotest.(check int) "one crossing from the surface" 1 n;
  float_eq ~eps:1e-9 "the far side" 4. (Poly.crossing w 0);
  Alcotest.(check int) "eliminated counted" 1 (Stats.hits w.stats Stats.roots);
  (* the degree of the polynomial in t may drop: a ray along the axis of x² + y² = 1 (order 2 is
     intersect_quadratic, which finds no root) *)
  let p, w = setup "quartic { <0,0,0,0,0,0,0,0,0,1, 0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,1,0,0,0,0, 0,0,0,0,-1> }" in
  Alcotest.(check int) "along the cylinder's axis: degree 0, no solve" 0 (Poly.crossings w p (v 0.2 0.1 (-3.)) (v 0. 0. 1.));
  Alcotest.(check int) "not solved" 0 (Stats.tests w.stats Stats.roots);
  Alcotest.(check int) "across it: two" 2 (Poly.crossings w p (v (-3.) 0. 0.) (v 1. 0. 0.))

let test_sturm_high () =
  let w = Polysolv.create () in
  let roots c n =
    let r = Array.make n nan in
    let k = Polysolv.solve w c n ~sturm:false ~eps:0. r in
    List.sort compare (Array.to_list (Array.sub r 0 k))
  in
  (* (x − 1)(x − 2)(x − 3)(x − 4)(x − 5) *)
  let r = roots [| 1.; -15.; 85.; -225.; 274.; -120. |] 5 in
  Alcotest.(check int) "degree 5: five roots" 5 (List.length r);
  List.iteri (fun i x -> float_eq ~eps:1e-9 "degree 5 root" (float_of_int (i + 1)) x) r;
  (* (x² − 1)(x² − 4)(x − 0.5)(x + 3): Sturm keeps the non-negative ones *)
  let r = roots [| 1.; 2.5; -6.5; -12.5; 11.5; 10.; -6. |] 6 in
  Alcotest.(check int) "degree 6: the roots in [0, 1e7]" 3 (List.length r);
  List.iter2 (fun e x -> float_eq ~eps:1e-9 "degree 6 root" e x) [ 0.5; 1.; 2. ] r;
  (* a root at 0 above degree 4 is counted as eliminated, but the whole polynomial is solved *)
  let r = Array.make 5 nan in
  let k = Polysolv.solve w [| 1.; -10.; 35.; -50.; 24.; -1e-9 |] 5 ~sturm:false ~eps:1e-4 r in
  Alcotest.(check bool) "eliminated" true (Polysolv.eliminated w);
  Alcotest.(check int) "five roots" 5 k;
  Alcotest.(check bool) "the root near 0 is still there" true (List.exists (fun x -> Float.abs x < 1e-9) (Array.to_list (Array.sub r 0 k)))

let test_dump () =
  let s = Dump.scene (scene (v37 ^ "cubic { <1,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,-1,0> sturm translate y }")) in
  check_contains "dump: the poly" ~sub:"poly { 3, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0> sturm" s

let tests =
  [
    Alcotest.test_case "parsing and the term order" `Quick test_parse;
    Alcotest.test_case "located parse errors" `Quick test_errors;
    Alcotest.test_case "POV-Ray's trace() points and normals" `Quick test_pov_trace;
    Alcotest.test_case "crossings against brute force" `Quick test_brute_force;
    Alcotest.test_case "inside, statistics, root elimination" `Quick test_inside_and_stats;
    Alcotest.test_case "Sturm sequences above degree 4" `Quick test_sturm_high;
    Alcotest.test_case "dump" `Quick test_dump;
  ]
