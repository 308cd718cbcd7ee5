(* Perturbed normals (normal.cpp's Perturb_Normal): cases computed by hand. The finite-difference
   slope of a gradient: the four tetrahedron samples of x + δ·c.x weigh the corners c by
   −5·bump·(0.02/δ), and Σ c.x·c = (4/3, 0, 0) (Σ c = 0), so gradient x tilts a normal by
   −(0.4/3)·bump along x whatever δ is. The normal's warps, no_bump_scale, slope_map and
   normal_map, average, quilted and POV-Ray's cycloidal are checked the same way. *)

open Helpers

let up = v 0. 1. 0.
let hit = { Patterns.normal = up; dir = v 0. (-1.) 0.; uv = Vec.zero }

let normal ?(warps = []) ?(accuracy = 0.02) ?(no_bump_scale = false) ?(nmap = Scene.No_map) pattern amount : Scene.normal =
  {
    npattern = pattern;
    nfrequency = 1.;
    nphase = 0.;
    nwave = Ramp;
    nwarps = warps;
    nnoise_generator = 0;
    amount = Precision.f32 amount;
    accuracy = Precision.f32 accuracy;
    no_bump_scale;
    nmap;
    nuv_mapping = false;
  }

let grad_x = Scene.Gradient (v 1. 0. 0.)
let perturb nm p = Normals.perturb 2 nm p hit up

(* the normal <0,1,0> tilted by t along x, made unit *)
let tilted_x t = Vec.normalize (v t 1. 0.)
let tilt bump = -0.4 /. 3. *. Precision.f32 bump

let test_gradient_slope () =
  let p = v 0.3 0. 0.2 in
  vec_eq ~eps:1e-8 "gradient x, bump 0.5" (tilted_x (tilt 0.5)) (perturb (normal grad_x 0.5) p);
  vec_eq ~eps:1e-8 "gradient x, bump 1" (tilted_x (tilt 1.)) (perturb (normal grad_x 1.) p);
  (* the step cancels out of a linear pattern *)
  vec_eq ~eps:1e-7 "accuracy 0.1" (tilted_x (tilt 0.5)) (perturb (normal ~accuracy:0.1 grad_x 0.5) p);
  (* bump 0: the normal unchanged *)
  vec_eq ~eps:1e-15 "bump 0" up (perturb (normal grad_x 0.) p);
  (* a pattern along the normal does not bend it *)
  vec_eq ~eps:1e-8 "gradient y" up (perturb (normal (Gradient up) 1.) p);
  (* the result is unit length *)
  float_eq ~eps:1e-15 "unit" 1. (Vec.length (perturb (normal grad_x 3.) p));
  (* a value that wraps inside the tetrahedron (fmod 1.00001 near x = 1) is a cliff: the corners
     before and after it disagree by about 1, a far larger tilt *)
  let cliff = perturb (normal grad_x 0.5) (v 0.995 0. 0.) in
  Alcotest.(check bool) "a wrap is a cliff" true (cliff.x > 0.5)

let test_warps () =
  let p = v 0.3 0. 0.2 in
  let scaled k = [ Scene.Transform_warp (Transform.scale (v k k k)) ] in
  (* a uniformly scaled normal keeps its bump: the normal is made unit in the normal's space and
     back (Warp_Normal, UnWarp_Normal) *)
  vec_eq ~eps:1e-8 "scale 2" (tilted_x (tilt 0.5)) (perturb (normal ~warps:(scaled 2.) grad_x 0.5) p);
  (* with no_bump_scale the pattern's slope is halved with its size, the tilt too *)
  let r = Normals.perturb 2 (normal ~no_bump_scale:true ~warps:(scaled 2.) grad_x 0.5) p hit up in
  vec_eq ~eps:1e-8 "scale 2, no_bump_scale: not unit" (v (tilt 0.5 /. 2.) 1. 0.) r;
  vec_eq ~eps:1e-8 "scale 2, no_bump_scale: the layer normal" (tilted_x (tilt 0.5 /. 2.))
    (Normals.layer_normal (normal ~no_bump_scale:true grad_x 0.5) r);
  (* rotated by 90° about y, gradient x rises along −z in world space: the tilt goes to +z *)
  let rot = [ Scene.Transform_warp (Transform.rotate (v 0. 90. 0.)) ] in
  let t = -.tilt 0.5 in
  vec_eq ~eps:1e-8 "rotate y 90" (Vec.normalize (v 0. 1. t)) (perturb (normal ~warps:rot grad_x 0.5) p);
  (* a non-uniform scale: x stretched by 4 flattens the slope 4 times in world space, and the
     normal, taken through the inverse transpose, tilts by a quarter of the pattern-space tilt *)
  let stretch = [ Scene.Transform_warp (Transform.scale (v 4. 1. 1.)) ] in
  vec_eq ~eps:1e-8 "scale x 4" (tilted_x (tilt 0.5 /. 4.)) (perturb (normal ~warps:stretch grad_x 0.5) p)

let slope h s : Scene.slope_entry = { svalue = 0.; height = h; slope = s }

let test_slope_map () =
  let map = [| { (slope 0. 1.) with svalue = 0. }; { (slope 1. 0.) with svalue = 1. } |] in
  (* the Hermite cubic of heights 0, 1 and slopes 1, 0: −t³ + t² + t *)
  float_eq "t = 0.5" 0.625 (Normals.slope_value map 0.5);
  float_eq "t = 0.25" (-0.015625 +. 0.0625 +. 0.25) (Normals.slope_value map 0.25);
  float_eq "on the first entry" 0. (Normals.slope_value map 0.);
  float_eq "below the first entry" 0. (Normals.slope_value map (-0.5));
  float_eq "at and beyond the last" 1. (Normals.slope_value map 1.);
  float_eq "beyond the last" 1. (Normals.slope_value map 3.);
  (* a slope_map [0 <0,0>] [1 <1,0>] is f(t) = 3t² − 2t³: the normal gathers f at the corners of
     the exact regular tetrahedron (edges from the centre √(8/9)·x − y/3, …, y), each corner
     weighed by −5·bump·(0.02/δ). Its slope at 0.3 is 6·0.3·0.7 = 1.26 times the pattern's, and
     the curvature adds to x and y. *)
  let smooth = Scene.Slope_map [| { (slope 0. 0.) with svalue = 0. }; { (slope 1. 0.) with svalue = 1. } |] in
  let r = perturb (normal ~nmap:smooth grad_x 0.5) (v 0.3 0. 0.) in
  let f t = (3. *. t *. t) -. (2. *. t *. t *. t) in
  let a = sqrt 8. /. 3. and b = sqrt 2. /. 3. and c = sqrt (2. /. 3.) in
  let corners = [ v a (-1. /. 3.) 0.; v (-.b) (-1. /. 3.) c; v (-.b) (-1. /. 3.) (-.c); v 0. 1. 0. ] in
  let delta = Precision.f32 0.02 in
  let k = -5. *. 0.5 *. (0.02 /. delta) in
  let sum = List.fold_left (fun acc (cn : Vec.t) -> Vec.madd acc (k *. f (0.3 +. (delta *. cn.x))) cn) up corners in
  vec_eq ~eps:1e-8 "slope_map on gradient x" (Vec.normalize sum) r;
  Alcotest.(check bool) "steeper by about 1.26" true (Float.abs ((r.x /. r.y /. tilt 0.5) -. 1.26) < 0.02)

let test_normal_map () =
  let flat = normal grad_x 0. and bumpy = normal grad_x 1. in
  let map = Scene.Normal_map [| { nvalue = 0.; nnormal = flat }; { nvalue = 1.; nnormal = bumpy } |] in
  let nm = normal ~nmap:map grad_x 0.5 in
  (* at x = 0.25 the value 0.25 blends 3/4 of the flat entry's normal with 1/4 of the bumpy one's *)
  let b = tilted_x (tilt 1.) in
  let expected = Vec.normalize (Vec.add (Vec.scale 0.75 up) (Vec.scale 0.25 b)) in
  vec_eq ~eps:1e-8 "a quarter of the way" expected (perturb nm (v 0.25 0. 0.));
  (* the parent's own bump size is not used *)
  vec_eq ~eps:1e-8 "parent bump ignored" expected (perturb { nm with amount = 7. } (v 0.25 0. 0.));
  (* on an entry's value, that entry alone *)
  vec_eq ~eps:1e-15 "value 0" up (perturb nm (v 0. 0. 0.));
  (* the entries see the parent's warped point: a parent scaled by 2 halves the value *)
  let scaled = { nm with nwarps = [ Scene.Transform_warp (Transform.scale (v 2. 2. 2.)) ] } in
  vec_eq ~eps:1e-8 "parent scaled" expected (perturb scaled (v 0.5 0. 0.))

let test_average () =
  let flat = normal grad_x 0. and bumpy = normal grad_x 1. in
  let map = Scene.Normal_map [| { nvalue = 1.; nnormal = flat }; { nvalue = 3.; nnormal = bumpy } |] in
  (* each entry's normal as it is alone, then their mean weighted by the values *)
  let p = v 0.3 0. 0. in
  let b = perturb bumpy p in
  let expected = Vec.normalize (Vec.scale 0.25 (Vec.add up (Vec.scale 3. b))) in
  vec_eq ~eps:1e-15 "weights 1 and 3" expected (perturb (normal ~nmap:map Average 0.5) p)

let test_quilted () =
  float_eq "quilt_cubic 0" 0. (Normals.quilt_cubic 0. 1. 1.);
  float_eq "quilt_cubic 1" 1.154700538 (Normals.quilt_cubic 1. 1. 1.);
  float_eq "quilt_cubic 0.5" (0.875 *. 1.154700538) (Normals.quilt_cubic 0.5 1. 1.);
  float_eq "quilt_cubic 0.5, controls 0" (0.125 *. 1.154700538) (Normals.quilt_cubic 0.5 0. 0.);
  (* at <0.75, 0.5, 0.5> the offset from the cell's centre is <0.25, 0, 0> *)
  let k = 0.578125 *. 1.154700538 *. 0.25 in
  let nm = normal (Quilted { control0 = 1.; control1 = 1. }) 0.5 in
  vec_eq ~eps:1e-12 "quilted" (tilted_x (0.5 *. k)) (perturb nm (v 0.75 0.5 0.5));
  (* FLOOR of a negative integer is one below floor: at x = −1 the offset is 0.5, not −0.5 *)
  let k = (0.125 +. (3. *. 0.5 *. 0.25) +. (3. *. 0.25 *. 0.5)) *. 1.154700538 *. 0.5 in
  vec_eq ~eps:1e-12 "quilted at x = −1" (tilted_x (0.5 *. k)) (perturb nm (v (-1.) 0.5 0.5))

let test_cycloidal () =
  float_eq "0" 0. (Normals.cycloidal 0.);
  float_eq ~eps:1e-15 "0.25" 1. (Normals.cycloidal 0.25);
  float_eq ~eps:1e-15 "1.25" 1. (Normals.cycloidal 1.25);
  float_eq ~eps:1e-15 "−0.25" (-1.) (Normals.cycloidal (-0.25));
  float_eq ~eps:1e-15 "−0.75" 1. (Normals.cycloidal (-0.75))

let tests =
  [
    Alcotest.test_case "finite difference of gradient x" `Quick test_gradient_slope;
    Alcotest.test_case "warps: scale, rotate, no_bump_scale" `Quick test_warps;
    Alcotest.test_case "slope_map" `Quick test_slope_map;
    Alcotest.test_case "normal_map" `Quick test_normal_map;
    Alcotest.test_case "average" `Quick test_average;
    Alcotest.test_case "quilted" `Quick test_quilted;
    Alcotest.test_case "cycloidal" `Quick test_cycloidal;
  ]

(* facets with coords 1, size 1: the cube points nearest the point itself. POV-Ray's cache holds
   the points around the last cube and is reused for a later cube of the same hash. *)
let test_facets_cache () =
  let nm = normal (Facets { fsize = 1.; coords = 1.; fmetric = 2. }) 0.5 in
  let at p = Normals.perturb 2 nm p hit up in
  (* a cube other than <0,0,0>'s with the same hash *)
  let h0 = Noise.hash3d 0 0 0 in
  let rec find i = if Noise.hash3d i 0 0 = h0 then i else find (i + 1) in
  let i = find 1 in
  let a = v 0.5 0.5 0.5 and b = v (float_of_int i +. 0.5) 0.5 0.5 in
  let cache = Normals.facets_cache () in
  let cached p = Normals.perturb ~facets:cache 2 nm p hit up in
  vec_eq ~eps:0. "a fresh cache: the points around the point" (at a) (cached a);
  let stale = cached b in
  Alcotest.(check bool) "the same hash elsewhere reuses the points" false (Vec.sub stale (at b) = Vec.zero);
  vec_eq ~eps:0. "the cached points are the first cube's" (Normals.perturb 2 nm (v 0.5 0.5 0.5) hit up) (cached (v 0.5 0.5 0.5));
  Normals.reset_facets cache;
  vec_eq ~eps:0. "after a reset" (at b) (cached b);
  (* the normal without coords: the nearest cube point to 10·N, unit after the unwarp *)
  let plain = normal (Facets { fsize = 0.1; coords = 0.; fmetric = 2. }) 0.5 in
  float_eq ~eps:1e-15 "facets: unit" 1. (Vec.length (Normals.perturb 2 plain (v 0.3 0. 0.2) hit up));
  Alcotest.(check bool) "facets: the same normal within a facet" true
    (Normals.perturb 2 plain (v 0.3 0. 0.2) hit up = Normals.perturb 2 plain (v 5. 0. (-3.)) hit up)

let tests = tests @ [ Alcotest.test_case "facets and its cache" `Quick test_facets_cache ]
