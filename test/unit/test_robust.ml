(* The robust mode (Limits.robust, lifted secondary-ray origins) and moving a whole scene
   (Place.scene): analytic cases whose answer does not depend on the scene's size. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"

let trace_robust ?(robust = true) (c : Compiled.t) origin dir =
  let ctx = Trace.make_ctx ~robust c (Stats.create ()) in
  Trace.trace ctx ~level:0 ~weight:1. ~interiors:c.start_interiors ~continued:false origin (Vec.normalize dir)

(* A floor lit from straight above, with a ball of radius [s] resting on it: the floor point
   under the ball is in its shadow at every size. POV-Ray's shadow rays ignore hits within 1e-3,
   so below that size the ball casts no shadow there. *)
let ball_on_floor s =
  Printf.sprintf
    "%sbackground { rgb 0 }\n\
     light_source { <0, %g, 0>, rgb 1 }\n\
     plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
     sphere { <0, %g, 0>, %g pigment { rgb 1 } finish { ambient 0 diffuse 1 } }"
    v37 (100. *. s) s s

let test_shadow_at_every_size () =
  List.iter
    (fun s ->
      let c = compile (ball_on_floor s) in
      (* a camera ray from the side (clear of the ball) onto the floor point 0.3·s from the
         contact point *)
      let target = v (0.3 *. s) 0. 0. in
      let origin = v (2. *. s) (0.5 *. s) 0. in
      let dir = Vec.sub target origin in
      let robust = trace_robust c origin dir and pov = trace_robust ~robust:false c origin dir in
      result_eq (Printf.sprintf "robust mode, radius %g: in the shadow" s) (0., 0., 0.) robust;
      let lit = 100. /. sqrt (10000. +. 0.09) (* the cosine at the floor point *) in
      (* the ray from the floor point enters the ball 0.0477·s above it and leaves it 1.954·s above
         it: POV-Ray's shadow ray sees the ball when that exit is beyond 1e-3 *)
      let expected_pov = if 1.954 *. s > 1e-3 then 0. else lit in
      float_eq ~eps:1e-6 (Printf.sprintf "POV-Ray's mode, radius %g" s) expected_pov pov.r)
    [ 1e-4; 1e-2; 1.; 1e3 ]

(* A ray that starts on a surface does not hit it again at a rounding-error depth, however far the
   surface is from the origin: a glancing reflection off a floor 1e5 away sees the sky. *)
let test_no_self_hit_far_away () =
  List.iter
    (fun off ->
      let text =
        Printf.sprintf
          "%sbackground { rgb <0.2, 0.4, 0.6> }\n\
           plane { y, %g pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }" v37 off
      in
      let c = compile text in
      let r = trace_robust c (v 0. (off +. 1.) 0.) (v 1000. (-1.) 0.37) in
      result_eq (Printf.sprintf "floor at %g" off) (0.2, 0.4, 0.6) r)
    [ 0.; 1e5; -1e5; 1e7 ]

(* Depth limits: POV-Ray's reject roots at 1e-6 and beyond 1e7, the robust ones do not. *)
let test_limits () =
  let tri = Option.get (Triangle.flat (v (-1.) (-1.) 2.) (v 1. (-1.) 2.) (v 0. 1. 2.)) in
  let plus_z = v 0. 0. 1. in
  let at z = Triangle.intersect_within Limits.robust tri (v 0. 0. z) plus_z in
  float_eq ~eps:1e-12 "robust: depth 5e-7 kept" 5e-7 (at (2. -. 5e-7));
  float_eq ~eps:1e-3 "robust: depth 2e7 kept" 2e7 (at (2. -. 2e7));
  Alcotest.(check (float 0.)) "robust: behind" infinity (at 3.);
  Alcotest.(check (float 0.)) "POV-Ray: depth 5e-7 rejected" infinity (Triangle.intersect tri (v 0. 0. (2. -. 5e-7)) plus_z)

(* Place.scene: objects, lights and camera scaled then moved; fade distances scaled. *)
let test_place_scene () =
  let s =
    scene
      (v37
     ^ "camera { location <0, 1, -5> look_at <0, 1, 0> }\n\
        light_source { <2, 4, -3>, rgb 1 fade_distance 3 fade_power 2 }\n\
        sphere { <1, 2, 3>, 0.5 pigment { rgb 1 } interior { fade_distance 2 fade_power 1 } }\n\
        plane { y, -1 pigment { rgb 1 } }")
  in
  let m = Place.scene ~scale:1e-3 ~translate:(v 10. 0. 0.) s in
  let ball = List.hd m.objects in
  let c, r = sphere_of ball in
  vec_eq "sphere centre" (v 10.001 0.002 0.003) c;
  float_eq "sphere radius" 5e-4 r;
  float_eq "interior fade distance" 2e-3 ball.interior.fade_distance;
  let n, off = plane_of (List.nth m.objects 1) in
  vec_eq "plane normal" (v 0. 1. 0.) n;
  float_eq "plane offset" (-1e-3) off;
  let l = List.hd m.lights in
  vec_eq "light" (v 10.002 0.004 (-0.003)) l.position;
  float_eq "light fade distance" 3e-3 l.fade_distance;
  vec_eq "camera location" (v 10. 0.001 (-0.005)) m.camera.location;
  vec_eq "camera direction" (Vec.scale 1e-3 s.camera.direction) m.camera.direction

let tests =
  [
    Alcotest.test_case "shadows at every size" `Quick test_shadow_at_every_size;
    Alcotest.test_case "no self-hit far from the origin" `Quick test_no_self_hit_far_away;
    Alcotest.test_case "depth limits" `Quick test_limits;
    Alcotest.test_case "Place.scene" `Quick test_place_scene;
  ]
