(* The isosurface, isosurface { function { … } … } (POV-Ray's isosurf.cpp): its reader's defaults,
   items, warnings and errors; trace() and inside() against POV-Ray's (the numbers printed by
   test/unit/data/iso_trace.pov), the cache of the last missed segment included; depths and
   normals against a sphere's; the end-of-render warning. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let iso_of (o : Scene.obj) =
  match o.shape with
  | Isosurface s -> s
  | _ -> Alcotest.fail "expected an isosurface"

let parse text = iso_of (the_object (scene (v37 ^ text)))

let test_defaults () =
  let s = parse "isosurface { function { x } }" in
  (match s.container with
  | Box_container { lo; hi } ->
      vec_eq "box lo" (v (-1.) (-1.) (-1.)) lo;
      vec_eq "box hi" (v 1. 1. 1.) hi
  | Sphere_container _ -> Alcotest.fail "a box by default");
  float_eq "threshold" 0. s.threshold;
  float_eq "accuracy" 0.001 s.accuracy;
  float_eq "max_gradient" 1.1 s.max_gradient;
  Alcotest.(check int) "max_trace" 1 s.max_trace;
  Alcotest.(check bool) "closed" true s.closed;
  Alcotest.(check bool) "no evaluate" true (s.evaluate = None);
  Alcotest.(check bool) "not a copy" false s.copy;
  Alcotest.(check bool) "no transform" true (Transform.is_identity s.trans);
  float_eq "the function" 0.25 (Fn.at_point s.fn 0.25 3. 4.)

let test_items () =
  let s =
    parse
      "isosurface { function { x + y } contained_by { box { <1, -2, 3>, <-1, 2, -3> } } threshold 0.5 accuracy 0.01 max_gradient 4 \
       max_trace 2.7 evaluate 1, 2 3 open }"
  in
  (match s.container with
  | Box_container { lo; hi } ->
      vec_eq "corners sorted (lo)" (v (-1.) (-2.) (-3.)) lo;
      vec_eq "corners sorted (hi)" (v 1. 2. 3.) hi
  | Sphere_container _ -> Alcotest.fail "a box");
  float_eq "threshold" 0.5 s.threshold;
  float_eq "accuracy" 0.01 s.accuracy;
  float_eq "max_gradient" 4. s.max_gradient;
  Alcotest.(check int) "max_trace truncated" 2 s.max_trace;
  Alcotest.(check bool) "open" false s.closed;
  (match s.evaluate with
  | Some e -> vec_eq "evaluate" (v 1. 2. 3.) (v e.p0 e.p1 e.p2)
  | None -> Alcotest.fail "evaluate");
  let t = parse "isosurface { function { x } contained_by { sphere { <1, 2, 3>, 0.5 } } all_intersections contained_by { } }" in
  (match t.container with
  | Sphere_container { centre; radius } ->
      vec_eq "centre" (v 1. 2. 3.) centre;
      float_eq "radius" 0.5 radius
  | Box_container _ -> Alcotest.fail "a sphere (an empty contained_by keeps it)");
  Alcotest.(check int) "all_intersections" 10 t.max_trace;
  let m = parse "isosurface { function { x } translate <1, 2, 3> }" in
  vec_eq "translated" (v 1. 2. 3.) (Transform.point m.trans Vec.zero)

let test_checks () =
  let check text what expect =
    let ws = warnings (v37 ^ text) in
    Alcotest.(check bool) (what ^ ": warned") true (List.exists (fun (e : Error.t) -> contains ~sub:expect e.msg) ws)
  in
  check "isosurface { function { x } accuracy 0 }" "accuracy" "Isosurface 'accuracy' is not positive. Using 0.001 (default).";
  float_eq "accuracy replaced" 0.001 (parse "isosurface { function { x } accuracy -1 }").accuracy;
  check "isosurface { function { x } max_gradient 0 }" "max_gradient" "Isosurface 'max_gradient' is not positive. Using 1.1 (default).";
  float_eq "max_gradient replaced" 1.1 (parse "isosurface { function { x } max_gradient -2 }").max_gradient;
  check "isosurface { function { x } max_trace 11 }" "max_trace" "Isosurface 'max_trace' exceeds maximum of 10. Using maximum.";
  Alcotest.(check int) "max_trace capped" 10 (parse "isosurface { function { x } max_trace 11 }").max_trace;
  check "isosurface { function { x } max_trace 0.9 }" "max_trace 0" "Isosurface 'max_trace' is not positive. Using 1 (default).";
  (* (short)70000 is 4464 *)
  Alcotest.(check int) "max_trace wraps as a short" 10 (parse "isosurface { function { x } max_trace 70000 }").max_trace;
  Alcotest.(check int) "max_trace wraps below 0" 1 (parse "isosurface { function { x } max_trace 40000 }").max_trace

let test_errors () =
  expect_scene_error "no function" (v37 ^ "isosurface { contained_by { box { -1, 1 } } }") ~line:3 ~col:14 ~sub:"'function'";
  expect_scene_error "a cone container" (v37 ^ "isosurface { function { x } contained_by { cone { 0, 1, y, 1 } } }") ~line:3 ~col:44
    ~sub:"'}'";
  expect_scene_error "a box of one corner" (v37 ^ "isosurface { function { x } contained_by { box { 1 } } }") ~line:3 ~col:52
    ~sub:"expected";
  expect_scene_error "a modifier inside the container" (v37 ^ "isosurface { function { x } contained_by { sphere { 0, 1 translate x } } }")
    ~line:3 ~col:58 ~sub:"'}'";
  expect_scene_error "an item after a modifier" (v37 ^ "isosurface { function { x } pigment { rgb 1 } max_gradient 2 }") ~line:3 ~col:47
    ~sub:"max_gradient";
  expect_scene_error "an unknown variable" (v37 ^ "isosurface { function { x + w } }") ~line:3 ~col:29 ~sub:"w"

(* POV-Ray's trace() of these isosurfaces, in this order (its parser keeps one cache for all its
   trace() calls): the point and the normal *)
let declarations =
  {|#declare I1 = isosurface { function { x*x + y*y + z*z - 0.64 } max_gradient 2 }
#declare I2 = isosurface { function { y - 0.3*sin(3*x)*sin(3*z) } contained_by { box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> } } open max_gradient 1.5 }
#declare I3 = isosurface { function { x*x + y*y + z*z - 4 } contained_by { sphere { <0.1, 0, 0>, 1 } } }
#declare I4 = isosurface { function { y + 0.2*x } accuracy 0.0005 }
#declare I5 = isosurface { function { abs(x) + abs(y) + abs(z) } threshold 0.9 max_gradient 1.8 rotate <20, 30, 0> scale <1, 1.5, 0.8> translate <0.2, 0, 0> }
#declare I6 = isosurface { function { x*x + y*y + z*z - 0.5 } max_gradient 1 }
#declare I7 = isosurface { function { sqrt(x*x + z*z) - 0.5 + 0.1*sin(8*y) } contained_by { box { <-1, -1, -1>, <1, 1, 1> } } max_gradient 2 max_trace 3 }
|}

let traces =
  [
    ("I1", "<0, 0, -3>", "<0, 0, 1>", v 0. 0. (-0.79980468750000000), v 0.00062554344066954 0.00062554344066954 (-0.99999960869532745));
    ("I1", "<0.3, 0.4, -3>", "<0.1, -0.2, 1>", v 0.54174804687500000 (-0.08349609374999994) (-0.58251953125000044),
     v 0.67798591775150141 (-0.10377203406289262) (-0.72771317170785388));
    ("I1", "<0, 0, 0>", "<1, 0, 0>", v 0.80080566406249998 0. 0., v 0.99999961064717524 0.00062398136911081 0.00062398136911081);
    ("I1", "<0.95, 0.95, -3>", "<0, 0, 1>", Vec.zero, Vec.zero);
    ("I2", "<0.2, 3, -0.4>", "<0, -1, 0.1>", v 0.20000000000000001 (-0.04785156250000000) (-0.09521484375000000),
     v 0.18468969788791728 0.88330816986759364 (-0.43087862854779907));
    ("I2", "<0.3, -3, 0.5>", "<0.1, 1, 0>", v 0.62851562499999991 0.28515625000000000 0.5,
     v 0.26848151747122284 0.96159813375720915 (-0.05697985548421601));
    ("I3", "<0.3, 0.2, -3>", "<0, 0, 1>", v 0.29999999999999999 0.20000000000000001 (-0.95916630466254382),
     v 0.20000000000000004 0.20000000000000007 (-0.95916630466254404));
    ("I3", "<-3, 0.1, 0.2>", "<1, 0.05, 0>", v (-0.85765465466416346) 0.20711726726679180 0.20000000000000001,
     v (-0.95765465466416255) 0.20711726726679161 0.19999999999999984);
    ("I4", "<0.3, -0.5, -3>", "<0, 0, 1>", v 0.29999999999999999 (-0.5) (-1.), v 0. 0. (-1.));
    ("I4", "<-3, -0.3, 0.2>", "<1, 0.1, 0>", v (-1.) (-0.09999999999999998) 0.20000000000000001, v (-1.) 0. 0.);
    ("I4", "<0.1, 3, 0.1>", "<0.05, -1, 0>", v 0.25253906250000002 (-0.05078125000000000) 0.10000000000000001,
     v 0.19611613513818929 0.98058067569091922 0.);
    ("I5", "<0.1, 0.2, -4>", "<0, 0, 1>", v 0.10000000000000001 0.20000000000000001 (-0.49746565494742123),
     v 0.10909990373609522 (-0.19305796524474861) (-0.97510298587397026));
    ("I5", "<3, 2, -2>", "<-1, -0.6, 0.7>", v 0.49210149464257391 0.49526089678554430 (-0.24447104624980187),
     v 0.34712622694312534 0.52294853668251939 (-0.77847813748996286));
    ("I6", "<0.1, 0.2, -3>", "<0, 0, 1>", v 0.10000000000000001 0.20000000000000001 (-0.66992187500000000),
     v 0.14235268183533858 0.28399714137300791 (-0.94819899687051290));
    ("I6", "<0.9, 0.9, -3>", "<0, 0, 1>", Vec.zero, Vec.zero);
    (* the same ray as two calls before: the miss just before is cached, and its segment is close
       enough for POV-Ray to answer "no root" without searching *)
    ("I6", "<0.1, 0.2, -3>", "<0, 0, 1>", Vec.zero, Vec.zero);
    ("I7", "<0, 0.1, -3>", "<0, 0, 1>", v 0. 0.10000000000000001 (-0.42773437500000000),
     v 0.00102205727386611 0.48531415147670454 (-0.87433925325091932));
    ("I7", "<0.05, 0.3, 0>", "<0, 0, 1>", v 0.05 0.29999999999999999 0.42962402343750000,
     v 0.10044317423828235 (-0.50941389984545216) 0.85463948387210953);
  ]

(* the points and normals as spheres' centres: P, N, P, N … *)
let test_trace () =
  let calls =
    List.mapi
      (fun i (iso, o, d, _, _) ->
        Printf.sprintf "#declare N%d = <0,0,0>;\n#declare P%d = trace(%s, %s, %s, N%d);\nsphere { P%d, 1 }\nsphere { N%d, 1 }\n" i i iso o d i i i)
      traces
  in
  let s = scene (v37 ^ declarations ^ String.concat "" calls) in
  let rec check i cases objs =
    match (cases, objs) with
    | [], [] -> ()
    | (_, _, _, ep, en) :: cases, p :: n :: objs ->
        vec_eq ~eps:0. (Printf.sprintf "trace %d: point" i) ep (fst (sphere_of p));
        vec_eq ~eps:1e-15 (Printf.sprintf "trace %d: normal" i) en (fst (sphere_of n));
        check (i + 1) cases objs
    | _ -> Alcotest.fail "one point and one normal per trace"
  in
  check 0 traces s.objects

let test_inside () =
  let cases =
    [ ("I1", "<0, 0, 0>", true); ("I1", "<0.7, 0.3, 0>", true); ("I1", "<0.5, 0.5, 0.5>", false); ("I3", "<0.1, 0.9, 0>", true);
      ("I3", "<0.1, 1.01, 0>", false); ("I4", "<0.5, -0.2, 0.3>", true); ("I4", "<0.5, -0.05, 0.3>", false);
      ("I4", "<0.5, -1.5, 0>", false); ("I5", "<0.2, 0, 0>", true); ("I5", "<1.1, 0, 0>", false) ]
  in
  let calls = List.map (fun (iso, p, _) -> Printf.sprintf "sphere { 0, 1 + inside(%s, %s) }\n" iso p) cases in
  let s = scene (v37 ^ declarations ^ String.concat "" calls) in
  List.iter2
    (fun (iso, p, e) o -> Alcotest.(check bool) (Printf.sprintf "inside(%s, %s)" iso p) e (snd (sphere_of o) = 2.))
    cases s.objects

(* Along rays through a sphere function's isosurface the crossing is within the accuracy of the
   sphere's, the normal close to the sphere's, and the inside agrees with the sphere's. *)
let test_sphere () =
  let r = 0.8 in
  let c = Isosurface.compile ~slot:0 (parse "isosurface { function { x*x + y*y + z*z - 0.64 } max_gradient 2 accuracy 0.0001 }") in
  let rng = Random.State.make [| 11 |] in
  let hits = ref 0 in
  for _ = 1 to 200 do
    let rnd () = Random.State.float rng 2. -. 1. in
    let w = Scratch.create ~robust:false (Stats.create ()) in
    let o = v (3. *. rnd ()) (3. *. rnd ()) (-3.) and target = v (0.7 *. rnd ()) (0.7 *. rnd ()) (0.5 *. rnd ()) in
    let d = Vec.normalize (Vec.sub target o) in
    (* the sphere's nearer crossing *)
    let b = Vec.dot o d and cc = Vec.dot o o -. (r *. r) in
    let disc = (b *. b) -. cc in
    let t = Isosurface.depth w c o d 1e-4 in
    if disc > 0.01 then begin
      incr hits;
      let exact = -.b -. sqrt disc in
      Alcotest.(check bool) "a crossing" true (t < infinity);
      float_eq ~eps:2e-4 "depth" exact t;
      let p = Vec.madd o t d in
      let n = Isosurface.normal c w.part p in
      vec_eq ~eps:2e-3 "normal" (Vec.normalize p) n
    end
    else if disc < -0.01 then Alcotest.(check bool) "a miss" true (t = infinity)
  done;
  Alcotest.(check bool) "rays met the sphere" true (!hits > 50);
  Alcotest.(check bool) "inside" true (Isosurface.inside c (v 0.5 0.5 0.3));
  Alcotest.(check bool) "outside" false (Isosurface.inside c (v 0.5 0.5 0.4))

(* every crossing along a ray: an all_intersections isosurface gives the sphere's two *)
let test_all_crossings () =
  let c = Isosurface.compile ~slot:0 (parse "isosurface { function { x*x + y*y + z*z - 0.64 } max_gradient 2 all_intersections }") in
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let n = Isosurface.hits w c 7 (v 0. 0. (-3.)) (v 0. 0. 1.) 1e-4 0 in
  Alcotest.(check int) "two crossings" 2 n;
  let h = w.hits.room in
  float_eq ~eps:1e-3 "entry" 2.2 h.(0);
  float_eq ~eps:1e-3 "exit" 3.8 h.(Scratch.hit_width);
  float_eq "member id" 7. h.(2);
  let one = Isosurface.compile ~slot:1 (parse "isosurface { function { x*x + y*y + z*z - 0.64 } max_gradient 2 }") in
  Alcotest.(check int) "max_trace 1: the first" 1 (Isosurface.hits w one 0 (v 0. 0. (-3.)) (v 0. 0. 1.) 1e-4 0)

(* DispatchShutdownMessages: its tests and numbers *)
let test_warning () =
  let s = parse "isosurface { function { x } max_gradient 1.1 }" in
  let stats found =
    let st = Stats.create () in
    let g = Stats.iso_slot st s.key in
    Array.iteri (fun i x -> st.iso_found.(g + i) <- x) found;
    st
  in
  (match Isosurface.warning s (stats [| 1.787; 0.; 0.; 0.; 0. |]) with
  | Some m ->
      Alcotest.(check string) "holes"
        "The maximum gradient found was 1.787, but max_gradient of the isosurface was set to 1.100. The isosurface may contain holes! \
         Adjust max_gradient to get a proper rendering of the isosurface."
        m
  | None -> Alcotest.fail "a warning");
  Alcotest.(check bool) "close enough: nothing" true (Isosurface.warning s (stats [| 1.12; 0.; 0.; 0.; 0. |]) = None);
  Alcotest.(check bool) "nothing found: nothing" true (Isosurface.warning s (stats [||]) = None);
  let big = parse "isosurface { function { x } max_gradient 20 }" in
  (match Isosurface.warning big (stats [| 3.5; 0.; 0.; 0.; 0. |]) with
  | Some m -> check_contains "faster" ~sub:"was 3.500, but max_gradient of the isosurface was set to 20.000. Adjust max_gradient to get a faster" m
  | None -> Alcotest.fail "a faster-rendering warning");
  let e = parse "isosurface { function { x } evaluate 1, 1.4, 0.9 }" in
  match Isosurface.warning e (stats [| 0.; 5.353; 10.; 51.8; 0.595 |]) with
  | Some m ->
      Alcotest.(check string) "evaluate"
        "Evaluate found a maximum gradient of 5.353 and an average gradient of 5.180. The maximum gradient variation was 0.595." m
  | None -> Alcotest.fail "an evaluate warning"

(* IsoSurface::Copy: an isosurface made from an identifier is a copy, in a CSG too; one written
   in place is not *)
let test_copies () =
  let s = scene (v37 ^ "#declare I = isosurface { function { x } }\nobject { I }\nisosurface { I }\nunion { object { I } sphere { 0, 1 } split_union off }\nisosurface { function { y } }\n") in
  let copy (o : Scene.obj) =
    match o.shape with
    | Isosurface i -> i.copy
    | Csg { members = m :: _; _ } -> (iso_of m.mobj).copy
    | _ -> Alcotest.fail "an isosurface"
  in
  Alcotest.(check (list bool)) "copies" [ true; true; true; false ] (List.map copy s.objects)

let tests =
  [
    Alcotest.test_case "defaults" `Quick test_defaults;
    Alcotest.test_case "items" `Quick test_items;
    Alcotest.test_case "POV-Ray's checks and warnings" `Quick test_checks;
    Alcotest.test_case "errors" `Quick test_errors;
    Alcotest.test_case "trace() points and normals, the cache" `Quick test_trace;
    Alcotest.test_case "inside()" `Quick test_inside;
    Alcotest.test_case "a sphere's crossings and normals" `Quick test_sphere;
    Alcotest.test_case "all_intersections" `Quick test_all_crossings;
    Alcotest.test_case "end-of-render warning" `Quick test_warning;
    Alcotest.test_case "copies" `Quick test_copies;
  ]
