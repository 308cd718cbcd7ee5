(* prism, lathe and sor (prism.cpp, lathe.cpp, sor.cpp, bcyl.cpp): parsing with POV-Ray's checks
   and located errors, depths against shapes known in closed form, depths against brute-force
   sampling of the inside test along the ray, normals, the inside rule, hit points and normals
   that POV-Ray's trace() printed, and the degree-6 solver. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
let v = Vec.make

let setup text =
  let c = compile (v37 ^ text) in
  (c.objects.(0), Trace.make_ctx ~robust:false c (Stats.create ()))

(* the nearest depth from [o] along [d] (normalised), the world normal there, and the hit point *)
let hit (obj, ctx) o d =
  let d = Vec.normalize d in
  let t = Shape.depth ctx.Context.shapes obj.Compiled.shape o d 0. in
  let p = Vec.madd o t d in
  (t, (if t < infinity then Shape.normal ctx.Context.shapes obj ctx.Context.shapes.part p else Vec.zero), p)

let depth s o d = let t, _, _ = hit s o d in t
let inside (obj, _) p = Shape.inside [||] obj.Compiled.shape p

(* the scene shape, looked for through an inverse's one-member intersection *)
let rec shape_of (o : Scene.obj) =
  match o.shape with Csg { members = [ m ]; _ } -> shape_of m.mobj | s -> s

let prism_of text = match shape_of (the_object (scene (v37 ^ text))) with Prism p -> p | _ -> Alcotest.fail "expected a prism"
let lathe_of text = match shape_of (the_object (scene (v37 ^ text))) with Lathe l -> l | _ -> Alcotest.fail "expected a lathe"
let sor_of text = match shape_of (the_object (scene (v37 ^ text))) with Sor s -> s | _ -> Alcotest.fail "expected a sor"

let square = "prism { 0, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> }"
let tube = "lathe { linear_spline 2, <1,0>, <1,2> }"
let can = "sor { 4, <1,-1>, <1,0>, <1,2>, <1,3> }"

(* ---------------------------------------------------------------------------------------------- *)

let test_parse () =
  let p = prism_of square in
  Alcotest.(check bool) "linear spline by default" true (p.spline = Prism.Linear);
  Alcotest.(check bool) "linear sweep by default" false p.conic;
  Alcotest.(check bool) "closed by default" true p.closed;
  Alcotest.(check int) "4 segments" 4 (Array.length p.segs);
  let p = prism_of "prism { conic_sweep cubic_spline 1, 0.2, 8, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1,0> open sturm }" in
  float_eq "heights swapped: low" 0.2 p.height1;
  float_eq "heights swapped: high" 1. p.height2;
  Alcotest.(check bool) "conic" true p.conic;
  Alcotest.(check bool) "open" false p.closed;
  Alcotest.(check bool) "sturm" true p.sturm;
  Alcotest.(check int) "cubic: 4 segments" 4 (Array.length p.segs);
  (* a linear outline left open is closed with its first point, as POV-Ray warns *)
  let p = prism_of "prism { 0, 1, 3, <0,0>, <1,0>, <0,1> }" in
  Alcotest.(check int) "closed for us: 3 segments" 3 (Array.length p.segs);
  Alcotest.(check bool) "warned" true
    (List.exists (fun (w : Error.t) -> contains ~sub:"Linear prism not closed" w.msg) (warnings (v37 ^ "prism { 0, 1, 3, <0,0>, <1,0>, <0,1> }")));
  (* a Bezier outline that does not close is ignored *)
  let p = prism_of "prism { bezier_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }" in
  Alcotest.(check bool) "degenerate" true p.degenerate;
  let l = lathe_of "lathe { bezier_spline 8, <0,0>, <1,0>, <1,1>, <0.5,1>, <0.5,1>, <0,1>, <0.8,2>, <0,2> sturm }" in
  Alcotest.(check int) "bezier lathe: 2 segments" 2 (Array.length l.segs);
  Alcotest.(check bool) "lathe sturm" true l.sturm;
  let s = sor_of "sor { 5, <0,-0.2>, <0.8,0>, <0.3,0.7>, <0.9,1.4>, <0.5,2> open }" in
  Alcotest.(check int) "sor: n − 3 segments" 2 (Array.length s.segs);
  Alcotest.(check bool) "sor open" false s.closed;
  float_eq "sor heights from the second point" 0. s.height1;
  float_eq "… to the last but one" 1.4 s.height2

let test_errors () =
  expect_scene_error "prism: too few points" "prism { 0, 1, 2, <0,0>, <1,0> }" ~line:1 ~col:15 ~sub:"at least three points";
  expect_scene_error "prism: quadratic" "prism { quadratic_spline 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> }" ~line:1 ~col:32 ~sub:"at least five points";
  expect_scene_error "prism: bezier" "prism { bezier_spline 0, 1, 5, <0,0>, <1,0>, <0,1>, <0,0>, <1,1> }" ~line:1 ~col:29 ~sub:"four points per segment";
  expect_scene_error "lathe: too few" "lathe { 1, <0,0> }" ~line:1 ~col:9 ~sub:"at least two points";
  expect_scene_error "lathe: negative radius" "lathe { 3, <0,0>, <-1,1>, <0,2> }" ~line:1 ~col:19 ~sub:"Incorrect point in lathe";
  expect_scene_error "sor: too few" "sor { 3, <0,0>, <1,1>, <0,2> }" ~line:1 ~col:7 ~sub:"at least four points";
  expect_scene_error "sor: heights must grow" "sor { 5, <0,0>, <1,1>, <1,2>, <1,1.5>, <0,3> }" ~line:1 ~col:31 ~sub:"Incorrect point in surface of revolution";
  expect_scene_error "sor: negative radius" "sor { 4, <0,0>, <-1,1>, <1,2>, <0,3> }" ~line:1 ~col:17 ~sub:"Incorrect point in surface of revolution";
  expect_scene_error "sturm elsewhere" "sphere { 0, 1 sturm }" ~line:1 ~col:15 ~sub:"not supported yet"

(* ---------------------------------------------------------------------------------------------- *)

let test_closed_forms () =
  let s = setup square in
  float_eq "prism side" 4. (depth s (v (-5.) 0.5 0.) (v 1. 0. 0.));
  float_eq "prism cap" 4. (depth s (v 0.2 5. 0.1) (v 0. (-1.) 0.));
  float_eq "prism base" 5. (depth s (v 0.2 (-5.) 0.1) (v 0. 1. 0.));
  Alcotest.(check bool) "prism: above the cap misses" true (depth s (v (-5.) 1.5 0.) (v 1. 0. 0.) = infinity);
  let _, n, _ = hit s (v (-5.) 0.5 0.3) (v 1. 0. 0.) in
  vec_eq "prism side normal" (v (-1.) 0. 0.) n;
  let s = setup ("object { " ^ square ^ " scale <2, 1, 1> translate 3*z }") in
  float_eq "scaled prism: world depth" 3. (depth s (v (-5.) 0.5 3.) (v 1. 0. 0.));
  let s = setup tube in
  float_eq "lathe tube" 4. (depth s (v (-5.) 1. 0.) (v 1. 0. 0.));
  let _, n, _ = hit s (v 0. 1. (-5.)) (v 0. 0. 1.) in
  vec_eq "lathe tube normal" (v 0. 0. (-1.)) n;
  Alcotest.(check bool) "lathe: no caps" true (depth s (v 0. 5. 0.) (v 0. (-1.) 0.) = infinity);
  let s = setup can in
  float_eq "sor wall" 4. (depth s (v (-5.) 1. 0.) (v 1. 0. 0.));
  float_eq "sor cap" 3. (depth s (v 0.3 5. 0.) (v 0. (-1.) 0.));
  let _, n, _ = hit s (v 0.3 5. 0.) (v 0. (-1.) 0.) in
  vec_eq "sor cap normal" (v 0. 1. 0.) n;
  let s = setup "sor { 4, <1,-1>, <1,0>, <1,2>, <1,3> open }" in
  Alcotest.(check bool) "open sor: no cap" true (depth s (v 0.3 5. 0.) (v 0. (-1.) 0.) = infinity);
  float_eq "open sor: the wall from inside" 1. (depth s (v 0. 1. 0.) (v 1. 0. 0.))

(* the first change of the inside test along the ray, sampled every [step] *)
let brute s o d ~far ~step =
  let d = Vec.normalize d in
  let start = inside s o in
  let rec go t = if t > far then infinity else if inside s (Vec.madd o t d) <> start then t else go (t +. step) in
  go step

let test_brute_force () =
  let shapes =
    [ "prism { cubic_spline 0, 1.2, 8, <0,-1.2>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1, 0.3> }";
      "prism { conic_sweep quadratic_spline 0.3, 1, 6, <0,-1>, <0.8,0>, <0,0.8>, <-0.8,0>, <0.8,0>, <0,0.8> }";
      "prism { bezier_spline -0.2, 0.6, 8, <0,0>,<1,0>,<1,1>,<0,1>, <0,1>,<-1,1>,<-1,0>,<0,0> }";
      "lathe { cubic_spline 7, <0,-0.5>, <0,0>, <0.8,0.2>, <0.3,1>, <0.7, 1.6>, <0, 2>, <0, 2.5> }";
      "lathe { quadratic_spline 6, <0,0>, <0.8,0>, <0.4,1>, <0.8, 1.5>, <0.3, 2>, <0, 2.2> }";
      "lathe { bezier_spline 8, <0,0>, <1,0>, <1,1>, <0.5,1>, <0.5,1>, <0,1>, <0.8,2>, <0,2> }";
      "sor { 7, <0,0>, <0.6,0>, <1,0.5>, <0.5,1>, <0.8,1.5>, <0.4,2>, <0,2.5> }" ]
  in
  let rng = Random.State.make [| 7 |] in
  List.iter
    (fun text ->
      let s = setup text in
      for _ = 1 to 40 do
        let o = v 0. 4. (-6.) in
        let target = v (Random.State.float rng 2. -. 1.) (Random.State.float rng 2.2) (Random.State.float rng 2. -. 1.) in
        let d = Vec.sub target o in
        let t = depth s o d and b = brute s o d ~far:12. ~step:1e-3 in
        if t < infinity || b < infinity then
          Alcotest.(check bool) (Printf.sprintf "%s: depth %g, inside changes at %g" text t b) true (Float.abs (t -. b) <= 1.1e-3)
      done)
    shapes

let test_inside () =
  let s = setup square in
  Alcotest.(check bool) "prism centre" true (inside s (v 0. 0.5 0.));
  Alcotest.(check bool) "prism base plane in" true (inside s (v 0. 0. 0.));
  Alcotest.(check bool) "prism cap plane out (y < height2)" false (inside s (v 0. 1. 0.));
  Alcotest.(check bool) "prism outside" false (inside s (v 1.5 0.5 0.));
  let s = setup ("object { " ^ square ^ " inverse }") in
  Alcotest.(check bool) "inverse prism" false (inside s (v 0. 0.5 0.));
  (* Lathe::Inside counts crossings only between the radii of the bounding cylinder: an open tube
     is not solid *)
  let s = setup tube in
  Alcotest.(check bool) "lathe tube: not solid" false (inside s (v 0.5 1. 0.2));
  let s = setup "lathe { linear_spline 4, <0,0>, <1,0>, <1,2>, <0,2> }" in
  Alcotest.(check bool) "closed lathe in" true (inside s (v 0.5 1. 0.2));
  Alcotest.(check bool) "closed lathe out" false (inside s (v 1.5 1. 0.));
  let s = setup can in
  Alcotest.(check bool) "sor in" true (inside s (v 0.5 1. 0.2));
  Alcotest.(check bool) "sor above" false (inside s (v 0. 2.5 0.))

(* hit points and normals POV-Ray 3.7.0.10 printed with trace() (24 decimals), from <0, 4, −6>:
     #declare Pr = prism { cubic_spline 0, 1.2, 8, <0,-1.2>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1, 0.3> }
     #declare La = lathe { cubic_spline 7, <0,-0.5>, <0,0>, <0.8,0.2>, <0.3,1>, <0.7, 1.6>, <0, 2>, <0, 2.5> }
     #declare Lq = lathe { quadratic_spline 6, <0,0>, <0.8,0>, <0.4,1>, <0.8, 1.5>, <0.3, 2>, <0, 2.2> }
     #declare So = sor { 7, <0,0>, <0.6,0>, <1,0.5>, <0.5,1>, <0.8,1.5>, <0.4,2>, <0,2.5> }
     #local P = trace(Obj, <0, 4, -6>, D, N); #debug concat(vstr(3, P, ", ", 0, 20), "\n") … *)
let test_pov_numbers () =
  let check name text d (px, py, pz) (nx, ny, nz) =
    let s = setup text in
    let _, n, p = hit s (v 0. 4. (-6.)) d in
    vec_eq ~eps:1e-15 (name ^ " point") (v px py pz) p;
    vec_eq ~eps:1e-12 (name ^ " normal") (v nx ny nz) n
  in
  let pr = "prism { cubic_spline 0, 1.2, 8, <0,-1.2>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1, 0.3> }" in
  let la = "lathe { cubic_spline 7, <0,-0.5>, <0,0>, <0.8,0.2>, <0.3,1>, <0.7, 1.6>, <0, 2>, <0, 2.5> }" in
  let lq = "lathe { quadratic_spline 6, <0,0>, <0.8,0>, <0.4,1>, <0.8, 1.5>, <0.3, 2>, <0, 2.2> }" in
  let so = "sor { 7, <0,0>, <0.6,0>, <1,0.5>, <0.5,1>, <0.8,1.5>, <0.4,2>, <0,2.5> }" in
  check "prism cap" pr (v 0.1 (-0.5) 1.) (0.55999999999999994227, 1.20000000000000017764, -0.40000000000000035527) (0., 1., 0.);
  check "cubic lathe" la (v (-0.1) (-0.4) 1.) (-0.57736148767295647488, 1.69055404930817410047, -0.22638512327043525119)
    (-0.52133177612079251162, 0.82850914100651562588, -0.20441570995250277210);
  check "quadratic lathe" lq (v 0.05 (-0.35) 1.) (0.28986597225585308824, 1.97093819420902871542, -0.20268055488293779121)
    (0.39878200336691693728, 0.87362625988727027337, -0.27883699866776701093);
  check "sor" so (v 0.05 (-0.35) 1.) (0.28592796218915667028, 1.99850426467590347457, -0.28144075621686681643)
    (0.55425569753462655687, 0.62862360914531334455, -0.54555749447287871234);
  check "sor, lower" so (v 0.02 (-0.6) 1.) (0.10617877586906794563, 0.81463672392796215860, -0.69106120654660241343)
    (0.08644756544297479972, 0.82216886672452993423, -0.56264124717077457216)

let test_sextic () =
  (* (x − 0.1)(x − 0.2)(x − 0.3)(x − 0.5)(x − 0.7)(x − 0.9), expanded *)
  let roots = [ 0.1; 0.2; 0.3; 0.5; 0.7; 0.9 ] in
  let c = List.fold_left (fun acc r -> let a = Array.append acc [| 0. |] in Array.mapi (fun i x -> x -. (if i > 0 then r *. acc.(i - 1) else 0.)) a) [| 1. |] roots in
  let w = Polysolv.create () and out = Array.make 6 0. in
  let n = Polysolv.solve w c 6 ~sturm:false ~eps:0. out in
  Alcotest.(check int) "six roots" 6 n;
  List.iter2 (fun e a -> float_eq ~eps:1e-9 "sextic root" e a) roots (List.sort compare (Array.to_list out));
  (* a quartic goes to Polysolv unchanged (small leading coefficients dropped first) *)
  let q = [| 0.; 1e-12; 1.; -10.; 35.; -50.; 24. |] and q4 = [| 1.; -10.; 35.; -50.; 24. |] in
  let a = Array.make 6 0. and b = Array.make 4 0. in
  let na = Polysolv.solve w q 6 ~sturm:false ~eps:0. a and nb = Polysolv.solve (Polysolv.create ()) q4 4 ~sturm:false ~eps:0. b in
  Alcotest.(check int) "same count" nb na;
  Alcotest.(check (list (float 0.))) "same roots, bit for bit" (Array.to_list (Array.sub b 0 nb)) (Array.to_list (Array.sub a 0 na))

let test_stats () =
  let obj, ctx = setup square in
  ignore (Shape.depth ctx.Context.shapes obj.Compiled.shape (v (-5.) 0.5 0.) (v 1. 0. 0.) 0.);
  ignore (Shape.depth ctx.Context.shapes obj.Compiled.shape (v (-5.) 0.5 5.) (v 1. 0. 0.) 0.);
  let s = ctx.Context.shapes.stats in
  (* the second ray misses the prism's box: a top-level prism is then not even tested *)
  Alcotest.(check int) "prism tests" 1 (Stats.tests s Stats.prism);
  Alcotest.(check int) "prism hits" 1 (Stats.hits s Stats.prism);
  let obj, ctx = setup tube in
  ignore (Shape.depth ctx.Context.shapes obj.Compiled.shape (v (-5.) 1. 0.) (v 1. 0. 0.) 0.);
  Alcotest.(check int) "lathe tests" 1 (Stats.tests ctx.Context.shapes.stats Stats.lathe);
  Alcotest.(check int) "lathe bound hits" 1 (Stats.hits ctx.Context.shapes.stats Stats.lathe_bound)

let test_dump () =
  let d text = Dump.obj (the_object (scene (v37 ^ text))) in
  check_contains "prism" ~sub:"prism { cubic_spline conic_sweep 0.2, 1 // 4 segments"
    (d "prism { conic_sweep cubic_spline 0.2, 1, 8, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1,0> open sturm }");
  check_contains "prism flags" ~sub:"open sturm"
    (d "prism { conic_sweep cubic_spline 0.2, 1, 8, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>, <0,1>, <-1,0> open sturm }");
  check_contains "lathe" ~sub:"lathe { bezier_spline // 2 segments, radius 0 … 1, height 0 … 2"
    (d "lathe { bezier_spline 8, <0,0>, <1,0>, <1,1>, <0.5,1>, <0.5,1>, <0,1>, <0.8,2>, <0,2> }");
  check_contains "sor" ~sub:"sor { // 2 segments" (d "sor { 5, <0,-0.2>, <0.8,0>, <0.3,0.7>, <0.9,1.4>, <0.5,2> open scale 2 }");
  check_contains "sor moved" ~sub:"matrix <2, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0>" (d "sor { 5, <0,-0.2>, <0.8,0>, <0.3,0.7>, <0.9,1.4>, <0.5,2> open scale 2 }")

let tests =
  [
    Alcotest.test_case "--dump" `Quick test_dump;
    Alcotest.test_case "parse" `Quick test_parse;
    Alcotest.test_case "errors" `Quick test_errors;
    Alcotest.test_case "closed forms" `Quick test_closed_forms;
    Alcotest.test_case "brute force" `Quick test_brute_force;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "POV-Ray trace()" `Quick test_pov_numbers;
    Alcotest.test_case "degree 6" `Quick test_sextic;
    Alcotest.test_case "statistics" `Quick test_stats;
  ]
