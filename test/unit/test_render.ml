(* Render: camera rays (§1.4, Camera) and the render loop. *)

open Helpers

(* the direction of the camera ray through (x, y) of a w×h image, for the camera of the scene [text] *)
let camera_dir text w h x y =
  let c = compile text in
  Camera.ray (Camera.make c ~robust:false ~width:w ~height:h) (Trace.make_ctx c (Stats.create ())) x y (fun _ _ _ d -> d)

let default_cam = ""

let test_centre_pixel () =
  (* 3×3: x0 = (1 + 0.5)/3 − 0.5 = 0, y0 = 0.5 − (1 + 0.5)/3 = 0: along direction *)
  vec_eq "3x3 centre" (v 0. 0. 1.) (camera_dir default_cam 3 3 1. 1.);
  (* 5×3 centre pixel (2,1) *)
  vec_eq "5x3 centre" (v 0. 0. 1.) (camera_dir default_cam 5 3 2. 1.);
  (* with look_at the centre ray is the unit direction: location <0,0,0>, look_at <1,1,1> *)
  let cam = "camera { direction <0,0,2> look_at <1,1,1> }" in
  let s3 = 1. /. sqrt 3. in
  vec_eq ~eps:1e-12 "look_at centre" (v s3 s3 s3) (camera_dir cam 7 5 3. 2.)

let test_pixel_formula () =
  (* 4×2, pixel (0,0): x0 = 0.5/4 − 0.5 = −0.375, y0 = 0.5 − 0.5/2 = 0.25;
     direction + x0·right + y0·up = <−0.375·1.33, 0.25, 1> = <−0.49875, 0.25, 1>, length 1.1450989 *)
  let l = sqrt ((0.49875 *. 0.49875) +. 0.0625 +. 1.) in
  vec_eq ~eps:1e-12 "4x2 top left" (v (-0.49875 /. l) (0.25 /. l) (1. /. l)) (camera_dir default_cam 4 2 0. 0.);
  vec_eq ~eps:1e-7 "4x2 top left, rounded" (v (-0.4355519) 0.2183217 0.8732870) (camera_dir default_cam 4 2 0. 0.);
  (* pixel (3,1): x0 = 3.5/4 − 0.5 = 0.375, y0 = 0.5 − 1.5/2 = −0.25 *)
  vec_eq ~eps:1e-12 "4x2 bottom right" (v (0.49875 /. l) (-0.25 /. l) (1. /. l)) (camera_dir default_cam 4 2 3. 1.);
  (* fractional position (−0.5, −0.5) is the top-left corner of the image: x0 = −0.5, y0 = 0.5 *)
  let c = v (-0.665) 0.5 1. in
  vec_eq ~eps:1e-12 "image corner" (Vec.normalize c) (camera_dir default_cam 10 10 (-0.5) (-0.5));
  (* the result is unit length *)
  float_eq ~eps:1e-12 "unit" 1. (Vec.length (camera_dir default_cam 7 3 0.3 2.9));
  (* +y is up: the top row looks up, the bottom row down *)
  Alcotest.(check bool) "top row looks up" true ((camera_dir default_cam 3 3 1. 0.).y > 0.);
  Alcotest.(check bool) "bottom row looks down" true ((camera_dir default_cam 3 3 1. 2.).y < 0.)

let opts = render_opts

(* A 3×3 image: the centre ray hits a sphere of ambient 1 (colour 1), the corners see the background. *)
let sphere_scene = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { rgb <0.1,0.2,0.3> }\nsphere { <0,0,5>, 1 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }"

let pixel img x y =
  let r, g, b = Image.get img x y in
  (r, g, b)

let check_pixel msg (er, eg, eb) img x y =
  let r, g, b = pixel img x y in
  float_eq ~eps:1e-6 (msg ^ " r") er r;
  float_eq ~eps:1e-6 (msg ^ " g") eg g;
  float_eq ~eps:1e-6 (msg ^ " b") eb b

let test_full_area () =
  let a = Render.full_area 4 3 in
  Alcotest.(check (list int)) "left right top bottom" [ 0; 3; 0; 2 ] [ a.left; a.right; a.top; a.bottom ]

let test_render () =
  let c = compile sphere_scene in
  let img, stats = Render.render (opts 3 3) c (Scene.Working 1.) in
  Alcotest.(check int) "width" 3 img.width;
  check_pixel "centre hits the sphere" (1., 1., 1.) img 1 1;
  (* corner (0,0): x0 = −1/3 → −0.443, y0 = 1/3; at z = 5 the ray is 2.8 off the axis: background *)
  check_pixel "corner sees the background" (0.1, 0.2, 0.3) img 0 0;
  check_pixel "corner (2,2)" (0.1, 0.2, 0.3) img 2 2;
  Alcotest.(check int) "one camera ray per pixel" 9 stats.camera_rays;
  Alcotest.(check int) "no AA samples" 0 stats.samples;
  (* a partial render leaves the rest black *)
  let o = { (opts 3 3) with area = { left = 1; right = 2; top = 1; bottom = 1 } } in
  let img, stats = Render.render o c (Scene.Working 1.) in
  check_pixel "rendered" (1., 1., 1.) img 1 1;
  check_pixel "rendered (2,1)" (0.1, 0.2, 0.3) img 2 1;
  check_pixel "not rendered" (0., 0., 0.) img 0 0;
  Alcotest.(check int) "two camera rays" 2 stats.camera_rays

let test_blocks_and_workers () =
  (* the image does not depend on the block size or the number of workers *)
  let c = compile sphere_scene in
  let a, _ = Render.render (opts 7 5) c (Scene.Working 1.) in
  let b, sb = Render.render { (opts 7 5) with block_size = 2; workers = 2 } c (Scene.Working 1.) in
  Alcotest.(check bool) "same image" true (a.data = b.data);
  Alcotest.(check int) "stats merged over blocks" 35 sb.camera_rays

let test_antialias () =
  (* a uniform image is never supersampled *)
  let bg = compile "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { rgb 0.5 }" in
  let img, stats = Render.render { (opts 4 4) with antialias = Some 0.3 } bg (Scene.Working 1.) in
  Alcotest.(check int) "no samples" 0 stats.samples;
  check_pixel "uniform" (0.5, 0.5, 0.5) img 2 2;
  (* an edge is: each supersampled pixel takes aa_depth² = 9 more samples *)
  let _, stats = Render.render { (opts 3 3) with antialias = Some 0.3 } (compile sphere_scene) (Scene.Working 1.) in
  Alcotest.(check bool) "samples taken" true (stats.samples > 0);
  Alcotest.(check int) "samples are multiples of 9" 0 (stats.samples mod 9)

let test_adaptive () =
  let a2 o = { o with Render.antialias = Some 0.3; aa_method = Render.Adaptive } in
  (* a uniform image: only the (w+1)×(h+1) pixel corners of each block are traced, never a sub-sample *)
  let bg = compile "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { rgb 0.5 }" in
  let img, stats = Render.render (a2 (opts 4 3)) bg (Scene.Working 1.) in
  Alcotest.(check int) "no samples" 0 stats.samples;
  Alcotest.(check int) "one ray per corner" 20 stats.camera_rays;
  check_pixel "uniform" (0.5, 0.5, 0.5) img 3 2;
  (* blocks of 2×2, 2×2, 2×1 and 2×1 pixels each trace their own corners: 9 + 9 + 6 + 6 *)
  let _, stats = Render.render { (a2 (opts 4 3)) with block_size = 2 } bg (Scene.Working 1.) in
  Alcotest.(check int) "corners per block" 30 stats.camera_rays;
  (* depth 1: no subdivision, each pixel is the mean of its four corners *)
  let sph = compile sphere_scene in
  let _, stats = Render.render { (a2 (opts 3 3)) with aa_depth = 1 } sph (Scene.Working 1.) in
  Alcotest.(check int) "depth 1: no samples" 0 stats.samples;
  Alcotest.(check int) "depth 1: corners only" 16 stats.camera_rays;
  (* an edge is subdivided (at depth 2 once, so at most 5 sub-samples per pixel); every camera ray
     is a corner or a sub-sample *)
  List.iter
    (fun depth ->
      let _, stats = Render.render { (a2 (opts 9 9)) with aa_depth = depth } sph (Scene.Working 1.) in
      Alcotest.(check bool) (Printf.sprintf "depth %d: samples taken" depth) true (stats.samples > 0);
      Alcotest.(check int) (Printf.sprintf "depth %d: rays = corners + samples" depth) (100 + stats.samples) stats.camera_rays;
      if depth = 2 then Alcotest.(check bool) "depth 2: at most 5 per pixel" true (stats.samples <= 81 * 5))
    [ 2; 3; 4 ];
  (* unlike method 1, the image does not depend on the block size *)
  let a, sa = Render.render { (a2 (opts 9 7)) with jitter = 1. } sph (Scene.Working 1.) in
  let b, sb = Render.render { (a2 (opts 9 7)) with jitter = 1.; block_size = 3; workers = 2 } sph (Scene.Working 1.) in
  Alcotest.(check bool) "subdivided" true (sa.samples > 0);
  Alcotest.(check int) "same samples" sa.samples sb.samples;
  Alcotest.(check bool) "same image for any block size" true (a.data = b.data)

(* Pool: results in task order whatever the worker count; a worker that raises is reported. *)
let test_pool () =
  let xs = List.init 97 Fun.id in
  let f x = (x, Array.make (x mod 7) (float_of_int x *. 0.5)) in
  List.iter
    (fun w -> Alcotest.(check bool) (Printf.sprintf "%d workers" w) true (Pool.map ~workers:w f xs = List.map f xs))
    [ 1; 2; 3; 8 ];
  Alcotest.(check (list int)) "no tasks" [] (Pool.map ~workers:2 Fun.id []);
  (match Pool.map ~workers:2 (fun x -> if x = 50 then failwith "boom" else x) xs with
  | _ -> Alcotest.fail "a failing task went unnoticed"
  | exception Pool.Worker_failed _ -> ());
  (* a worker killed half-way (its results may be cut short) is named by its signal, not by the
     unmarshalling of what it left *)
  match Pool.map ~workers:2 (fun x -> if x = 50 then Unix.kill (Unix.getpid ()) Sys.sigkill; x) xs with
  | _ -> Alcotest.fail "a killed worker went unnoticed"
  | exception Pool.Worker_failed m -> Alcotest.(check string) "message" "a render worker was killed (SIGKILL)" m

let tests =
  [
    Alcotest.test_case "worker pool" `Quick test_pool;
    Alcotest.test_case "centre pixel" `Quick test_centre_pixel;
    Alcotest.test_case "pixel formula" `Quick test_pixel_formula;
    Alcotest.test_case "full_area" `Quick test_full_area;
    Alcotest.test_case "render" `Quick test_render;
    Alcotest.test_case "blocks and workers" `Quick test_blocks_and_workers;
    Alcotest.test_case "antialias" `Quick test_antialias;
    Alcotest.test_case "antialias method 2" `Quick test_adaptive;
  ]
