(* Lights, the orthographic camera and object flags (docs/povray-rules.md §3.4, §16.6, §18.2–§18.4): parsing,
   the spotlight and cylinder attenuation, the parallel light's depth, orthographic ray origins and
   interior lists, the groups image and reflection rays search, and traced values computed by hand. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
let deg x = x *. Float.pi /. 180.

let the_light text = match (scene (v37 ^ text)).lights with [ l ] -> l | l -> Alcotest.failf "expected one light, got %d" (List.length l)

(* The first compiled light of [text]. *)
let compiled_light text = (compile (v37 ^ text)).lights.(0)

(* The attenuation of [lt] at [p] for a light at its centre (not parallel): the ray towards it. *)
let at (lt : Light.t) (p : Vec.t) =
  let dv = Vec.sub (v lt.lx lt.ly lt.lz) p in
  let dist = Vec.length dv in
  Light.attenuation lt p (Vec.scale (1. /. dist) dv) dist

(* A point at distance 2 from the origin, [a] degrees off the +z axis. *)
let off_axis a = v (2. *. sin (deg a)) 0. (2. *. cos (deg a))

(* ---- parsing (§18.2) ---- *)

let test_parse_spotlight () =
  let l = the_light "light_source { <0,5,0>, rgb 1 spotlight }" in
  Alcotest.(check bool) "a spotlight" true (l.kind = Scene.Spotlight);
  float_eq "default radius 30 as a cosine" (cos (deg 30.)) l.radius;
  float_eq "default falloff 45 as a cosine" (cos (deg 45.)) l.falloff;
  float_eq "default tightness" 0. l.tightness;
  vec_eq "default point_at" (v 0. 0. 1.) l.point_at;
  let l = the_light "light_source { <0,5,0>, rgb 1 spotlight radius 60 falloff 90 tightness 3 point_at <1,2,3> }" in
  float_eq "radius 60 is stored as 0.5" 0.5 l.radius;
  float_eq ~eps:1e-15 "falloff 90 is stored as cos 90" (cos (deg 90.)) l.falloff;
  float_eq "tightness" 3. l.tightness;
  vec_eq "point_at" (v 1. 2. 3.) l.point_at;
  (* the keyword resets the values where it stands *)
  let l = the_light "light_source { <0,5,0>, rgb 1 spotlight radius 10 falloff 20 tightness 3 spotlight }" in
  float_eq "radius reset" (cos (deg 30.)) l.radius;
  float_eq "falloff reset" (cos (deg 45.)) l.falloff;
  float_eq "tightness reset" 0. l.tightness;
  let l = the_light "light_source { <0,5,0>, rgb 1 cylinder }" in
  Alcotest.(check bool) "a cylinder light is parallel" true (l.kind = Scene.Cylinder_light && l.parallel);
  float_eq "cylinder radius" 0.75 l.radius;
  float_eq "cylinder falloff" 1. l.falloff;
  let l = the_light "light_source { <0,5,0>, rgb 1 parallel point_at <1,0,0> }" in
  Alcotest.(check bool) "a parallel point light" true (l.kind = Scene.Point_light && l.parallel);
  vec_eq "parallel point_at" (v 1. 0. 0.) l.point_at

let test_parse_errors () =
  expect_scene_error "radius before spotlight" "light_source { 0, 1 radius 10 spotlight }" ~line:1 ~col:21 ~sub:"'radius' needs a spotlight";
  expect_scene_error "falloff on a point light" "light_source { 0, 1\n falloff 10 }" ~line:2 ~col:2 ~sub:"'falloff' needs a spotlight";
  expect_scene_error "tightness on a parallel light" "light_source { 0, 1 parallel tightness 1 }" ~line:1 ~col:30 ~sub:"'tightness'";
  expect_scene_error "point_at on a point light" "light_source { 0, 1 point_at x }" ~line:1 ~col:21 ~sub:"'point_at' needs a spotlight, cylinder or parallel"

let test_light_transforms () =
  (* §14.8: translate and rotate move centre and point_at as points *)
  let l = the_light "light_source { <0,5,0>, rgb 1 spotlight point_at <0,0,1> translate <1,2,3> }" in
  vec_eq "centre" (v 1. 7. 3.) l.position;
  vec_eq "point_at" (v 1. 2. 4.) l.point_at;
  let l = the_light "light_source { <1,0,0>, rgb 1 spotlight point_at <2,0,0> rotate <0,0,90> }" in
  vec_eq ~eps:1e-12 "rotated centre" (v 0. 1. 0.) l.position;
  vec_eq ~eps:1e-12 "rotated point_at" (v 0. 2. 0.) l.point_at;
  (* inside a union, the union's transforms move the light *)
  let s = scene (v37 ^ "union { light_source { <0,5,0>, rgb 1 spotlight point_at 0 } sphere { 0, 1 } translate x*2 }") in
  let l = List.hd s.lights in
  vec_eq "union moves centre" (v 2. 5. 0.) l.position;
  vec_eq "union moves point_at" (v 2. 0. 0.) l.point_at;
  (* the compiled direction is normalize(point_at − centre) *)
  let lt = compiled_light "light_source { <0,5,0>, rgb 1 spotlight point_at <0,1,0> scale 2 }" in
  vec_eq "compiled direction" (v 0. (-1.) 0.) (v lt.dx lt.dy lt.dz)

(* ---- attenuation (§3.4, §18.2) ---- *)

let test_cubic_spline () =
  float_eq "below lo" 0. (Light.cubic_spline 0.2 0.6 0.1);
  float_eq "at lo" 0. (Light.cubic_spline 0.2 0.6 0.2);
  float_eq "middle" 0.5 (Light.cubic_spline 0.2 0.6 0.4);
  (* s = 0.25: (3 − 0.5)·0.0625 *)
  float_eq "a quarter" 0.15625 (Light.cubic_spline 0.2 0.6 0.3);
  float_eq "at hi" 1. (Light.cubic_spline 0.2 0.6 0.6);
  float_eq "beyond hi" 1. (Light.cubic_spline 0.2 0.6 0.9)

let test_spot_attenuation () =
  let spot = compiled_light "light_source { 0, rgb 1 spotlight point_at z }" in
  float_eq "on the axis" 1. (at spot (off_axis 0.));
  float_eq "inside the radius" 1. (at spot (off_axis 20.));
  float_eq "just inside the radius" 1. (at spot (off_axis 29.9));
  (* cos 40 between cos 45 and cos 30: s = 0.370862…, (3 − 2s)s² *)
  float_eq ~eps:1e-12 "in the soft edge" 0.31060707541748794 (at spot (off_axis 40.));
  float_eq "beyond the falloff" 0. (at spot (off_axis 50.));
  float_eq "grazing: 90 degrees off" 0. (at spot (off_axis 90.));
  float_eq "behind the light" 0. (at spot (off_axis 100.));
  let tight = compiled_light "light_source { 0, rgb 1 spotlight radius 30 falloff 45 tightness 5 point_at z }" in
  float_eq ~eps:1e-12 "tightness 5: cos^5" 0.7327048768870098 (at tight (off_axis 20.));
  float_eq "tightness on the axis" 1. (at tight (off_axis 0.));
  (* radius > falloff: a hard edge at the radius *)
  let hard = compiled_light "light_source { 0, rgb 1 spotlight radius 25 falloff 15 point_at z }" in
  float_eq "hard edge: inside" 1. (at hard (off_axis 24.9));
  float_eq "hard edge: outside" 0. (at hard (off_axis 25.1));
  float_eq "hard edge: between falloff and radius is lit" 1. (at hard (off_axis 20.));
  (* fade multiplies: 2/(1 + (4/2)²) = 0.4 at distance 4 *)
  let faded = compiled_light "light_source { 0, rgb 1 spotlight point_at z fade_distance 2 fade_power 2 }" in
  float_eq ~eps:1e-12 "spot and fade" (0.31060707541748794 *. 0.4) (at faded (Vec.scale 2. (off_axis 40.)));
  float_eq "fade at the fade distance" 1. (at faded (off_axis 0.))

let test_cylinder_attenuation () =
  let cyl = compiled_light "light_source { <0,5,0>, rgb 1 cylinder point_at 0 }" in
  float_eq "on the axis" 1. (at cyl (v 0. 0. 0.));
  float_eq "inside the radius" 1. (at cyl (v 0.5 0. 0.));
  (* ρ = 0.875: 1 − ρ = 0.125, the spline from 0 to 1 − 0.75 at its middle *)
  float_eq "in the soft edge" 0.5 (at cyl (v 0.875 0. 0.));
  float_eq "at the falloff" 0. (at cyl (v 0. 0. 1.));
  float_eq "behind the centre" 0. (at cyl (v 0. 6. 0.));
  let tight = compiled_light "light_source { <0,5,0>, rgb 1 cylinder tightness 2 point_at 0 }" in
  float_eq "tightness 2: (1 − ρ)²" 0.25 (at tight (v 0.5 0. 0.))

(* ---- parallel lights (§18.3) ---- *)

let test_parallel_depth () =
  let par = compiled_light "light_source { <0,5,0>, rgb 1 parallel point_at 0 }" in
  let depth (p : Vec.t) =
    let dv = Vec.sub (v par.lx par.ly par.lz) p in
    let dist = Vec.length dv in
    Light.parallel_depth par (Vec.scale (1. /. dist) dv) dist
  in
  float_eq ~eps:1e-12 "below the light's plane" 5. (depth (v 3. 0. 4.));
  float_eq ~eps:1e-12 "straight below" 2. (depth (v 0. 3. 0.));
  float_eq ~eps:1e-12 "behind the plane: negative" (-2.) (depth (v 3. 7. 4.));
  float_eq ~eps:1e-12 "on the plane" 0. (depth (v 3. 5. 4.));
  (* a parallel spotlight's ray is its axis: cosθ = 1 in front, −1 behind *)
  let spot = compiled_light "light_source { <0,5,0>, rgb 1 spotlight radius 5 falloff 8 tightness 5 parallel point_at 0 }" in
  let up = v 0. 1. 0. in
  float_eq "parallel spotlight in front" 1. (Light.attenuation spot (v 3. 0. 4.) up 5.);
  float_eq "parallel spotlight behind" 0. (Light.attenuation spot (v 3. 7. 4.) up (-2.))

(* ---- the samples a light gives a point (Light.sample) ---- *)

let test_samples () =
  let pt = compiled_light "light_source { <0,3,4>, rgb <1,0.5,0.25> }" in
  Alcotest.(check int) "a point light gives one sample" 1 (Light.samples pt);
  let sample light p =
    let s = Light.room () in
    Light.sample light p 0 s;
    s
  in
  let s = sample pt (v 0. 0. 0.) in
  vec_eq ~eps:1e-15 "towards the light" (v 0. 0.6 0.8) (Light.direction s);
  float_eq "as far as the light" 5. s.dist;
  rgb_eq "its colour" (Rgb.make 1. 0.5 0.25) (Light.colour pt s);
  (* §18.3: a parallel light's sample runs along −dir, as far as the plane through the centre *)
  let par = compiled_light "light_source { <0,5,0>, rgb 1 parallel point_at 0 }" in
  let s = sample par (v 3. 0. 4.) in
  vec_eq "along −dir" (v 0. 1. 0.) (Light.direction s);
  float_eq ~eps:1e-12 "as far as the plane" 5. s.dist;
  (* a spotlight's colour is its colour times the attenuation, in single precision; 15° off the
     axis lies between the radius (10°) and the falloff (20°) *)
  let spot = compiled_light "light_source { <0,5,0>, rgb 1 spotlight radius 10 falloff 20 tightness 0 point_at 0 }" in
  let p = v (5. *. tan (deg 15.)) 0. 0. in
  let s = sample spot p in
  let a = Light.attenuation spot p (Light.direction s) s.dist in
  Alcotest.(check bool) "in the soft edge" true (a > 0. && a < 1.);
  float_eq ~eps:0. "the sample's attenuation" a s.atten;
  float_eq ~eps:0. "attenuated in single precision" (Precision.f32 a) (Light.colour spot s).r;
  rgb_eq "outside the cone: black" Rgb.black (Light.colour spot (sample spot (v (5. *. tan (deg 30.)) 0. 0.)))

let diffuse_floor = "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"

let test_parallel_trace () =
  (* L = (−1,1,0)/√2 everywhere: N·L = 1/√2 *)
  let light = "light_source { <0,5,0>, rgb 1 parallel point_at <1,4,0> }\n" in
  let s = 1. /. sqrt 2. in
  result_eq "lit at any point" (s, s, s) (trace_text (v37 ^ light ^ diffuse_floor) (v 3. 1. 0.) (v 0. (-1.) 0.));
  (* the origin is 5/√2 in front of the plane; a sphere 2√2 along L shadows it, one 3√2 along
     (behind the light's plane) does not *)
  let blocker c = Printf.sprintf "sphere { %s, 0.5 pigment { rgb 1 } }\n" c in
  result_eq "shadowed in front of the plane" (0., 0., 0.) (trace_text (v37 ^ light ^ diffuse_floor ^ blocker "<-2,2,0>") (v 0. 1. 0.) (v 0. (-1.) 0.));
  result_eq "not shadowed by an object behind the plane" (s, s, s)
    (trace_text (v37 ^ light ^ diffuse_floor ^ blocker "<-3,3,0>") (v 0. 1. 0.) (v 0. (-1.) 0.))

(* ---- double_illuminate (§16.6) ---- *)

let test_double_illuminate () =
  let floor flags = Printf.sprintf "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 phong 1 } %s }\n" flags in
  let below = "light_source { <1,-1,0>, rgb 1 }\n" in
  let look = trace_text ~interiors:[] in
  result_eq "light behind: dark" (0., 0., 0.) (look (v37 ^ below ^ floor "") (v 0. 1. 0.) (v 0. (-1.) 0.));
  let s = 1. /. sqrt 2. in
  (* |N·L| = 1/√2, and no phong from behind (R·L < 0) *)
  result_eq "double_illuminate: |N·L|" (s, s, s) (look (v37 ^ below ^ floor "double_illuminate") (v 0. 1. 0.) (v 0. (-1.) 0.));
  result_eq "double_illuminate off" (0., 0., 0.) (look (v37 ^ below ^ floor "double_illuminate off") (v 0. 1. 0.) (v 0. (-1.) 0.));
  (* on a union it reaches every member, nested unions too *)
  let s = scene (v37 ^ "union { sphere { 0, 1 } union { sphere { x, 1 } sphere { y, 1 } } double_illuminate }") in
  Alcotest.(check (list bool)) "union members" [ true; true; true ] (List.map (fun (o : Scene.obj) -> o.double_illuminate) s.objects)

(* ---- no_image, no_reflection (§16.6) ---- *)

let test_flag_groups () =
  let c = compile (v37 ^ "sphere { 0, 1 no_image } sphere { x*3, 1 } sphere { x*6, 1 no_reflection } plane { y, -2 no_image }") in
  let ids (g : Compiled.group) = List.sort compare (List.map (fun (o : Compiled.obj) -> o.id) (Array.to_list g.unbounded @ Array.to_list g.bounded)) in
  Alcotest.(check (list int)) "image rays" [ 1; 2 ] (ids c.seen);
  Alcotest.(check (list int)) "reflection rays" [ 0; 1; 3 ] (ids c.mirrored);
  Alcotest.(check (list int)) "all" [ 0; 1; 2; 3 ] (ids c.all);
  (* without flags every ray searches the one group *)
  let c = compile (v37 ^ "sphere { 0, 1 } sphere { x*3, 1 no_image off }") in
  Alcotest.(check bool) "no flags: one group" true (c.seen == c.all && c.mirrored == c.all);
  (* a union passes its flags to its members *)
  let s = scene (v37 ^ "union { sphere { 0, 1 } sphere { x, 1 no_reflection } no_image }") in
  Alcotest.(check (list (pair bool bool))) "union flags" [ (true, false); (true, true) ]
    (List.map (fun (o : Scene.obj) -> (o.no_image, o.no_reflection)) s.objects)

let test_flag_trace () =
  let bg = "background { rgb <0.1, 0.2, 0.3> }\n" in
  let mirror = "plane { z, 5 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }\n" in
  let red flags = Printf.sprintf "sphere { <0,0,-5>, 1 pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } %s }\n" flags in
  let look text d = trace_text ~interiors:[] (v37 ^ bg ^ mirror ^ text) Vec.zero d in
  let minus_z = v 0. 0. (-1.) and plus_z = v 0. 0. 1. in
  result_eq "plain: seen" (1., 0., 0.) (look (red "") minus_z);
  result_eq "plain: reflected" (1., 0., 0.) (look (red "") plus_z);
  result_eq "no_image: not seen" (0.1, 0.2, 0.3) (look (red "no_image") minus_z);
  result_eq "no_image: reflected" (1., 0., 0.) (look (red "no_image") plus_z);
  result_eq "no_reflection: seen" (1., 0., 0.) (look (red "no_reflection") minus_z);
  result_eq "no_reflection: not reflected" (0.1, 0.2, 0.3) (look (red "no_reflection") plus_z);
  (* seen through a transmit-1 pane (an image ray) the no_image sphere stays hidden *)
  let pane = "plane { z, -2 pigment { rgbt <1,1,1,1> } finish { ambient 0 diffuse 0 } }\n" in
  result_eq "no_image through glass" (0.1, 0.2, 0.3) (look (pane ^ red "no_image") minus_z);
  result_eq "no_reflection through glass" (1., 0., 0.) (look (pane ^ red "no_reflection") minus_z)

(* ---- the orthographic camera (§18.4) ---- *)

let camera text = (scene (v37 ^ text)).camera

let test_ortho_camera () =
  let c = camera "camera { orthographic location <0,0,-4> }" in
  Alcotest.(check bool) "orthographic" true (c.projection = Scene.Orthographic);
  (* k1 = |<0,0,1> − location| = 5, k2 = 1 *)
  vec_eq "default look_at: right" (v 6.65 0. 0.) c.right;
  vec_eq "default look_at: up" (v 0. 5. 0.) c.up;
  let c = camera "camera { orthographic location <0,0,-4> look_at 0 }" in
  vec_eq ~eps:1e-12 "look_at: right" (v 5.32 0. 0.) c.right;
  vec_eq ~eps:1e-12 "look_at: up" (v 0. 4. 0.) c.up;
  let c = camera "camera { orthographic location <0,0,-4> right x*8 up y*6 look_at 0 }" in
  vec_eq "right and up written: kept" (v 8. 0. 0.) c.right;
  vec_eq "up kept" (v 0. 6. 0.) c.up;
  let c = camera "camera { orthographic location <0,0,-4> right x*8 look_at 0 }" in
  vec_eq "right alone written: no scaling of up" (v 0. 1. 0.) c.up;
  (* angle 40: the view is 2·k1·tan 20° wide, right written or not *)
  let c = camera "camera { orthographic location <0,0,-4> look_at 0 angle 40 }" in
  vec_eq ~eps:1e-12 "angle: right" (v 2.9117618741296187 0. 0.) c.right;
  vec_eq ~eps:1e-12 "angle: up" (v 0. 2.1892946422027206 0.) c.up;
  vec_eq ~eps:1e-12 "angle: direction" (v 0. 0. 1.827072483937324) c.direction;
  let c = camera "camera { location <0,0,-4> look_at 0 }" in
  Alcotest.(check bool) "perspective" true (c.projection = Scene.Perspective);
  vec_eq "perspective right unscaled" (v 1.33 0. 0.) c.right

let test_ortho_origins () =
  let c = compile (v37 ^ "camera { orthographic location <0,0,-4> right x*8 up y*6 look_at 0 }") in
  let cam = Camera.make c ~robust:false ~width:4 ~height:2 and ctx = Trace.make_ctx c (Stats.create ()) in
  let origin x y = Camera.ray cam ctx x y (fun _ _ o _ -> o) in
  (* pixel (0,0) of 4×2: x0 = 0.5/4 − 0.5, y0 = 0.5 − 0.5/2 *)
  vec_eq "top left" (v (-3.) 1.5 (-4.)) (origin 0. 0.);
  vec_eq "bottom right" (v 3. (-1.5) (-4.)) (origin 3. 1.);
  vec_eq "the image centre is the location" (v 0. 0. (-4.)) (origin 1.5 0.5);
  vec_eq "every ray along the direction" (v 0. 0. 1.) (Camera.ray cam ctx 0. 0. (fun _ _ _ d -> d));
  (* each origin has its own interior list, last entered first *)
  let cs = compile (v37 ^ "sphere { <-2,0,0>, 1 } sphere { 0, 3 } sphere { <2,0,0>, 1 } plane { y, 10 }") in
  let at p = Interiors.at cs.objects (Array.make 512 0.) p in
  Alcotest.(check (list int)) "inside the left and big spheres, under the plane" [ 3; 1; 0 ] (at (v (-2.) 0. 0.));
  Alcotest.(check (list int)) "inside the right and big spheres" [ 3; 2; 1 ] (at (v 2.5 0. 0.));
  Alcotest.(check (list int)) "on a sphere's surface: outside it (strict)" [ 3 ] (at (v 3. 0. 0.));
  Alcotest.(check (list int)) "above the plane" [] (at (v 0. 11. 0.))

(* ---- looks_like (§19.2) ---- *)

let test_looks_like () =
  let s = scene (v37 ^ "light_source { <0,2,0>, rgb 1 looks_like { sphere { 0, 0.5 } translate x } translate z }") in
  let l = match s.lights with [ l ] -> l | _ -> Alcotest.fail "one light" in
  vec_eq "the light moved by its own translate" (v 0. 2. 1.) l.position;
  let o = the_object s in
  let c, r = sphere_of o in
  (* moved to the centre <0,2,0>, then by its own translate x, then by the light's translate z *)
  vec_eq "the object at the centre and moved" (v 1. 2. 1.) c;
  float_eq "radius" 0.5 r;
  Alcotest.(check bool) "no_shadow" true o.no_shadow;
  Alcotest.(check bool) "marked as a light's shape" true o.looks_like;
  (* a declared light with looks_like is an object: its copies move light and shape *)
  let s = scene (v37 ^ "#declare L = light_source { 0, rgb 1 looks_like { sphere { 0, 0.5 } } }
object { L translate y*3 }") in
  vec_eq "copy: light" (v 0. 3. 0.) (List.hd s.lights).position;
  vec_eq "copy: shape" (v 0. 3. 0.) (fst (sphere_of (the_object s)));
  (* a union's transforms and texture reach the shape *)
  let s = scene (v37 ^ "union { light_source { 0, rgb 1 looks_like { sphere { 0, 0.5 } } } sphere { x*5, 1 } pigment { rgb <0,1,0> } translate y }") in
  let o = List.hd s.objects in
  vec_eq "union moves the shape" (v 0. 1. 0.) (fst (sphere_of o));
  colour_eq "union pigment" (colour5 0. 1. 0. 0. 0.) (pigment_of o);
  (* the light and its shape count as one top-level object for POV-Ray's bounding threshold *)
  let c = compile (v37 ^ "light_source { 0, rgb 1 looks_like { sphere { 0, 0.5 } } } sphere { x*5, 1 }") in
  Alcotest.(check bool) "two top-level objects: no bounding" false c.bounding;
  (* POV-Ray's own threshold (no ini file) is 1: the tree even for one object; -MB never *)
  let two = v37 ^ "light_source { 0, rgb 1 } sphere { x*5, 1 }" in
  Alcotest.(check bool) "threshold 1: bounding" true (compile ~bounding_threshold:Compile.pov_bounding_threshold two).bounding;
  Alcotest.(check bool) "threshold 2: bounding" true (compile ~bounding_threshold:2 two).bounding;
  Alcotest.(check bool) "Bounding=off: none" false (compile ~bounding_threshold:max_int two).bounding;
  Alcotest.(check bool) "nothing to bound" false (compile ~bounding_threshold:1 v37).bounding;
  (* a camera inside the shape starts inside it (checked against POV-Ray: lights_looks_like_inside) *)
  let c = compile (v37 ^ "camera { location 0 } light_source { 0, rgb 1 looks_like { sphere { 0, 0.5 } } }") in
  Alcotest.(check (list int)) "camera inside the shape" [ 0 ] c.start_interiors;
  expect_scene_error "two looks_like" "light_source { 0, rgb 1 looks_like { sphere { 0, 1 } }\n  looks_like { sphere { 0, 1 } } }" ~line:2 ~col:3
    ~sub:"only one looks_like"

let tests =
  [
    Alcotest.test_case "spotlight, cylinder and parallel parsing" `Quick test_parse_spotlight;
    Alcotest.test_case "light keyword errors" `Quick test_parse_errors;
    Alcotest.test_case "light transforms" `Quick test_light_transforms;
    Alcotest.test_case "cubic spline" `Quick test_cubic_spline;
    Alcotest.test_case "spotlight attenuation" `Quick test_spot_attenuation;
    Alcotest.test_case "cylinder attenuation" `Quick test_cylinder_attenuation;
    Alcotest.test_case "parallel depth" `Quick test_parallel_depth;
    Alcotest.test_case "light samples" `Quick test_samples;
    Alcotest.test_case "parallel light traced" `Quick test_parallel_trace;
    Alcotest.test_case "double_illuminate" `Quick test_double_illuminate;
    Alcotest.test_case "no_image and no_reflection groups" `Quick test_flag_groups;
    Alcotest.test_case "no_image and no_reflection traced" `Quick test_flag_trace;
    Alcotest.test_case "orthographic camera vectors" `Quick test_ortho_camera;
    Alcotest.test_case "orthographic origins and interiors" `Quick test_ortho_origins;
    Alcotest.test_case "looks_like" `Quick test_looks_like;
  ]
