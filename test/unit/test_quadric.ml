(* The quadric shape, quadric { <A,B,C>, <D,E,F>, <G,H,I>, J } (POV-Ray's quadrics.cpp): the roots
   in POV-Ray's order and depth limits, worked out by hand in the comments and checked against the
   implicit surface by sampling; Inside with the surface, inverse; the gradient normal; the
   transform of the coefficients; POV-Ray's box. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let q ?(mixed = Vec.zero) ?(linear = Vec.zero) sx sy sz j = Quadric.make ~square:(v sx sy sz) ~mixed ~linear j
let sphere = q 1. 1. 1. (-1.)
let cylinder_y = q 1. 0. 1. (-1.)

(* every root of the ray from [o] along [d] (normalised here), in the order found *)
let roots ?(lim = Limits.pov) ?(stats = Stats.create ()) quad o d =
  let out = Array.make 2 nan in
  let n = Quadric.intersect stats lim quad o (Vec.normalize d) out in
  List.init n (fun i -> out.(i))

let roots_eq ?(eps = 1e-12) msg expected actual =
  Alcotest.(check int) (msg ^ ": count") (List.length expected) (List.length actual);
  List.iteri (fun i (e, a) -> float_eq ~eps (Printf.sprintf "%s: root %d" msg i) e a) (List.combine expected actual)

(* the left side at [p] *)
let value (x : Quadric.t) (p : Vec.t) =
  (x.xx *. p.x *. p.x) +. (x.yy *. p.y *. p.y) +. (x.zz *. p.z *. p.z) +. (x.xy *. p.x *. p.y) +. (x.xz *. p.x *. p.z)
  +. (x.yz *. p.y *. p.z) +. (x.lx *. p.x) +. (x.ly *. p.y) +. (x.lz *. p.z) +. x.k

let test_roots () =
  (* the unit sphere from z = −5 along +z: a = 1, b = −5, c = 24, Δ = 1: (5 + 1)/1 first, then 4 *)
  roots_eq "sphere" [ 6.; 4. ] (roots sphere (v 0. 0. (-5.)) (v 0. 0. 1.));
  (* from the centre: the root −1 is behind *)
  roots_eq "from inside" [ 1. ] (roots sphere Vec.zero (v 1. 0. 0.));
  (* a tangent ray: Δ = 25 − 25 = 0 is no hit (Δ ≤ 0) *)
  roots_eq "tangent" [] (roots sphere (v 1. 0. (-5.)) (v 0. 0. 1.));
  (* on the surface: the root 0 is not beyond 1e-6; going in, the far side at 2 *)
  roots_eq "on the surface, outward" [] (roots sphere (v 1. 0. 0.) (v 1. 0. 0.));
  roots_eq "on the surface, inward" [ 2. ] (roots sphere (v 1. 0. 0.) (v (-1.) 0. 0.));
  (* beyond 1e7 nothing *)
  roots_eq "beyond 1e7" [] (roots sphere (v 0. 0. (-2e7)) (v 0. 0. 1.));
  (* the robust mode's limits have no horizon *)
  roots_eq "robust, beyond 1e7" [ 2e7 +. 1.; 2e7 -. 1. ] (roots ~lim:Limits.robust sphere (v 0. 0. (-2e7)) (v 0. 0. 1.));
  (* an infinite cylinder across: 6 then 4; along its axis: a = 0 and b = 0, no root *)
  roots_eq "cylinder across" [ 6.; 4. ] (roots cylinder_y (v (-5.) 3. 0.) (v 1. 0. 0.));
  roots_eq "cylinder along its axis" [] (roots cylinder_y (v 0.5 (-5.) 0.) (v 0. 1. 0.));
  (* the plane y = 0 as a quadric: a = 0, so the one root −c/2b: from y = 2 along (0,−1,1)/√2,
     b = −0.5/√2, c = 2: t = 2√2 *)
  let floor = q ~linear:(v 0. 1. 0.) 0. 0. 0. 0. in
  roots_eq "linear" [ 2. *. sqrt 2. ] (roots floor (v 0. 2. 0.) (v 0. (-1.) 1.));
  roots_eq "parallel to the plane" [] (roots floor (v 0. 2. 0.) (v 1. 0. 0.));
  (* the paraboloid y = x² + z² down its axis: a = 0, b = 0.5, c = −5: the vertex at 5 *)
  let bowl = q ~linear:(v 0. (-1.) 0.) 1. 0. 1. 0. in
  roots_eq "paraboloid down its axis" [ 5. ] (roots bowl (v 0. 5. 0.) (v 0. (-1.) 0.));
  (* statistics: every test, and each one with roots whatever their depth *)
  let stats = Stats.create () in
  ignore (roots ~stats sphere (v 1. 0. 0.) (v 1. 0. 0.));
  ignore (roots ~stats sphere (v 1. 0. (-5.)) (v 0. 0. 1.));
  ignore (roots ~stats floor (v 0. 2. 0.) (v 0. (-1.) 0.));
  Alcotest.(check (pair int int)) "tests and successes" (3, 2) (Stats.tests stats Stats.quadric, Stats.hits stats Stats.quadric)

(* Random quadrics and rays: every root lies on the surface, and wherever the left side changes
   sign along the ray (sampled every 1e-3 up to 20) a root was found there. *)
let test_sampled () =
  let rs = Random.State.make [| 37 |] in
  let r a = Random.State.float rs (2. *. a) -. a in
  let checked = ref 0 in
  for _ = 1 to 60 do
    let x = q ~mixed:(v (r 1.) (r 1.) (r 1.)) ~linear:(v (r 2.) (r 2.) (r 2.)) (r 2.) (r 2.) (r 2.) (r 3.) in
    let o = v (r 3.) (r 3.) (r 3.) and d = Vec.normalize (v (r 1.) (r 1.) (r 1.)) in
    let found = roots x o d in
    let scale = 1. +. Float.abs x.k +. (10. *. (Float.abs x.xx +. Float.abs x.yy +. Float.abs x.zz)) in
    List.iter
      (fun t ->
        let f = value x (Vec.madd o t d) in
        if Float.abs f > 1e-9 *. scale *. (1. +. (t *. t)) then Alcotest.failf "root %g is off the surface: %g" t f)
      found;
    let h = 1e-3 in
    let f0 = ref (value x (Vec.madd o h d)) in
    for k = 2 to 20_000 do
      let t = float_of_int k *. h in
      let f = value x (Vec.madd o t d) in
      if (f < 0.) <> (!f0 < 0.) then begin
        incr checked;
        if not (List.exists (fun r -> r >= t -. (2. *. h) && r <= t +. h) found) then
          Alcotest.failf "a sign change near %g has no root (found %s)" t (String.concat ", " (List.map string_of_float found))
      end;
      f0 := f
    done
  done;
  if !checked < 30 then Alcotest.failf "only %d sign changes sampled" !checked

let test_inside () =
  Alcotest.(check bool) "centre" true (Quadric.inside sphere Vec.zero);
  Alcotest.(check bool) "outside" false (Quadric.inside sphere (v 2. 0. 0.));
  (* the surface itself is inside: 1 − 1 = 0 ≤ 0 *)
  Alcotest.(check bool) "on the surface" true (Quadric.inside sphere (v 1. 0. 0.));
  (* inverse negates the coefficients: outside and the surface are inside *)
  let inv = Quadric.invert sphere in
  Alcotest.(check bool) "inverted: centre" false (Quadric.inside inv Vec.zero);
  Alcotest.(check bool) "inverted: outside" true (Quadric.inside inv (v 2. 0. 0.));
  Alcotest.(check bool) "inverted: on the surface" true (Quadric.inside inv (v 1. 0. 0.));
  (* through the scene: an inverted member is asked as it is, its surface included *)
  let c = compile (v37 ^ "intersection { box { -3, 3 } quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 inverse } }") in
  let m = match c.objects.(0).shape with Csg { members = [| _; m |]; _ } -> m | _ -> Alcotest.fail "expected an intersection of two" in
  Alcotest.(check int) "the member's object" 2 m.id;
  Alcotest.(check bool) "the member is flagged" true m.inverted;
  let stack = Array.make 512 0. in
  Alcotest.(check bool) "member: centre" false (Shape.inside_member stack m Vec.zero);
  Alcotest.(check bool) "member: outside" true (Shape.inside_member stack m (v 2. 0. 0.));
  Alcotest.(check bool) "member: on the surface" true (Shape.inside_member stack m (v 0. 1. 0.));
  Alcotest.(check bool) "the CSG: between" true (Shape.inside stack c.objects.(0).shape (v 2. 0. 0.))

let test_normal () =
  vec_eq "sphere" (v 0.6 0.8 0.) (Quadric.normal sphere (v 0.6 0.8 0.));
  (* the gradient (2x, 0, 2z) of the cylinder, normalised *)
  vec_eq "cylinder" (v 0.6 0. 0.8) (Quadric.normal cylinder_y (v 0.6 7. 0.8));
  (* the cone's apex has no gradient: <1,0,0> *)
  vec_eq "apex" (v 1. 0. 0.) (Quadric.normal (q 1. (-1.) 1. 0.) Vec.zero);
  (* x²/4 + y² = 1 at (√2, √½): gradient (x/2, 2y) = (√2/2, √2), so (1, 2)/√5 *)
  let e = Quadric.transform sphere (Transform.scale (v 2. 1. 1.)) in
  vec_eq ~eps:1e-12 "ellipse" (Vec.scale (1. /. sqrt 5.) (v 1. 2. 0.)) (Quadric.normal e (v (sqrt 2.) (sqrt 0.5) 0.))

let test_transform () =
  (* scale 2: x² + y² + z² = 4, i.e. ¼ of each square term *)
  let s = Quadric.transform sphere (Transform.scale (v 2. 2. 2.)) in
  vec_eq "scaled" (v 0.25 0.25 0.25) (v s.xx s.yy s.zz);
  float_eq "scaled constant" (-1.) s.k;
  (* translate <1,2,3>: linear terms −2·<1,2,3>, constant 1 + 4 + 9 − 1 *)
  let t = Quadric.transform sphere (Transform.translate (v 1. 2. 3.)) in
  vec_eq "translated: linear" (v (-2.) (-4.) (-6.)) (v t.lx t.ly t.lz);
  float_eq "translated: constant" 13. t.k;
  vec_eq "translated: no mixed terms" Vec.zero (v t.xy t.xz t.yz);
  (* Cylinder_X turned 90° about z lies along y *)
  let r = Quadric.transform (q 0. 1. 1. (-1.)) (Transform.rotate (v 0. 0. 90.)) in
  vec_eq ~eps:1e-12 "turned" (v 1. 0. 1.) (v r.xx r.yy r.zz);
  vec_eq ~eps:1e-12 "turned: mixed" Vec.zero (v r.xy r.xz r.yz);
  (* a shear x' = x + y: the sphere becomes (x − y)² + y² + z² = 1, mixed term −2xy *)
  let m = match Transform.matrix [| 1.; 0.; 0.; 1.; 1.; 0.; 0.; 0.; 1.; 0.; 0.; 0. |] with Ok (m, _) -> m | Error e -> Alcotest.fail e in
  let h = Quadric.transform sphere m in
  vec_eq "sheared" (v 1. 2. 1.) (v h.xx h.yy h.zz);
  float_eq "sheared: xy" (-2.) h.xy;
  (* the surface moves with the transform: the point (0.6, 0.8, 0) goes to (0.6, 0.8, 0)·M *)
  float_eq "on the moved surface" 0. (value h (Transform.point m (v 0.6 0.8 0.)))

let box_of (x : Quadric.t) = [| x.box_llx; x.box_lly; x.box_llz; x.box_lenx; x.box_leny; x.box_lenz |]
let f32 = Precision.f32
let box_eq msg e a = Array.iteri (fun i x -> float_eq ~eps:0. (Printf.sprintf "%s %d" msg i) x a.(i)) e

let test_box () =
  (* the ellipsoid 4x² + 9y² + 4z² = 1: radii ½, ⅓, ½, in single precision *)
  let e = q 4. 9. 4. (-1.) in
  box_eq "ellipsoid" [| -0.5; f32 (-1. /. 3.); -0.5; 1.; f32 (2. /. 3.); 1. |] (Quadric.pov_box e);
  (* translated by its linear terms: (x − 1)² + y² + z² = 1 about <1,0,0> *)
  box_eq "translated ellipsoid" [| 0.; -1.; -1.; 2.; 2.; 2. |] (Quadric.pov_box (q ~linear:(v (-2.) 0. 0.) 1. 1. 1. 0.));
  (* moved: the box's corners are mapped (Recompute_BBox) *)
  box_eq "moved" [| 0.5; f32 (-1. /. 3.); -0.5; 1.; f32 (2. /. 3.); 1. |] (box_of (Quadric.transform e (Transform.translate (v 1. 0. 0.))));
  (* an infinite cylinder: longer than 1e6, so the huge box, which is infinite *)
  Alcotest.(check (array (float 0.))) "infinite cylinder" [||] (Quadric.pov_box cylinder_y);
  Alcotest.(check bool) "no bounds" true (Quadric.bounds cylinder_y = None);
  box_eq "its huge box" [| -1e10; -1e10; -1e10; f32 2e10; f32 2e10; f32 2e10 |] (box_of cylinder_y);
  (* within a clip box: the cylinder's x and z radii, the clip's y *)
  let clip = [| -2.; -3.; -2. |] and clip_hi = [| 2.; 3.; 2. |] in
  box_eq "cylinder within" [| -1.; -3.; -1.; 2.; 6.; 2. |] (Quadric.box_within cylinder_y clip clip_hi);
  (* y = x² + z² from y = 0 up: at y = 3 the radius is √(2·½·3/1) = √3, more than the clip's 1 *)
  let bowl = q ~linear:(v 0. (-1.) 0.) 1. 0. 1. 0. in
  box_eq "paraboloid within" [| -1.; 0.; -1.; 2.; 3.; 2. |] (Quadric.box_within bowl [| -1.; -3.; -1. |] [| 1.; 3.; 1. |]);
  let bowl_box = Quadric.box_within bowl [| -5.; -1.; -5. |] [| 5.; 3.; 5. |] in
  box_eq "paraboloid within a wide box" [| f32 (-.sqrt 3.); 0.; f32 (-.sqrt 3.); f32 (2. *. sqrt 3.); 3.; f32 (2. *. sqrt 3.) |] bowl_box;
  (* x² − y² + z² = 1: at |y| = 1 the radius is √(1 + 1) *)
  let hyp = q 1. (-1.) 1. (-1.) in
  let r = f32 (-.sqrt 2.) in
  box_eq "hyperboloid within" [| r; -1.; r; f32 (2. *. sqrt 2.); 2.; f32 (2. *. sqrt 2.) |] (Quadric.box_within hyp [| -5.; -1.; -5. |] [| 5.; 1.; 5. |]);
  (* a mixed term: nothing but the clip box *)
  box_eq "mixed" [| -2.; -3.; -2.; 4.; 6.; 4. |] (Quadric.box_within (q ~mixed:(v 1. 0. 0.) 1. 1. 1. (-1.)) clip clip_hi);
  (* in a CSG intersection the quadric is bounded within the other members' box *)
  let c = compile (v37 ^ "intersection { quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 } box { -2, 2 } }") in
  box_eq "CSG box" [| -1.; -2.; -1.; 2.; 4.; 2. |] c.objects.(0).pbox;
  (* clipped_by likewise *)
  let c = compile (v37 ^ "quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 clipped_by { box { -2, 2 } } }") in
  box_eq "clipped box" [| -1.; -2.; -1.; 2.; 4.; 2. |] c.objects.(0).pbox

let test_parse () =
  (* the commas are optional; the shape is as written *)
  let o = the_object (scene "quadric { <1,2,3> <4,5,6> <7,8,9> 10 }") in
  match o.shape with
  | Quadric x ->
      vec_eq "square" (v 1. 2. 3.) (v x.xx x.yy x.zz);
      vec_eq "mixed" (v 4. 5. 6.) (v x.xy x.xz x.yz);
      vec_eq "linear" (v 7. 8. 9.) (v x.lx x.ly x.lz);
      float_eq "constant" 10. x.k
  | _ ->
      Alcotest.fail "expected a quadric"

let test_trace () =
  (* the nearest hit through the tracer, and its normal flipped toward the ray *)
  let c = compile (v37 ^ "quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 }") in
  let obj = c.objects.(0) in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  float_eq "nearest" 4. (Shape.depth ctx.Context.shapes obj.shape (v 0. 0. (-5.)) (v 0. 0. 1.) 0.);
  float_eq "nearest beyond 5" 6. (Shape.depth ctx.Context.shapes obj.shape (v 0. 0. (-5.)) (v 0. 0. 1.) 5.);
  vec_eq "normal" (v 0. 0. (-1.)) (Shape.normal ctx.Context.shapes obj (-1) (v 0. 0. (-1.)))

(* the intersection allocates nothing: the roots stay unboxed and go into the array *)
let test_no_allocation () =
  let stats = Stats.create () and out = Array.make 2 0. and o = v 0.3 0.2 (-5.) and d = v 0. 0. 1. in
  let before = Gc.minor_words () in
  for _ = 1 to 10_000 do
    ignore (Quadric.intersect stats Limits.pov sphere o d out)
  done;
  let words = Gc.minor_words () -. before in
  if words > 100. then Alcotest.failf "10,000 intersections allocated %.0f words" words

let tests =
  [
    Alcotest.test_case "roots" `Quick test_roots;
    Alcotest.test_case "roots against the sampled surface" `Quick test_sampled;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "normal" `Quick test_normal;
    Alcotest.test_case "transform" `Quick test_transform;
    Alcotest.test_case "POV-Ray's box" `Quick test_box;
    Alcotest.test_case "parse" `Quick test_parse;
    Alcotest.test_case "through the tracer" `Quick test_trace;
    Alcotest.test_case "no allocation" `Quick test_no_allocation;
  ]
