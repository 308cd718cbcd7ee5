(* The blob (shape/blob.cpp): parsing (components last written first, the old syntax, strength,
   threshold, sturm, hierarchy, component transforms), parse errors with their place, the
   intersection against brute-force sampling of the field and against POV-Ray's own trace(),
   the normal against the field's gradient and POV-Ray's, the inside test, the bounding sphere
   hierarchy (same field with and without), the texture weights and the box. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let blob_of (o : Scene.obj) =
  match o.shape with
  | Blob { blob; textures } -> (blob, textures)
  | _ ->
      Alcotest.fail "expected a blob"

let setup text =
  let c = compile (v37 ^ text) in
  (c.objects.(0), Trace.make_ctx ~robust:false c (Stats.create ()))

let compiled (obj : Compiled.obj) = match obj.shape with Blob b -> b | _ -> Alcotest.fail "expected a compiled blob"

(* the nearest depth along the unit (VNormalize) direction, and the normal there *)
let hit (obj, ctx) o d =
  let d = Transform.normalize d in
  let t = Shape.depth ctx.Context.shapes obj.Compiled.shape o d 0. in
  (t, d, if t < infinity then Shape.normal ctx.Context.shapes obj (-1) (Vec.madd o t d) else Vec.zero)

(* the scene of test/unit/data-free POV-Ray check below (printed by trace() in POV-Ray 3.7.0.10):
     #declare B1 = blob { ... as [b1] ... }
     #declare B2 = object { B1 scale <1, 0.5, 2> rotate <10, 20, 30> translate <0.1, 0.2, 0.3> }
     #macro T(Obj, O, D) #local N = <0, 0, 0>; #local P = trace(Obj, O, D, N);
       #debug concat(vstr(3, P, ", ", 0, 17), " | ", vstr(3, N, ", ", 0, 17), "\n") #end *)
let b1 =
  "blob { threshold 0.6\n\
  \  sphere { <-0.5, 0, 0>, 1.1, 1 }\n\
  \  sphere { <0.6, 0.1, 0>, 1.0, strength 1.5 }\n\
  \  cylinder { <0, -1, 0>, <0.2, 1, 0.3>, 0.4, 1 }\n\
  \  sphere { <0, 0.8, 0>, 0.5, -0.5 scale <1, 2, 1> } }"

let b2 = "object { B1 scale <1, 0.5, 2> rotate <10, 20, 30> translate <0.1, 0.2, 0.3> }"

let pov_traces =
  [
    ( "B1",
      v 0. 0. (-5.),
      v 0. 0. 1.,
      v 0.00000000000000000 0.00000000000000000 (-0.48147034760049845),
      v (-0.20251183030200581) (-0.11027376840125187) (-0.97305120861664751) );
    ( "B1",
      v (-3.) 0.2 (-4.),
      v 0.6 0. 0.8,
      v (-0.34181993350143891) 0.20000000000000001 (-0.45575991133525129),
      v 0.30288579367014312 0.38296329034973364 (-0.87269657627225350) );
    ( "B1",
      v 0.1 3. 0.05,
      v 0. (-1.) 0.,
      v 0.10000000000000001 0.77339417374970809 0.05000000000000000,
      v (-0.39231532228244398) 0.57069437738585116 (-0.72138520606025591) );
    ( "B1",
      v 2.5 1.5 (-2.),
      v (-0.7) (-0.4) 0.6,
      v 0.70745032874082447 0.47568590213761386 (-0.46352885320642101),
      v 0.17723635233552668 0.61968352911566349 (-0.76457805301588011) );
    ( "B2",
      v 0. 0. (-5.),
      v 0. 0. 1.,
      v 0.00000000000000000 0.00000000000000000 (-0.17769426448896919),
      v 0.01229157931341149 (-0.82864774447062461) (-0.55963544621631001) );
    ( "B2",
      v (-3.) 0.2 (-4.),
      v 0.6 0. 0.8,
      v (-0.36269288297129032) 0.20000000000000001 (-0.48359051062838665),
      v (-0.77776907981125709) 0.45023212583965877 (-0.43859581775417350) );
    ( "B2",
      v 0.1 3. 0.05,
      v 0. (-1.) 0.,
      v 0.10000000000000001 0.60017186724809335 0.05000000000000000,
      v (-0.55487157983567759) 0.83165668146107330 0.02155676394577816 );
  ]

let test_pov_trace () =
  List.iter
    (fun (which, o, d, p, n) ->
      let text = if which = "B1" then b1 else "#declare B1 = " ^ b1 ^ "\n" ^ b2 in
      let t, d', normal = hit (setup text) o d in
      let msg = Printf.sprintf "%s from %s" which (Vec.to_string o) in
      (* 17 printed digits: the point and normal agree to the last bit or two *)
      vec_eq ~eps:2e-16 (msg ^ ": point") p (Vec.madd o t d');
      vec_eq ~eps:2e-16 (msg ^ ": normal") n normal)
    pov_traces

let test_parse () =
  let b, texs = blob_of (the_object (scene (v37 ^ "blob { component 2, 1.5, <1, 2, 3> sphere { 0, 2, strength -1 } cylinder { 0, y, 0.5 3 } }"))) in
  float_eq "threshold 1 by default" 1. b.threshold;
  Alcotest.(check int) "no textures" 0 (Array.length texs);
  Alcotest.(check bool) "hierarchy on by default" true b.hierarchy;
  Alcotest.(check bool) "no sturm" false b.sturm;
  (match b.components with
  | [ cyl; sph; old ] ->
      (* the last written first, as POV-Ray links them *)
      Alcotest.(check bool) "cylinder" true (cyl.kind = Blob.Cylinder);
      float_eq "cylinder length" 1. cyl.len;
      float_eq "cylinder radius²" 0.25 cyl.rad2;
      float_eq "cylinder strength" 3. cyl.strength;
      float_eq "sphere strength" (-1.) sph.strength;
      float_eq "sphere radius²" 4. sph.rad2;
      vec_eq "old centre" (v 1. 2. 3.) old.origin;
      float_eq "old strength" 2. old.strength;
      float_eq "old radius²" 2.25 old.rad2
  | _ -> Alcotest.fail "three components");
  let b, _ = blob_of (the_object (scene (v37 ^ "blob { threshold 0.3 sphere { 0, 1, 1 scale <1, 2, 1> } sphere { x, 1, 1 scale 2 translate y } sturm hierarchy off }"))) in
  float_eq "threshold" 0.3 b.threshold;
  Alcotest.(check bool) "sturm" true b.sturm;
  Alcotest.(check bool) "hierarchy off" false b.hierarchy;
  match b.components with
  | [ uni; ell ] ->
      (* a uniform scale stays a sphere, moved and grown in place; a non-uniform one is an ellipsoid *)
      Alcotest.(check bool) "sphere" true (uni.kind = Blob.Sphere && uni.ctrans = None);
      vec_eq "moved centre" (v 2. 1. 0.) uni.origin;
      float_eq "scaled radius²" 4. uni.rad2;
      Alcotest.(check bool) "ellipsoid" true (ell.kind = Blob.Ellipsoid && ell.ctrans <> None)
  | _ -> Alcotest.fail "two components"

let test_object_id () =
  (* Parse_Object_Id: blob { B … } is object { B … }; sturm takes Allow_Float(1.0) > 0 *)
  let b, _ = blob_of (the_object (scene (v37 ^ "#declare B = blob { sphere { 0, 1, 1 } } blob { B translate x sturm -1 }"))) in
  Alcotest.(check bool) "moved" true (b.trans <> None);
  Alcotest.(check bool) "sturm -1 is off" false b.sturm;
  Alcotest.(check int) "one component" 1 (List.length b.components)

let test_errors () =
  expect_scene_error "no component" (v37 ^ "blob { threshold 0.5\n  pigment { rgb 1 } }") ~line:4 ~col:3 ~sub:"Need at least one component in a blob";
  expect_scene_error "degenerate cylinder" (v37 ^ "blob {\n cylinder { 1, 1, 1, 2 } }") ~line:4 ~col:22 ~sub:"Degenerate cylindrical component";
  expect_scene_error "a component modifier" (v37 ^ "blob {\n sphere { 0, 1, 1 hollow } }") ~line:4 ~col:19 ~sub:"blob component modifier";
  expect_scene_error "components come before the modifiers" (v37 ^ "blob { sphere { 0, 1, 1 } pigment { rgb 1 }\n sphere { x, 1, 1 } }") ~line:4 ~col:2
    ~sub:"object modifier"

(* brute force: the first sign change of field − threshold along the ray, sampled finely and
   bisected, against the solver's nearest depth *)
let brute (c : Blob.compiled) (o : Vec.t) (d : Vec.t) =
  let f t = Blob.field c (Vec.madd o t d) -. c.thresh in
  let step = 1e-3 in
  let rec scan t prev =
    if t > 20. then infinity
    else
      let cur = f t in
      if (prev <= 0.) <> (cur <= 0.) then begin
        let lo = ref (t -. step) and hi = ref t in
        for _ = 1 to 60 do
          let m = 0.5 *. (!lo +. !hi) in
          if (f m <= 0.) = (prev <= 0.) then lo := m else hi := m
        done;
        0.5 *. (!lo +. !hi)
      end
      else scan (t +. step) cur
  in
  scan 1e-2 (f 1e-2)

let rays =
  [ (v 0. 0. (-5.), v 0. 0. 1.); (v (-3.) 0.2 (-4.), v 0.6 0. 0.8); (v 0.1 3. 0.05, v 0. (-1.) 0.); (v 2.5 1.5 (-2.), v (-0.7) (-0.4) 0.6);
    (v 4. (-0.3) 0.2, v (-1.) 0.05 0.); (v (-0.2) (-3.) (-3.), v 0.05 0.7 0.7) ]

let test_brute () =
  List.iter
    (fun text ->
      let ((obj, _) as s) = setup text in
      let c = compiled obj in
      List.iter
        (fun (o, d) ->
          let t, d, n = hit s o d in
          let e = brute c o d in
          let msg = Printf.sprintf "%s: ray from %s" (String.sub text 0 20) (Vec.to_string o) in
          if e = infinity then Alcotest.(check bool) (msg ^ ": miss") true (t = infinity)
          else begin
            float_eq ~eps:1e-9 (msg ^ ": depth") e t;
            (* the normal is the field's gradient reversed, made unit *)
            let p = Vec.madd o t d and h = 1e-6 in
            let g k = (Blob.field c (Vec.add p (Vec.scale h k)) -. Blob.field c (Vec.sub p (Vec.scale h k))) /. (2. *. h) in
            let grad = Vec.normalize (Vec.neg (v (g (v 1. 0. 0.)) (g (v 0. 1. 0.)) (g (v 0. 0. 1.)))) in
            vec_eq ~eps:1e-6 (msg ^ ": normal") grad n
          end)
        rays)
    [ b1; "#declare B1 = " ^ b1 ^ "\n" ^ b2; "blob { threshold 0.4 cylinder { <-1, 0, 0>, <1, 0.3, 0.2>, 0.7, 1 } sphere { <0, 0.5, 0>, 0.8, 0.7 } sturm }" ]

let test_inside () =
  let obj, _ = setup b1 in
  let c = compiled obj in
  (* as POV-Ray's inside() printed them: 1 0 0 *)
  Alcotest.(check bool) "centre" true (Blob.inside c (v 0. 0. 0.));
  Alcotest.(check bool) "in the negative component" false (Blob.inside c (v 0. 1.4 0.));
  Alcotest.(check bool) "outside" false (Blob.inside c (v 1.5 0. 0.));
  (* inverse: a CSG member with its Inside negated *)
  let obj, _ = setup (String.sub b1 0 (String.length b1 - 1) ^ " inverse }") in
  let stack = Array.make 512 0. in
  let inside_of (o : Compiled.obj) p =
    match o.shape with Csg { members = [| m |]; _ } -> Shape.inside_member stack m p | _ -> Shape.inside stack o.shape p
  in
  Alcotest.(check bool) "inverse: centre" false (inside_of obj (v 0. 0. 0.));
  Alcotest.(check bool) "inverse: outside" true (inside_of obj (v 1.5 0. 0.))

let test_hierarchy () =
  (* the hierarchy changes only the order of the sums: the same field to rounding *)
  let many = String.concat "\n" (List.init 12 (fun i -> Printf.sprintf "sphere { <%g, %g, %g>, 0.8, 1 }" (0.3 *. float i) (0.2 *. float (i mod 3)) (0.1 *. float (i mod 4)))) in
  let a = compiled (fst (setup ("blob { threshold 0.5 " ^ many ^ " }"))) in
  let b = compiled (fst (setup ("blob { threshold 0.5 " ^ many ^ " hierarchy off }"))) in
  Alcotest.(check bool) "a tree" true (a.tree.root >= 0);
  Alcotest.(check bool) "no tree" true (b.tree.root < 0);
  List.iter
    (fun p -> float_eq ~eps:1e-12 ("field at " ^ Vec.to_string p) (Blob.field b p) (Blob.field a p))
    [ v 0. 0. 0.; v 1.5 0.2 0.1; v 3. 0.5 0.; v 2.2 (-0.3) 0.4 ]

let test_weights () =
  (* Determine_Textures: weights proportional to the fields, summing to 1; −1 is the blob's own *)
  let obj, _ = setup "blob { sphere { <-0.5, 0, 0>, 1, 1 pigment { rgb x } } sphere { <0.5, 0, 0>, 1, 3 } }" in
  let c = compiled obj in
  Alcotest.(check bool) "textured" true c.textured;
  match Blob.weights c (v 0. 0. 0.) with
  | [ (w1, t1); (w2, t2) ] ->
      let ws = List.sort compare [ (t1, w1); (t2, w2) ] in
      (match ws with
      | [ (-1, own); (0, red) ] ->
          float_eq ~eps:1e-7 "the blob's own, 3 to 1" 0.75 own;
          float_eq ~eps:1e-7 "the red one" 0.25 red
      | _ -> Alcotest.fail "one of each")
  | _ -> Alcotest.fail "two weights"

let test_box () =
  (* Compute_BBox: the positive components' spheres; a negative one adds nothing *)
  let obj, _ = setup "blob { sphere { 0, 1, 1 } sphere { 3*x, 5, -1 } translate y }" in
  let b = Shape.pov_box obj.shape in
  float_eq "lower x" (-1.) b.(0);
  float_eq "lower y" 0. b.(1);
  float_eq "length x" 2. b.(3);
  float_eq "length z" 2. b.(5);
  (* a transform after the blob is set up maps its box (Recompute_BBox) *)
  let obj, _ = setup "#declare B = blob { sphere { 0, 1, 1 } } object { B rotate z*45 }" in
  let b = Shape.pov_box obj.shape in
  float_eq ~eps:1e-6 "mapped box" (-.sqrt 2.) b.(0)

let test_empty_box () =
  (* no component of positive strength: an empty box, never entered (POV-Ray's bounding box
     test); a transform maps that box to the whole space, and the blob is hit (checked by
     rendering against POV-Ray) *)
  let t, _, _ = hit (setup "blob { threshold -0.2 sphere { 0, 1, -1 } }") (v 0. 0. (-3.)) (v 0. 0. 1.) in
  Alcotest.(check bool) "never hit" true (t = infinity);
  let t, _, _ = hit (setup "blob { threshold -0.2 sphere { 0, 1, -1 } translate x*0.001 }") (v 0. 0. (-3.)) (v 0. 0. 1.) in
  Alcotest.(check bool) "moved: hit" true (t < infinity)

let test_dump () =
  let s = Dump.scene (scene (v37 ^ "blob { threshold 0.5 sphere { 0, 1, 2 } }")) in
  check_contains "dump" ~sub:"blob { threshold 0.5" s

let tests =
  [
    Alcotest.test_case "parse" `Quick test_parse;
    Alcotest.test_case "parse errors" `Quick test_errors;
    Alcotest.test_case "an object identifier first" `Quick test_object_id;
    Alcotest.test_case "POV-Ray's trace()" `Quick test_pov_trace;
    Alcotest.test_case "brute force" `Quick test_brute;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "hierarchy" `Quick test_hierarchy;
    Alcotest.test_case "texture weights" `Quick test_weights;
    Alcotest.test_case "box" `Quick test_box;
    Alcotest.test_case "empty box" `Quick test_empty_box;
    Alcotest.test_case "dump" `Quick test_dump;
  ]
