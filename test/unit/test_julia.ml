(* The julia fractal, julia_fractal { <a, b, c, d> … } (POV-Ray's fractal.cpp, quatern.cpp,
   hcmplx.cpp): its reader's defaults, clamps and errors; the march against POV-Ray's own trace()
   and inside() (the numbers printed by test/unit/data/julia_trace.pov); the crossing checked
   against the iteration by sampling; the inverted flag's life. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let julia_of (o : Scene.obj) =
  match o.shape with
  | Julia f -> f
  | _ ->
      Alcotest.fail "expected a julia fractal"

let parse text = julia_of (the_object (scene (v37 ^ text)))

let test_defaults () =
  let f = parse "julia_fractal { <-0.083, 0.0, -0.83, -0.025> }" in
  Alcotest.(check int) "max_iteration" 20 f.iterations;
  float_eq "precision" (1. /. 20.) f.precision;
  vec_eq "slice" (v 0. 0. 0.) (v f.s0 f.s1 f.s2);
  float_eq "slice t" 1. f.s3;
  Alcotest.(check bool) "quaternion" true (f.algebra = Quaternion);
  Alcotest.(check bool) "sqr" true (f.func = Sqr);
  (* R = 1 + |c| + 1e-7 = 1.83570… capped at 2? no: |c| = 0.83451…, R = 1.834515…, exit R² + 1e-7 *)
  let r = 1. +. sqrt ((0.083 *. 0.083) +. (0.83 *. 0.83) +. (0.025 *. 0.025)) +. 1e-7 in
  float_eq ~eps:0. "radius" r f.radius;
  float_eq ~eps:0. "exit" ((r *. r) +. 1e-7) f.exit_value;
  let big = parse "julia_fractal { <1, 1, 0, 0> }" in
  float_eq "radius capped at 2" 2. big.radius;
  let h = parse "julia_fractal { <1, 1, 0, 0> hypercomplex }" in
  float_eq "hypercomplex radius" 4. h.radius;
  float_eq "hypercomplex exit" 16. h.exit_value

let test_items () =
  let f = parse "julia_fractal { <1, 2, 3, 4> max_iteration 0.7 precision 0.5 slice <0, 0, 3, 4>, 0.25 hypercomplex pwr(2, 0.5) }" in
  Alcotest.(check int) "max_iteration floor 0 -> 1" 1 f.iterations;
  float_eq "precision below 1 -> 1" 1. f.precision;
  vec_eq "slice normalised" (v 0. 0. 0.6) (v f.s0 f.s1 f.s2);
  float_eq "slice t normalised" 0.8 f.s3;
  float_eq "slice distance" 0.25 f.slice_dist;
  Alcotest.(check bool) "pwr" true (f.func = Func Pwr);
  float_eq "exponent" 2. f.ex;
  float_eq "exponent y" 0.5 f.ey;
  let g = parse "julia_fractal { 0.5 max_iteration 7.9 precision 200 cube }" in
  vec_eq "a float is all four terms" (v 0.5 0.5 0.5) (v g.p0 g.p1 g.p2);
  float_eq "t term" 0.5 g.p3;
  Alcotest.(check int) "max_iteration floored" 7 g.iterations;
  float_eq "precision" (1. /. 200.) g.precision;
  Alcotest.(check bool) "cube" true (g.func = Cube);
  let fs = [ ("exp", Julia_algebra.Exp); ("ln", Ln); ("sin", Sin); ("asin", Asin); ("cos", Cos); ("acos", Acos); ("tan", Tan);
             ("atan", Atan); ("sinh", Sinh); ("asinh", Asinh); ("cosh", Cosh); ("acosh", Acosh); ("tanh", Tanh); ("atanh", Atanh) ] in
  List.iter
    (fun (k, e) ->
      let f = parse (Printf.sprintf "julia_fractal { <0, 0, 0, 0> hypercomplex %s }" k) in
      Alcotest.(check bool) k true (f.func = Func e))
    fs

let test_errors () =
  expect_scene_error "zero slice" (v37 ^ "julia_fractal { <0,0,0,0> slice <0,0,0,0>, 1 }") ~line:3 ~col:33 ~sub:"Slice vector is zero";
  expect_scene_error "slice t" (v37 ^ "julia_fractal { <0,0,0,0> slice <1,0,0,0>, 1 }") ~line:3 ~col:33 ~sub:"Slice t component is zero";
  expect_scene_error "quaternion sin" (v37 ^ "julia_fractal { <0,0,0,0> sin }") ~line:3 ~col:1 ~sub:"quaternion only supports sqr and cube";
  expect_scene_error "not a fractal function" (v37 ^ "julia_fractal { <0,0,0,0> hypercomplex sqrt }") ~line:3 ~col:40
    ~sub:"fractal keyword expected";
  expect_scene_error "a colour for the parameter" (v37 ^ "julia_fractal { <0,0,0,0,1> }") ~line:3 ~col:17 ~sub:"color expression"

let fractals =
  [|
    "julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15 }";
    "julia_fractal { <-0.2, 0.6, 0.2, 0.0> cube max_iteration 6 precision 30 slice <0,0,1,1>, 0.1 }";
    "julia_fractal { <-0.4, 0.4, 0.1, 0> hypercomplex sqr max_iteration 6 precision 30 rotate <10,20,30> scale <1,1.5,0.8> }";
    "julia_fractal { <0.3, 0.2, 0.1, 0.1> hypercomplex reciprocal max_iteration 5 precision 30 }";
  |]

(* the point and normal of the first crossing, as POV-Ray's trace() gives them *)
let first_hit f o d =
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let n = Julia.hits w f 0 o (Vec.normalize d) 0. 0 in
  if n = 0 then None
  else
    let h = w.hits.room in
    let p = v h.(3) h.(4) h.(5) in
    Some (h.(0), p, Julia.normal f p)

let test_trace () =
  let cases =
    [ (0, v 0. 1.2 (-3.2), v 0.05 (-0.3) 1., v 0.14802136458346660 0.31187181249919999 (-0.23957270833066732),
       v 0.73134400255195631 0.23294151098265828 (-0.64099469763204797));
      (0, v (-3.) 0.2 0.1, v 1. 0. 0.02, v (-0.44537591530391818) 0.20000000000000001 0.15109248169392164,
       v (-0.53826582453675564) 0.09093957781709273 0.83785434015836879);
      (1, v 0.1 0.2 (-3.), v 0. 0. 1., v 0.10000000000000001 0.20000000000000001 (-0.47583565589217397),
       v 0.97737827898413276 0.07697180463216038 (-0.19699502801259539));
      (2, v 0.3 5. (-0.2), v 0. (-1.) 0.1, v 0.30000000000000021 0.49589317283269441 0.25041068271673039,
       v 0.59333400415646731 0.61766926796724286 0.51617771641215182);
      (3, v (-4.) 0.05 0.1, v 1. 0.01 0., v (-1.85103506313081678) 0.07148964936869197 0.10000000000000001,
       v (-0.08619344233107384) (-0.82313662181972380) (-0.56126356760289797)) ]
  in
  List.iteri
    (fun i (k, o, d, ep, en) ->
      let f = parse fractals.(k) in
      match first_hit f o d with
      | None -> Alcotest.failf "case %d: no hit" i
      | Some (t, p, n) ->
          (* the point to POV-Ray's 17 printed digits, the normal (recomputed at it) closely *)
          vec_eq ~eps:1e-15 (Printf.sprintf "case %d: point" i) ep p;
          vec_eq ~eps:1e-9 (Printf.sprintf "case %d: normal" i) en n;
          Alcotest.(check bool) (Printf.sprintf "case %d: depth positive" i) true (t > 0.))
    cases

let test_inside () =
  let f1 = parse fractals.(0) and f3 = parse fractals.(2) in
  let stack = Array.make 512 0. in
  let check f p e = Alcotest.(check bool) (Printf.sprintf "inside %s" (Vec.to_string p)) e (Julia.inside stack f p) in
  (* POV-Ray's inside() of the same points *)
  check f1 (v 0. 0. 0.) true;
  check f1 (v 0.5 0.2 0.1) false;
  check f1 (v 0.2 0.5 (-0.3)) false;
  check f1 (v 1.9 0. 0.) false;
  check f3 (v 0. 0. 0.) true;
  check f3 (v 0.8 0.2 0.) true

(* Brute force: along random rays the first crossing found is where the iteration's verdict
   changes: a little before it the points are outside, just beyond it inside (to the tolerance of
   the bisection). *)
let test_sampling () =
  let f = parse fractals.(0) in
  let stack = Array.make 512 0. in
  let rng = Random.State.make [| 7 |] in
  let hits = ref 0 in
  for _ = 1 to 60 do
    let r () = Random.State.float rng 2. -. 1. in
    let o = v (3. *. r ()) (3. *. r ()) (-3.) in
    let target = v (0.3 *. r ()) (0.3 *. r ()) (0.3 *. r ()) in
    let d = Vec.normalize (Vec.sub target o) in
    match first_hit f o d with
    | None -> ()
    | Some (t, _, _) ->
        incr hits;
        let at s = Julia.inside stack f (Vec.madd o s d) in
        Alcotest.(check bool) "just beyond: inside" true (at (t +. 1e-6));
        (* everything before it, sampled at the march's own least step, is outside *)
        let k = ref 0.1 in
        while !k < t -. 1e-6 do
          Alcotest.(check bool) (Printf.sprintf "outside at %g before %g" !k t) false (at !k);
          k := !k +. (f.precision /. 4.)
        done
  done;
  Alcotest.(check bool) "some rays hit" true (!hits > 10)

let test_inverted () =
  let f = parse "julia_fractal { <-0.083, 0.0, -0.83, -0.025> inverse }" in
  Alcotest.(check bool) "inverse inside the block is cleared by SetUp_Fractal" false f.inverted;
  let o = the_object (scene (v37 ^ "#declare J = julia_fractal { <-0.083, 0.0, -0.83, -0.025> }\nobject { J inverse }")) in
  Alcotest.(check bool) "object { J inverse } keeps it" true (julia_of o).inverted;
  Alcotest.(check bool) "inverted inside" false (Julia.inside (Array.make 512 0.) (julia_of o) Vec.zero);
  let moved = the_object (scene (v37 ^ "#declare J = julia_fractal { <-0.083, 0.0, -0.83, -0.025> }\nobject { J inverse translate x }")) in
  Alcotest.(check bool) "a later transform clears it" false (julia_of moved).inverted

(* A function map: Iteration_HCompl_Func reads y for z, so the polished point's Iteration may
   escape; POV-Ray's normal is then Normal_Calc on the stack as the march left it, which
   the march reports (Julia.normal, iterating afresh, cannot know it). *)
let test_function_normal () =
  let f = parse "julia_fractal { <0.5, 0.2, 0.1, 0.0> hypercomplex sin max_iteration 5 precision 30 }" in
  let cases =
    [ (v (-0.2) 0.1 (-5.), v 0. 0. 1., v (-0.20000000000000001) 0.10000000000000001 (-1.46041171642394518),
       v (-0.79176812671258645) 0.49159075045786965 0.36254898646432604);
      (v 0.3 (-0.2) (-5.), v 0.01 0.02 1., v 0.33482143171879508 (-0.13035713656240772) (-1.51785682812032841),
       v 0.84721175004920946 0.33522980831284876 0.41213253474712042) ]
  in
  List.iteri
    (fun i (o, d, ep, en) ->
      let w = Scratch.create ~robust:false (Stats.create ()) in
      let t = Julia.depth w f o (Vec.normalize d) 0. in
      Alcotest.(check bool) (Printf.sprintf "case %d: a hit" i) true (t < infinity);
      vec_eq ~eps:1e-15 (Printf.sprintf "case %d: the march's point" i) ep (Crossing.point w.crossing);
      vec_eq ~eps:1e-12 (Printf.sprintf "case %d: the march's normal" i) en (Crossing.normal w.crossing))
    cases

(* In CSG every crossing is reported; after the first the depth lags behind the point by the
   step the march had taken past the crossing, as POV-Ray's does. *)
let test_later_crossings () =
  let f = parse fractals.(0) in
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let o = v 0. 0.05 (-3.) and d = v 0. 0. 1. in
  let n = Julia.hits w f 0 o d 0. 0 in
  Alcotest.(check bool) "several crossings" true (n >= 2);
  let h = w.hits.room in
  let depth k = h.(k * Scratch.hit_width) and along k = h.((k * Scratch.hit_width) + 5) -. o.z in
  float_eq ~eps:1e-12 "the first depth is its point's" (along 0) (depth 0);
  for k = 1 to n - 1 do
    Alcotest.(check bool) (Printf.sprintf "crossing %d: in order" k) true (depth k >= depth (k - 1));
    Alcotest.(check bool) (Printf.sprintf "crossing %d: the depth lags" k) true (depth k < along k -. 1e-9)
  done;
  (* each is pushed with its report: the point pushed, and the normal computed there *)
  for k = 0 to n - 1 do
    Alcotest.(check bool) (Printf.sprintf "crossing %d: reported" k) true (Scratch.hit_report w k);
    let p = Crossing.point w.crossing in
    vec_eq ~eps:0. (Printf.sprintf "crossing %d: its point" k) (v h.((k * Scratch.hit_width) + 3) h.((k * Scratch.hit_width) + 4) h.((k * Scratch.hit_width) + 5)) p;
    float_eq ~eps:1e-12 (Printf.sprintf "crossing %d: a unit normal" k) 1. (Vec.length (Crossing.normal w.crossing))
  done

let test_box () =
  let f = parse "julia_fractal { <-0.083, 0.0, -0.83, -0.025> }" in
  let b = Julia.pov_box f in
  float_eq "lower x" (Precision.f32 (-.f.radius)) b.(0);
  float_eq "length" (Precision.f32 (2. *. f.radius)) b.(3)

let tests =
  [
    Alcotest.test_case "defaults" `Quick test_defaults;
    Alcotest.test_case "items and clamps" `Quick test_items;
    Alcotest.test_case "errors" `Quick test_errors;
    Alcotest.test_case "trace() points and normals" `Quick test_trace;
    Alcotest.test_case "inside()" `Quick test_inside;
    Alcotest.test_case "crossings by sampling" `Quick test_sampling;
    Alcotest.test_case "inverted flag" `Quick test_inverted;
    Alcotest.test_case "function map normal" `Quick test_function_normal;
    Alcotest.test_case "later crossings in CSG" `Quick test_later_crossings;
    Alcotest.test_case "box" `Quick test_box;
  ]
