(* superellipsoid, ovus and sphere_sweep: POV-Ray 3.7.0.10's own hits and normals (trace()) and
   inside tests (inside()) for six shapes, printed with 20 decimals by
   test/unit/data/superq_trace.pov (its output is test/unit/data/superq_trace.txt); the hits
   against brute-force sampling of each shape's implicit surface or inside test; normals against
   the gradient; the parser's rules and errors; the dump; the degree-10 solver. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

(* the shapes of superq_trace.pov, in its order *)
let objects =
  [|
    "superellipsoid { <3, 3> scale 0.9 translate <2.2, 1, 0> }";
    "superellipsoid { <0.25, 0.6> rotate <20, 35, 10> }";
    "ovus { 1, 0.6 }";
    "ovus { 0.6, 1 scale <1, 1.3, 0.8> rotate 20*z }";
    "sphere_sweep { linear_spline 3, <-1, 0, 0>, 0.3, <0, 1, 0>, 0.5, <1, 0, 0.5>, 0.2 }";
    "sphere_sweep { cubic_spline 5, <-1.5, 0, 0>, 0.2, <-0.5, 0.5, 0>, 0.3, <0.5, -0.3, 0>, 0.4, <1.5, 0.5, 0>, 0.3, <2, 0, 0>, 0.2 }";
  |]

let rays =
  [|
    (v 0. 0. (-6.), v 0.37572848608453923713 0.17078567549297241079 0.91085693596251959825);
    (v 0.3 0.4 (-5.), v 0. 0. 1.);
    (v (-4.) 0.2 (-3.), v 0.8 0.05 0.6);
    (v 0.1 3. 0.05, v 0. (-1.) 0.01);
  |]

let points = [| v 0. 0.3 0.; v 0.5 0.5 0.1; v 0.9 0.2 0.3 |]

let traced =
  [
    (0, 0, (2.17729600419826718749, 0.98968000190830351936, -0.72170665648904730460), (-0.59855648655470627961, -0.77847744687047193413, -0.18895236732392989287));
    (0, 1, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (0, 2, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (0, 3, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (1, 0, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (1, 1, (0.29999999999999998890, 0.40000000000000002220, -1.02951597839643360643), (0.39052837840550636006, 0.24675611806634842327, -0.88690416836138064038));
    (1, 2, (-0.77057506765488881229, 0.40183905827156946033, -0.57793130074116660921), (-0.61285233155487039980, 0.24868532090553396863, -0.75004508589408869224));
    (1, 3, (0.10000000000000000555, 1.01831985911516853527, 0.06981680140884831409), (0.02450784679312829895, 0.96171415929340886564, 0.27295648235595387776));
    (2, 0, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (2, 1, (0.29999999999999998890, 0.40000000000000002220, -0.91588708068290891617), (0.30560795313650235272, 0.18999999999999886424, -0.93300792010556810041));
    (2, 2, (-0.77073063509697403717, 0.40182933530643916153, -0.57804797632273041685), (-0.78528530954796726959, 0.19091466765348233392, -0.58896398216097545220));
    (2, 3, (0.10000000000000000555, 1.58812310230501996244, 0.06411876897694980537), (0.16666666666666657415, 0.98020517050836597495, 0.10686461496158294882));
    (3, 0, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (3, 1, (0.29999999999999998890, 0.40000000000000002220, -0.65616563863895516207), (0.43231879302049192049, -0.12075600736040779937, -0.89359859438546462851));
    (3, 2, (-0.81909549609926846081, 0.39880653149379596822, -0.61432162207445140112), (-0.49445785499499406157, -0.24832619166951541700, -0.83297390845371876988));
    (3, 3, (0.09999999999999997780, 1.82380472274275229339, 0.06176195277257248706), (0.54784295679640782062, 0.82966254397905536688, 0.10736925913300948698));
    (4, 0, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (4, 1, (0.29999999999999998890, 0.40000000000000002220, -0.13057786154758677100), (-0.04197533543323316713, -0.69894607966186583781, -0.71394148845726579378));
    (4, 2, (-0.52155445905647512816, 0.41740284630897028784, -0.39116584429235601306), (-0.02322360267200775791, -0.17677639732799566019, -0.98397701681831328813));
    (4, 3, (0.10000000000000000555, 1.48554731037816334371, 0.06514452689621837156), (0.20000000000000001110, 0.97109462075632668743, 0.13028905379243674312));
    (5, 0, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (5, 1, (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000), (0.00000000000000000000, 0.00000000000000000000, 0.00000000000000000000));
    (5, 2, (-0.41405195811234252190, 0.42412175261797857573, -0.31053896858425655836), (-0.16187868342338590510, -0.06230943660252762084, -0.98484152327336460520));
    (5, 3, (0.10000000000000000555, 0.47723521707134919367, 0.07522764782928650917), (0.66240014076275610666, 0.71685904149988444178, 0.21757566071913742034));
  ]

let insides = [ (0, 0, false); (0, 1, false); (0, 2, false); (1, 0, true); (1, 1, true); (1, 2, true); (2, 0, true); (2, 1, true); (2, 2, true); (3, 0, true); (3, 1, true); (3, 2, false); (4, 0, false); (4, 1, true); (4, 2, true); (5, 0, true); (5, 1, false); (5, 2, true) ]

let setup text =
  let c = compile (v37 ^ text) in
  (c.objects.(0), Trace.make_ctx ~robust:false c (Stats.create ()))

(* the nearest hit beyond POV-Ray's MIN_ISECT_DEPTH, its point and normal *)
let hit (obj, ctx) o d =
  let t = Shape.depth ctx.Context.shapes obj.Compiled.shape o d 1e-4 in
  if t = infinity then None
  else
    let p = Vec.madd o t d in
    Some (t, p, Shape.normal ctx.Context.shapes obj ctx.Context.shapes.part p)

let test_traced () =
  List.iter
    (fun (i, j, (px, py, pz), (nx, ny, nz)) ->
      let o, d = rays.(j) in
      let d = Vec.normalize d in
      let msg = Printf.sprintf "%s, ray %d" objects.(i) j in
      match hit (setup objects.(i)) o d with
      | None -> if px <> 0. || py <> 0. || pz <> 0. then Alcotest.failf "%s: POV-Ray hits it, povml does not" msg
      | Some (_, p, n) ->
          if px = 0. && py = 0. && pz = 0. then Alcotest.failf "%s: povml hits it, POV-Ray does not" msg;
          vec_eq ~eps:1e-12 (msg ^ ": point") (v px py pz) p;
          vec_eq ~eps:1e-12 (msg ^ ": normal") (v nx ny nz) n)
    traced

let test_insides () =
  List.iter
    (fun (i, k, expected) ->
      let obj, _ = setup objects.(i) in
      Alcotest.(check bool) (Printf.sprintf "%s: inside %d" objects.(i) k) expected (Shape.inside [||] obj.Compiled.shape points.(k)))
    insides

(* Brute force: along the ray, the inside test is false up to the hit and true just beyond it
   (the rays enter each shape from outside); sampled every 1/1000 of the depth. *)
let test_sampled () =
  Array.iteri
    (fun _ text ->
      Array.iteri
        (fun j (o, d) ->
          let d = Vec.normalize d in
          let ((obj, _) as s) = setup text in
          match hit s o d with
          | None -> ()
          | Some (t, _, _) ->
              let inside x = Shape.inside [||] obj.Compiled.shape (Vec.madd o x d) in
              for k = 0 to 998 do
                let x = t *. Float.of_int k /. 1000. in
                if inside x then Alcotest.failf "%s, ray %d: inside at %g, before the hit at %g" text j x t
              done;
              Alcotest.(check bool) (Printf.sprintf "%s, ray %d: inside past the hit" text j) true (inside (t +. 1e-6)))
        rays)
    objects

(* the superellipsoid's value vanishes at its hits, and its normal is the gradient's direction *)
let test_superellipsoid_surface () =
  let s = Superellipsoid.make 0.5 0.8 in
  let o = v 0.2 0.3 (-4.) and d = Vec.normalize (v 0.05 0.02 1.) in
  let out = Array.make 11 0. in
  let n = Superellipsoid.intersect s ~near:1e-4 ~all:true o d out in
  Alcotest.(check int) "two hits" 2 n;
  for k = 0 to n - 1 do
    let p = Vec.madd o out.(k) d in
    float_eq ~eps:1e-9 "on the surface" 0. (Superellipsoid.value s p.x p.y p.z);
    let h = 1e-6 in
    let g a b = (Superellipsoid.value s a.Vec.x a.y a.z -. Superellipsoid.value s b.Vec.x b.y b.z) /. (2. *. h) in
    let grad = Vec.normalize (v (g (v (p.x +. h) p.y p.z) (v (p.x -. h) p.y p.z)) (g (v p.x (p.y +. h) p.z) (v p.x (p.y -. h) p.z)) (g (v p.x p.y (p.z +. h)) (v p.x p.y (p.z -. h)))) in
    vec_eq ~eps:1e-5 "normal along the gradient" grad (Superellipsoid.normal s p)
  done;
  (* alone, only the first hit *)
  Alcotest.(check int) "a shape alone stops at its first hit" 1 (Superellipsoid.intersect s ~near:1e-4 ~all:false o d out);
  float_eq "power multiplies out" 0.0625 (Superellipsoid.power 0.5 4.);
  float_eq "power of a fraction" (Float.pow 0.5 0.3) (Superellipsoid.power 0.5 0.3)

let test_parse () =
  (match (the_object (scene "superellipsoid { <0.5, 0.25> }")).shape with
  | Superellipsoid s ->
      float_eq "2/e" 4. s.ex;
      float_eq "e/n" 2. s.ey;
      float_eq "2/n" 8. s.ez
  | _ -> Alcotest.fail "expected a superellipsoid");
  (match (the_object (scene "ovus { 1, 0.6 sturm }")).shape with
  | Ovus o ->
      Alcotest.(check bool) "sturm" true o.sturm;
      float_eq "connecting radius 2·bottom" 2. o.crad
  | _ -> Alcotest.fail "expected an ovus");
  (* a top radius of twice the bottom one or more: POV-Ray's sphere, with its warning *)
  (match (the_object (scene "ovus { 1, 2 }")).shape with
  | Sphere { centre; radius; _ } ->
      vec_eq "centre" (v 0. 1. 0.) centre;
      float_eq "radius" 2. radius
  | _ -> Alcotest.fail "expected the sphere that replaces the ovus");
  Alcotest.(check bool) "the ovus warning" true (List.exists (fun (e : Error.t) -> contains ~sub:"twice first radius" e.msg) (warnings "ovus { 1, 2 }"));
  (match (the_object (scene "sphere_sweep { b_spline 4, <0,0,0>, 1, <1,0,0>, 1, <2,0,0>, 1 <3,0,0>, 1 tolerance 0.01 }")).shape with
  | Sphere_sweep s ->
      Alcotest.(check int) "four spheres, commas optional" 4 (Array.length s.spheres);
      float_eq "tolerance" 0.01 s.tolerance;
      Alcotest.(check bool) "no transform" true (s.trans = None)
  | _ -> Alcotest.fail "expected a sphere sweep");
  (* translate, rotate and a uniform scale move the modeling spheres; a non-uniform scale starts a
     transform *)
  (match (the_object (scene "sphere_sweep { linear_spline 2, <0,0,0>, 1, <1,0,0>, 0.5 scale 2 translate y }")).shape with
  | Sphere_sweep s ->
      let c, r = s.spheres.(1) in
      vec_eq "moved centre" (v 2. 1. 0.) c;
      float_eq "scaled radius" 1. r;
      Alcotest.(check bool) "still no transform" true (s.trans = None)
  | _ -> Alcotest.fail "expected a sphere sweep");
  match (the_object (scene "sphere_sweep { linear_spline 2, <0,0,0>, 1, <1,0,0>, 0.5 scale <1,2,1> translate y }")).shape with
  | Sphere_sweep s -> Alcotest.(check bool) "a transform" true (s.trans <> None)
  | _ -> Alcotest.fail "expected a sphere sweep"

let test_errors () =
  expect_scene_error "cubic sweep with 3 spheres" "sphere_sweep { cubic_spline 3, <0,0,0>, 1, <1,0,0>, 1, <2,0,0>, 1 }" ~line:1 ~col:29
    ~sub:"Too few modeling spheres";
  expect_scene_error "linear sweep with 1 sphere" "sphere_sweep { linear_spline 1.9, <0,0,0>, 1 }" ~line:1 ~col:30 ~sub:"Too few modeling spheres";
  expect_scene_error "no interpolation" "sphere_sweep { 2, <0,0,0>, 1, <1,0,0>, 1 }" ~line:1 ~col:16 ~sub:"Invalid type of interpolation";
  expect_scene_error "negative ovus radius" "ovus { -1, 0.5 }" ~line:1 ~col:1 ~sub:"Both Ovus radii must be positive";
  (* lemon is not a POV-Ray 3.7 shape: an identifier it does not know *)
  expect_scene_error "lemon" "sphere { 0, 1 }\nlemon { <0,-1,0>, 0, <0,1,0>, 0, 1.5 }" ~line:2 ~col:1 ~sub:"lemon"

let test_dump () =
  let d = Dump.scene (scene "superellipsoid { <1, 0.5> }\novus { 1, 0.5 }\nsphere_sweep { linear_spline 2, <0,0,0>, 1, <1,0,0>, 1 }") in
  check_contains "superellipsoid" ~sub:"superellipsoid { // powers 2, 2, 4" d;
  check_contains "ovus" ~sub:"ovus { 1, 0.5" d;
  check_contains "sphere_sweep" ~sub:"sphere_sweep { linear_spline 2" d

(* polysolve at degree 6 and 10: the roots of products of known factors *)
let test_high_degree () =
  let w = Polysolv.create () in
  let mul a b = Array.init (Array.length a + Array.length b - 1) (fun k -> let s = ref 0. in Array.iteri (fun i x -> let j = k - i in if j >= 0 && j < Array.length b then s := !s +. (x *. b.(j))) a; !s) in
  let poly roots = List.fold_left (fun acc r -> mul acc [| 1.; -.r |]) [| 1. |] roots in
  let check name rs =
    let c = poly rs in
    let n = Array.length c - 1 in
    let out = Array.make n 0. in
    let k = Polysolv.solve w c n ~sturm:true ~eps:1e-10 out in
    let got = List.sort compare (Array.to_list (Array.sub out 0 k)) in
    let want = List.sort compare (List.filter (fun r -> r >= 0.) rs) in
    Alcotest.(check int) (name ^ ": count") (List.length want) (List.length got);
    List.iter2 (fun e a -> float_eq ~eps:1e-7 name e a) want got
  in
  check "degree 6" [ 0.1; 0.3; 0.55; 0.9; 2.; -1. ];
  check "degree 10" [ 0.05; 0.2; 0.35; 0.5; 0.65; 0.8; 1.5; -0.5; -2.; 3. ];
  check "degree 3 through the small solver" [ 0.25; 0.5; 2. ]

let tests =
  [
    Alcotest.test_case "POV-Ray's hits and normals (trace)" `Quick test_traced;
    Alcotest.test_case "POV-Ray's inside tests" `Quick test_insides;
    Alcotest.test_case "hits against sampled inside tests" `Quick test_sampled;
    Alcotest.test_case "superellipsoid surface and gradient" `Quick test_superellipsoid_surface;
    Alcotest.test_case "parsing and placing" `Quick test_parse;
    Alcotest.test_case "parse errors and their locations" `Quick test_errors;
    Alcotest.test_case "dump" `Quick test_dump;
    Alcotest.test_case "Solve_Polynomial above degree 4" `Quick test_high_degree;
  ]
