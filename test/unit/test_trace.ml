(* Trace: one ray through tiny scenes, against shading values computed by hand (§3–§8). Colours are
   single precision in the tracer, so results are compared within 1e-6. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
let origin = v 0. 0. 0.
let plus_z = v 0. 0. 1.
let s3 = sqrt 3.

(* ---- diffuse and ambient (§3.2, §3.3) ---- *)

(* A unit sphere at <0,0,3> seen along +z from the origin, lit from the origin: the hit is at
   z = 2, N = (P − C)/r = <0,0,-1>, L = <0,0,-1>, N·L = 1. *)
let front_sphere ?(pigment = "rgb 1") ?(finish = "ambient 0 diffuse 1") ?(light = "color rgb 1") () =
  Printf.sprintf "%ssphere { <0,0,3>, 1 pigment { %s } finish { %s } }\nlight_source { <0,0,0> %s }\n" v37 pigment finish
    light

let test_diffuse_head_on () =
  (* C·lc·(N·L)·diffuse·att = 1·1·1·1·1 = 1 *)
  result_eq "white" (1., 1., 1.) (trace_text (front_sphere ()) origin plus_z);
  (* pigment <1,0.5,0.25>, light <1,1,0.5>, diffuse 0.8:
     r = 1·1·0.8 = 0.8; g = 0.5·1·0.8 = 0.4; b = 0.25·0.5·0.8 = 0.1 *)
  result_eq "coloured"
    (0.8, 0.4, 0.1)
    (trace_text (front_sphere ~pigment:"rgb <1,0.5,0.25>" ~finish:"ambient 0 diffuse 0.8" ~light:"color rgb <1,1,0.5>" ())
       origin plus_z);
  (* two lights add up: 1 + 1 = 2 (no clipping in the tracer, §8.1) *)
  result_eq "two lights" (2., 2., 2.)
    (trace_text (front_sphere () ^ "light_source { <0,0,-1> color rgb 1 }") origin plus_z);
  (* a light of colour 2 is twice as bright *)
  result_eq "bright light" (2., 2., 2.) (trace_text (front_sphere ~light:"color rgb 2" ()) origin plus_z)

let test_ambient () =
  (* no light: ambient·C = 0.2·<1,0.5,0.25> = <0.2,0.1,0.05> *)
  result_eq "ambient only"
    (0.2, 0.1, 0.05)
    (trace_text (v37 ^ "sphere { <0,0,3>, 1 pigment { rgb <1,0.5,0.25> } finish { ambient 0.2 diffuse 0 } }") origin plus_z);
  (* ambient_light <0.5,1,1> scales it: r = 0.2·0.5 = 0.1 *)
  result_eq "ambient_light"
    (0.1, 0.1, 0.05)
    (trace_text
       (v37
      ^ "global_settings { ambient_light rgb <0.5,1,1> }\n\
         sphere { <0,0,3>, 1 pigment { rgb <1,0.5,0.25> } finish { ambient 0.2 diffuse 0 } }")
       origin plus_z);
  (* ambient plus diffuse: 0.2 + 1 = 1.2 *)
  result_eq "ambient + diffuse" (1.2, 1.2, 1.2) (trace_text (front_sphere ~finish:"ambient 0.2 diffuse 1" ()) origin plus_z);
  (* emission: C·emission = <1,0.5,0>·0.5 *)
  result_eq "emission" (0.5, 0.25, 0.)
    (trace_text (v37 ^ "sphere { <0,0,3>, 1 pigment { rgb <1,0.5,0> } finish { ambient 0 emission 0.5 diffuse 0 } }") origin plus_z);
  (* default finish, black default pigment: everything is 0 *)
  result_eq "default texture is black" (0., 0., 0.) (trace_text (v37 ^ "sphere { <0,0,3>, 1 }\nlight_source { 0, 1 }") origin plus_z)

let test_light_without_colour () =
  (* §10.2: a light without a colour is black: only the ambient 0.2 is left *)
  result_eq "black light" (0.2, 0.2, 0.2)
    (trace_text (v37 ^ "sphere { <0,0,3>, 1 pigment { rgb 1 } finish { ambient 0.2 diffuse 1 } }\nlight_source { <0,0,0> }")
       origin plus_z)

(* The plane y = 0 seen straight down from <0,1,0>, hit at the origin: N = <0,1,0>. The light at
   <√3,1,0> is 2 away, L = <√3/2, 1/2, 0>, N·L = 1/2. *)
let floor_scene ?(pigment = "rgb 1") ?(light = "color rgb 1") finish =
  Printf.sprintf "%splane { y, 0 pigment { %s } finish { %s } }\nlight_source { <sqrt(3),1,0> %s }\n" v37 pigment finish light

let down_from_above c = trace_ray c (v 0. 1. 0.) (v 0. (-1.) 0.)

let test_diffuse_angle () =
  result_eq "N·L = 0.5" (0.5, 0.5, 0.5) (down_from_above (compile (floor_scene "ambient 0 diffuse 1")));
  (* brilliance 2: (N·L)² = 0.25 *)
  result_eq "brilliance 2" (0.25, 0.25, 0.25) (down_from_above (compile (floor_scene "ambient 0 diffuse 1 brilliance 2")));
  (* diffuse albedo 0.6 brilliance 2 is diffuse 0.9: 0.9·0.25 = 0.225 *)
  result_eq "diffuse albedo" (0.225, 0.225, 0.225)
    (down_from_above (compile (floor_scene "ambient 0 diffuse albedo 0.6 brilliance 2")));
  (* a light behind the surface (N·L < 0) adds nothing *)
  result_eq "light below" (0., 0., 0.)
    (trace_text (v37 ^ "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\nlight_source { <1,-1,0> 1 }")
       (v 0. 1. 0.) (v 0. (-1.) 0.))

let test_phong () =
  (* R = D − 2(D·N)N = <0,-1,0> + 2<0,1,0> = <0,1,0>; R·L = 1/2; phong 1, phong_size 2:
     1·(1/2)² = 0.25, not multiplied by the pigment colour *)
  result_eq "phong only" (0.25, 0.25, 0.25)
    (down_from_above (compile (floor_scene ~pigment:"rgb <1,0,0>" "ambient 0 diffuse 0 phong 1 phong_size 2")));
  (* with diffuse 1 on a red pigment: r = 0.5 + 0.25, g = b = 0.25 *)
  result_eq "phong + diffuse" (0.75, 0.25, 0.25)
    (down_from_above (compile (floor_scene ~pigment:"rgb <1,0,0>" "ambient 0 diffuse 1 phong 1 phong_size 2")));
  (* phong 0.5, default phong_size 40: 0.5·0.5^40 = 4.5e-13, i.e. nothing *)
  result_eq "phong_size 40" (0., 0., 0.)
    (down_from_above (compile (floor_scene "ambient 0 diffuse 0 phong 0.5")));
  (* metallic 1: the highlight takes the pigment colour: M(lc) = lc·(1 + (1 − F)(C − 1)) with
     x = acos(1/2)/(π/2) = 2/3, F = 0.014567225/(2/3 − 1.12)² − 0.011612903 = 0.0592700;
     red: 0.25·1; green and blue: 0.25·F = 0.0148175 *)
  result_eq "metallic phong" (0.25, 0.0148175, 0.0148175)
    (down_from_above (compile (floor_scene ~pigment:"rgb <1,0,0>" "ambient 0 diffuse 0 phong 1 phong_size 2 metallic")))

let test_specular () =
  (* H = (L − D)/2 = (<√3/2,1/2,0> + <0,1,0>)/2 = <√3/4, 3/4, 0>, |H| = √3/2,
     c = (H·N)/|H| = (3/4)/(√3/2) = √3/2; roughness 0.5 → exponent 2: c² = 3/4 *)
  result_eq "specular" (0.75, 0.75, 0.75)
    (down_from_above (compile (floor_scene ~pigment:"rgb <0,0,1>" "ambient 0 diffuse 0 specular 1 roughness 0.5")));
  (* specular 0.4, roughness 0.25 → exponent 4: 0.4·(3/4)² = 0.225 *)
  result_eq "specular 0.4 roughness 0.25" (0.225, 0.225, 0.225)
    (down_from_above (compile (floor_scene "ambient 0 diffuse 0 specular 0.4 roughness 0.25")))

let test_light_fade () =
  (* §3.4: 2/(1 + (d/fd)^fp) with d = 2: fd 1, fp 2: 2/(1 + 4) = 0.4 *)
  result_eq "fade 1 2" (0.4, 0.4, 0.4)
    (trace_text (front_sphere ~light:"color rgb 1 fade_distance 1 fade_power 2" ()) origin plus_z);
  (* fd 2: 2/(1 + 1) = 1 *)
  result_eq "fade at fade_distance" (1., 1., 1.)
    (trace_text (front_sphere ~light:"color rgb 1 fade_distance 2 fade_power 2" ()) origin plus_z);
  (* fd 4, fp 1: 2/(1 + 0.5) = 4/3, brighter than the light *)
  result_eq "closer than fade_distance" (4. /. 3., 4. /. 3., 4. /. 3.)
    (trace_text (front_sphere ~light:"color rgb 1 fade_distance 4 fade_power 1" ()) origin plus_z);
  (* no fade without fade_power *)
  result_eq "fade_distance alone" (1., 1., 1.)
    (trace_text (front_sphere ~light:"color rgb 1 fade_distance 1" ()) origin plus_z)

(* ---- shadows (§4) ---- *)

(* The floor y = 0 (ambient 0.2, diffuse 1, white) is hit at the origin by a ray from <2,2,0>; the light
   is straight above at <0,10,0>, so N·L = 1. Unshadowed: 0.2 + 1 = 1.2; in shadow: 0.2. *)
let shadow_scene extra =
  v37 ^ "plane { y, 0 pigment { rgb 1 } finish { ambient 0.2 diffuse 1 } }\nlight_source { <0,10,0> color rgb 1 }\n" ^ extra

let shadow_ray extra = trace_text (shadow_scene extra) (v 2. 2. 0.) (v (-1.) (-1.) 0.)

let test_shadows () =
  result_eq "unshadowed" (1.2, 1.2, 1.2) (shadow_ray "");
  (* an opaque sphere between the point and the light *)
  result_eq "opaque occluder" (0.2, 0.2, 0.2) (shadow_ray "sphere { <0,5,0>, 1 }");
  (* transmit 0.5, crossed twice: 0.5·0.5 = 0.25 of the light, 0.2 + 0.25 = 0.45 *)
  result_eq "transmit 0.5 sphere" (0.45, 0.45, 0.45) (shadow_ray "sphere { <0,5,0>, 1 pigment { rgbt <1,1,1,0.5> } }");
  (* filter 1 on <1,0.5,0>: filcol = rgb·f = <1,0.5,0>, twice: <1,0.25,0>; plus ambient 0.2 *)
  result_eq "filter sphere" (1.2, 0.45, 0.2) (shadow_ray "sphere { <0,5,0>, 1 pigment { rgbf <1,0.5,0,1> } }");
  (* two transparent spheres: 0.25·0.25 = 0.0625 *)
  result_eq "two transmit spheres" (0.2625, 0.2625, 0.2625)
    (shadow_ray "sphere { <0,3,0>, 1 pigment { rgbt <1,1,1,0.5> } } sphere { <0,7,0>, 1 pigment { rgbt <1,1,1,0.5> } }");
  (* the filtered walk also stops at an opaque object *)
  result_eq "opaque in a filtered scene" (0.2, 0.2, 0.2)
    (shadow_ray "sphere { <0,3,0>, 1 pigment { rgbt <1,1,1,0.5> } } sphere { <0,7,0>, 1 }");
  (* an occluder beyond the light casts no shadow *)
  result_eq "beyond the light" (1.2, 1.2, 1.2) (shadow_ray "sphere { <0,15,0>, 1 }");
  (* no_shadow objects do not block *)
  result_eq "no_shadow" (1.2, 1.2, 1.2) (shadow_ray "sphere { <0,5,0>, 1 no_shadow }");
  (* an occluder off the shadow ray does not block *)
  result_eq "beside the ray" (1.2, 1.2, 1.2) (shadow_ray "sphere { <3,5,0>, 1 }")

let test_shadow_fade () =
  (* §4: a transmit-1 sphere (filcol 1) with interior fade: the shadow ray enters at t = 4 (no fade, not
     yet inside), then crosses 2 units inside: factor 1/(1 + (2/1)²) = 0.2; 0.2 ambient + 0.2 *)
  result_eq "fade in shadow" (0.4, 0.4, 0.4)
    (shadow_ray "sphere { <0,5,0>, 1 pigment { rgbt <1,1,1,1> } interior { fade_distance 1 fade_power 2 } }");
  (* fade_power 0: no fade in shadows at all (unlike camera rays) *)
  result_eq "no fade in shadow without fade_power" (1.2, 1.2, 1.2)
    (shadow_ray "sphere { <0,5,0>, 1 pigment { rgbt <1,1,1,1> } interior { fade_distance 1 } }")

(* §4, TracePointLightShadowRay: the opaque object that last blocked a light is tested first, with
   hits from 1e-4 (not 1e-3) counting. A sheet 5e-4 above a platform does not shadow it (closer
   than the 1e-3 shadow tolerance) — unless the previous shadow test of that light, at the same
   kind of trace level (or, for a camera ray's hit with nothing cached for those, at the deeper
   levels), was blocked by the sheet. *)
let test_shadow_cache () =
  let c =
    compile
      (v37
     ^ "light_source { <0,10,0>, rgb 1 }\n\
        #declare White = texture { pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
        triangle { <-2,0.0005,-2>, <2,0.0005,-2>, <0,0.0005,3> }\n\
        triangle { <-0.2,0,-0.2>, <0.2,0,-0.2>, <0,0,0.3> texture { White } }\n\
        plane { y, -1 texture { White } }")
  in
  (* camera rays grazing in from z = −1: to the platform at (0,0,0), under the sheet, and to the
     floor at (0.5,−1,0), whose shadow ray crosses the sheet 1 unit up *)
  let platform = v 0. 0.0003 (-1.) and floor = v 0.5 (-0.9997) (-1.) in
  let dir = Vec.normalize (v 0. (-0.0003) 1.) in
  let shoot ?(level = 0) ctx o = Trace.trace ctx ~level ~weight:1. ~interiors:[] ~continued:false o dir in
  let lit msg (r : Trace.result) = Alcotest.(check bool) (msg ^ ": lit") true (r.r > 0.9) in
  let dark msg (r : Trace.result) = Alcotest.(check bool) (msg ^ ": in shadow") true (r.r = 0.) in
  let fresh () = Trace.make_ctx c (Stats.create ()) in
  lit "platform, empty cache" (shoot (fresh ()) platform);
  dark "floor, under the sheet" (shoot (fresh ()) floor);
  let ctx = fresh () in
  dark "floor first" (shoot ctx floor);
  dark "then the platform: the cached sheet is hit at 5e-4" (shoot ctx platform);
  (* the shadow rays of a camera ray's hit (trace level 1) have a slot of their own, and try the
     deeper levels' blocker when it is empty; levels 2 and beyond share one slot *)
  let ctx = fresh () in
  dark "floor, level 1" (shoot ctx floor);
  lit "platform shaded at level 2: level 1's sheet is not tried" (shoot ~level:1 ctx platform);
  dark "platform shaded at level 1: its own slot" (shoot ctx platform);
  let ctx = fresh () in
  dark "floor shaded at level 2" (shoot ~level:1 ctx floor);
  dark "platform shaded at level 3: the slot of level 2" (shoot ~level:2 ctx platform);
  dark "platform shaded at level 1, its own slot empty: the deeper levels' sheet" (shoot ctx platform)

(* §2.1, §13.22: of equal depths the object POV-Ray meets first wins. A = P1 P2 P3 and
   B = P1 P2 Q with Q − P2 = 2(P3 − P2) lie in the plane z = 2 + x with bit-identical normals and
   distances (the cross product exactly doubles), so every ray meets them at exactly the same
   depth. With fewer than 3 top-level objects (Bounding_Threshold) POV-Ray has no bounding
   hierarchy and tests them in scene order: the first declared wins. With 3 (here a black light
   source is the third) it tests them in the order the ray enters their boxes: B's box reaches
   further up in x and z, so a ray coming down from there meets B first, whatever the order. *)
let test_depth_ties () =
  let a = "triangle { <0,1,2>, <0,0,2>, <1,0,3> pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }\n" in
  let b = "triangle { <0,1,2>, <0,0,2>, <2,0,4> pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } }\n" in
  let light = "light_source { <0,10,0>, rgb 0 }\n" in
  let o = v 3. 0.3 6. and d = v (-2.7) 0. (-3.7) in
  let shoot text = trace_text ~interiors:[] (v37 ^ text) o d in
  result_eq "no hierarchy, A first: A" (1., 0., 0.) (shoot (a ^ b));
  result_eq "no hierarchy, B first: B" (0., 1., 0.) (shoot (b ^ a));
  result_eq "hierarchy, A first: B's box first" (0., 1., 0.) (shoot (light ^ a ^ b));
  result_eq "hierarchy, B first: B's box first" (0., 1., 0.) (shoot (light ^ b ^ a))

(* A ray inside a cylinder standing on a box (the cylinder's end on the box's top face, y = 0.5),
   going down. Its depths to the two faces differ by rounding only: the box's top at
   0.77866380786041611 (0x1.8ead05caadbabp-1), the cylinder's end one unit in the last place
   farther, 0.77866380786041622. POV-Ray's bounding tree (3 objects with the light) enters the
   cylinder's box first (the ray starts inside it), takes the end as the best hit, and then skips
   the box, whose single-precision entry, 0.7786638…, lies beyond that depth: the end is seen.
   Without the hierarchy (no light: 2 objects) the strictly nearer box face is seen. *)
let test_overtaking_tie () =
  let box = "box { <-3.3, 0, -0.8>, <-1.5, 0.5, 0.8> pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }\n" in
  let cyl = "cylinder { <-2.4, 0.5, 0>, <-2.4, 1.5, 0>, 0.6 pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } }\n" in
  let light = "light_source { <0,10,0>, rgb 0 }\n" in
  let o = v (-0x1.4d72cee72319cp+1) 0x1.191f757aee3a2p+0 0x1.20b364a18c7a3p-1 in
  let d = v 0x1.00b5f76b9d548p-2 (-0x1.894be94f3dbfbp-1) (-0x1.2da3db86db2a5p-1) in
  let shoot text = trace_text ~interiors:[] (v37 ^ text) o d in
  result_eq "hierarchy, box first: the cylinder's end" (0., 1., 0.) (shoot (light ^ box ^ cyl));
  result_eq "hierarchy, cylinder first: the cylinder's end" (0., 1., 0.) (shoot (light ^ cyl ^ box));
  result_eq "no hierarchy: the nearer box face" (1., 0., 0.) (shoot (box ^ cyl))

let test_shadowless () =
  (* a small sphere on the way to the light at <√3,1,0>, off the camera ray *)
  let blocker = "sphere { <sqrt(3)/2, 0.5, 0>, 0.1 }\n" in
  let fin = "ambient 0 diffuse 1 phong 1 phong_size 2" in
  (* normal light, blocked: nothing *)
  result_eq "blocked" (0., 0., 0.) (down_from_above (compile (floor_scene ~pigment:"rgb <1,0,0>" fin ^ blocker)));
  (* shadowless: diffuse 0.5 on red, no phong (§3.3), and no shadow test *)
  result_eq "shadowless: diffuse, no phong, no shadow" (0.5, 0., 0.)
    (down_from_above (compile (floor_scene ~pigment:"rgb <1,0,0>" ~light:"color rgb 1 shadowless" fin ^ blocker)))

(* ---- background, reflection and trace levels (§5, §7, §8.4) ---- *)

let test_miss () =
  let r = trace_text (v37 ^ "background { rgb <0.1,0.2,0.3> }") origin plus_z in
  result_eq "3.7 background" (0.1, 0.2, 0.3) r;
  float_eq "3.7 miss transmit 0" 0. r.tr;
  (* a legacy scene without background returns opaque black too: POV-Ray sets the background to
     black with transmit 0 when it writes no alpha channel (fidelity scene aa_legacy_missed) *)
  let r = trace_text "sphere { <0,0,-3>, 1 }" origin plus_z in
  result_eq "legacy default background" (0., 0., 0.) r;
  float_eq "legacy miss transmit 0" 0. r.tr;
  let r = trace_text "background { rgb <0.1,0.2,0.3> }" origin plus_z in
  result_eq "legacy background" (0.1, 0.2, 0.3) r;
  float_eq "legacy background transmit 0" 0. r.tr;
  (* a sphere behind the ray is not hit *)
  result_eq "object behind" (0.1, 0.2, 0.3)
    (trace_text (v37 ^ "background { rgb <0.1,0.2,0.3> } sphere { <0,0,-3>, 1 pigment { rgb 1 } }") origin plus_z)

(* A mirror facing the origin: plane { -z, -5 } is z = 5 with the normal towards the origin. *)
let mirror ?(settings = "") ?(bg = "rgb <0.2,0.4,0.6>") finish =
  Printf.sprintf "%sglobal_settings { %s }\nbackground { %s }\nplane { -z, -5 pigment { rgb 1 } finish { %s } }" v37 settings bg
    finish

let test_reflection () =
  (* ci = 1, type 0: refl = MIN = 1; the reflected ray (−z) misses: result = background *)
  result_eq "mirror" (0.2, 0.4, 0.6) (trace_text (mirror "ambient 0 diffuse 0 reflection 1") origin plus_z);
  result_eq "half mirror" (0.1, 0.2, 0.3) (trace_text (mirror "ambient 0 diffuse 0 reflection 0.5") origin plus_z);
  (* reflection colour per channel: <1,0,0.5>·bg *)
  result_eq "coloured mirror" (0.2, 0., 0.3) (trace_text (mirror "ambient 0 diffuse 0 reflection rgb <1,0,0.5>") origin plus_z);
  (* reflection is added to the local colour: ambient 0.1 + bg *)
  result_eq "ambient + mirror" (0.3, 0.5, 0.7) (trace_text (mirror "ambient 0.1 diffuse 0 reflection 1") origin plus_z);
  (* exponent 2: refl·c^(1/2) = sqrt 0.25 = 0.5 *)
  result_eq "reflection exponent" (0.5, 0.5, 0.5)
    (trace_text (mirror ~bg:"rgb 0.25" "ambient 0 diffuse 0 reflection { 1 exponent 2 }") origin plus_z)

let test_reflection_falloff () =
  (* the floor hit at 60° from the normal: from <−√3,1,0> along <√3/2,−1/2,0>, ci = −D·N = 1/2;
     reflection {0, 1}: frac = 1 − ci = 1/2, refl = 0.5·1 + 0.5·0; the reflected ray misses: bg 1 *)
  let scene f = v37 ^ "background { rgb 1 }\nplane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 " ^ f ^ " } }" in
  let ray f = trace_text (scene f) (v (-.s3) 1. 0.) (v (s3 /. 2.) (-0.5) 0.) in
  result_eq "falloff 1" (0.5, 0.5, 0.5) (ray "reflection { 0, 1 }");
  (* falloff 2: frac = (1/2)² = 1/4 *)
  result_eq "falloff 2" (0.25, 0.25, 0.25) (ray "reflection { 0, 1 falloff 2 }");
  (* min 0.2, max 0.6: 0.5·0.6 + 0.5·0.2 = 0.4 *)
  result_eq "min/max" (0.4, 0.4, 0.4) (ray "reflection { 0.2, 0.6 }");
  (* fresnel, ior 1.5, ci 1/2: s = n² + ci² − 1 = 1.5, g = √1.5 = 1.2247449,
     a = (g − ci)/(g + ci) = 0.4202041, b = (ci(g + ci) − 1)/(ci(g − ci) + 1) = −0.1010205,
     F = ½a²(1 + b²) = 0.0891867 *)
  let fres = v37 ^ "background { rgb 1 }\nplane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } } interior { ior 1.5 } }" in
  (* the ray starts above the plane, outside it (the default camera at the origin lies ON the plane,
     which counts as inside, so the interior list is given explicitly) *)
  result_eq "fresnel at 60°" (0.0891867, 0.0891867, 0.0891867)
    (trace_text ~interiors:[] fres (v (-.s3) 1. 0.) (v (s3 /. 2.) (-0.5) 0.));
  (* from inside (interiors [0]) the relative ior is 1/1.5: s = 4/9 + 1/4 − 1 < 0, total reflection: MAX *)
  result_eq "fresnel from inside" (1., 1., 1.) (trace_text ~interiors:[ 0 ] fres (v (-.s3) 1. 0.) (v (s3 /. 2.) (-0.5) 0.))

let test_fresnel_normal () =
  (* normal incidence, ior 1.5: s = 2.25, g = 1.5, a = 0.5/2.5 = 0.2, b = (2.5 − 1)/(0.5 + 1) = 1,
     F = ½·0.04·2 = 0.04 = ((n−1)/(n+1))² *)
  let text =
    v37
    ^ "background { rgb 1 }\n\
       plane { -z, -5 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection { 1 fresnel } } interior { ior 1.5 } }"
  in
  result_eq "fresnel R0" (0.04, 0.04, 0.04) (trace_text text origin plus_z)

let test_max_trace_level () =
  (* with max_trace_level 1 the mirror's reflected ray starts at level 1 ≥ 1: black, only ambient 0.1 *)
  result_eq "reflection cut off" (0.1, 0.1, 0.1)
    (trace_text (mirror ~settings:"max_trace_level 1" "ambient 0.1 diffuse 0 reflection 1") origin plus_z);
  result_eq "level 2 reaches the background" (0.3, 0.5, 0.7)
    (trace_text (mirror ~settings:"max_trace_level 2" "ambient 0.1 diffuse 0 reflection 1") origin plus_z);
  (* two facing mirrors at z = ±5, each ambient 0.1 plus full reflection: every surface met adds 0.1,
     and max_trace_level N allows N surfaces: 0.1·N *)
  let mirrors n =
    Printf.sprintf
      "%sglobal_settings { max_trace_level %d }\n\
       plane { z, 5 pigment { rgb 1 } finish { ambient 0.1 diffuse 0 reflection 1 } }\n\
       plane { -z, 5 pigment { rgb 1 } finish { ambient 0.1 diffuse 0 reflection 1 } }"
      v37 n
  in
  List.iter
    (fun n ->
      let e = 0.1 *. float_of_int n in
      result_eq (Printf.sprintf "two mirrors, level %d" n) (e, e, e) (trace_text (mirrors n) origin plus_z))
    [ 1; 2; 3; 5 ];
  (* a ray that starts at the limit returns black, not the background *)
  let c = compile (mirror "ambient 0.1 diffuse 0 reflection 1") in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  let r = Trace.trace ctx ~level:5 ~weight:1. ~interiors:[] ~continued:false origin plus_z in
  result_eq "level 5 of 5" (0., 0., 0.) r;
  Alcotest.(check bool) "is Trace.black" true (r = Trace.black);
  (* a weight below adc_bailout (1/255) returns black too *)
  let r = Trace.trace ctx ~level:0 ~weight:0.001 ~interiors:[] ~continued:false origin plus_z in
  Alcotest.(check bool) "below adc_bailout" true (r = Trace.black);
  (* stats: one reflected ray, levels up to 2 *)
  let stats = Stats.create () in
  let ctx = Trace.make_ctx c stats in
  ignore (Trace.trace ctx ~level:0 ~weight:1. ~interiors:[] ~continued:false origin plus_z);
  Alcotest.(check int) "reflected rays" 1 stats.reflected_rays;
  Alcotest.(check int) "max level" 1 stats.max_level

let test_distances () =
  let bg = v37 ^ "background { rgb <0.1,0.2,0.3> }\n" in
  let floor = bg ^ "plane { y, 0 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }" in
  (* §2.1: hits beyond 1e7 are discarded: from <0,1,0> along <1,−1e-8,0> the plane is 1e8 away *)
  result_eq "plane beyond 1e7" (0.1, 0.2, 0.3) (trace_text ~interiors:[] floor (v 0. 1. 0.) (v 1. (-1e-8) 0.));
  (* … and seen at 1e6 it is there: along <1,−1e-6,0> *)
  result_eq "plane at 1e6" (1., 1., 1.) (trace_text ~interiors:[] floor (v 0. 1. 0.) (v 1. (-1e-6) 0.));
  (* every ray ignores hits closer than 1e-4 (MIN_ISECT_DEPTH): the plane 5e-5 below is not hit *)
  result_eq "hit at 5e-5 ignored" (0.1, 0.2, 0.3) (trace_text ~interiors:[] floor (v 0. 5e-5 0.) (v 0. (-1.) 0.));
  result_eq "hit at 2e-4 kept" (1., 1., 1.) (trace_text ~interiors:[] floor (v 0. 2e-4 0.) (v 0. (-1.) 0.))

let test_adc_bailout () =
  (* §7: the reflected ray's weight is 1·max(refl); below adc_bailout it returns black *)
  result_eq "reflection 0.4 < adc_bailout 0.5" (0.1, 0.1, 0.1)
    (trace_text (mirror ~settings:"adc_bailout 0.5" "ambient 0.1 diffuse 0 reflection 0.4") origin plus_z);
  (* reflection 0.6 ≥ 0.5: 0.1 + 0.6·<0.2,0.4,0.6> = <0.22,0.34,0.46> *)
  result_eq "reflection 0.6" (0.22, 0.34, 0.46)
    (trace_text (mirror ~settings:"adc_bailout 0.5" "ambient 0.1 diffuse 0 reflection 0.6") origin plus_z)

(* ---- transparency (§6) ---- *)

let glass ?(settings = "") ?(interior = "") pigment =
  Printf.sprintf "%sglobal_settings { %s }\nbackground { rgb 1 }\nsphere { <0,0,5>, 1 pigment { %s } finish { ambient 0 diffuse 0 } %s }"
    v37 settings pigment interior

let test_transmit () =
  (* rgbt <1,1,1,0.5>, ior 1: two surfaces each pass filcol = 0.5 of the white background: 0.25 *)
  result_eq "two surfaces" (0.25, 0.25, 0.25) (trace_text (glass "rgbt <1,1,1,0.5>") origin plus_z);
  (* filter: filcol = rgb·f = <1,0.5,0>·1; twice: <1,0.25,0> *)
  result_eq "filter" (1., 0.25, 0.) (trace_text (glass "rgbf <1,0.5,0,1>") origin plus_z);
  (* §7: ior-1 rays are continued and do not use up a level: max_trace_level 2 still sees through *)
  result_eq "continued rays keep the level" (0.25, 0.25, 0.25)
    (trace_text (glass ~settings:"max_trace_level 2" "rgbt <1,1,1,0.5>") origin plus_z);
  (* … but the level test still applies to them: with max_trace_level 1 the continued ray starts at 1 *)
  result_eq "continued ray at the limit" (0., 0., 0.)
    (trace_text (glass ~settings:"max_trace_level 1" "rgbt <1,1,1,0.5>") origin plus_z);
  (* ior 1.5 along the axis: the ray goes straight (normal incidence), but each refraction uses a level:
     max_trace_level 3 passes (levels 1, 2, then the background), 2 does not *)
  result_eq "refraction, level 3" (0.25, 0.25, 0.25)
    (trace_text (glass ~settings:"max_trace_level 3" ~interior:"interior { ior 1.5 }" "rgbt <1,1,1,0.5>") origin plus_z);
  result_eq "refraction, level 2" (0., 0., 0.)
    (trace_text (glass ~settings:"max_trace_level 2" ~interior:"interior { ior 1.5 }" "rgbt <1,1,1,0.5>") origin plus_z)

let test_att () =
  (* rgbf <0.5,0.5,0.5,0.4>, ambient 1: filcol = 0.5·0.4 = 0.2.
     3.7: att = 1 − 0.4 = 0.6, each surface emits 0.5·0.6 = 0.3, black background:
       back 0.3 + 0.2·0 = 0.3, front 0.3 + 0.2·0.3 = 0.36.
     legacy: att = 1 − 0.4·0.5 = 0.8, each surface emits 0.4: 0.4 + 0.2·0.4 = 0.48 *)
  let body = "sphere { <0,0,5>, 1 pigment { rgbf <0.5,0.5,0.5,0.4> } finish { ambient 1 diffuse 0 } }" in
  result_eq "3.7 att" (0.36, 0.36, 0.36) (trace_text (v37 ^ body) origin plus_z);
  result_eq "legacy att" (0.48, 0.48, 0.48) (trace_text body origin plus_z)

let test_interior_fade () =
  (* rgbt 1 (att 0, filcol 1), white background; the ray travels d = 2 inside the sphere.
     §6.3 at the exit: fade_colour 0 + 1/(1 + (2/1)²) = 0.2 *)
  result_eq "fade 1 2" (0.2, 0.2, 0.2)
    (trace_text (glass ~interior:"interior { fade_distance 1 fade_power 2 }" "rgbt <1,1,1,1>") origin plus_z);
  (* fade_power left at 0: (d/fd)^0 = 1, factor 1/2 for camera rays *)
  result_eq "fade_power 0" (0.5, 0.5, 0.5)
    (trace_text (glass ~interior:"interior { fade_distance 1 }" "rgbt <1,1,1,1>") origin plus_z);
  (* fade_colour <1,0,0>: red channel 1 + 0 = 1, others 0.2 *)
  result_eq "fade_colour" (1., 0.2, 0.2)
    (trace_text (glass ~interior:"interior { fade_distance 1 fade_power 2 fade_color rgb <1,0,0> }" "rgbt <1,1,1,1>")
       origin plus_z)

(* Segment.through: what a ray meets on its way to a hit, the interior's fade by the ray's kind *)
let test_segment () =
  let glass interior = (compile (v37 ^ "sphere { 0, 1 pigment { rgbt 1 } interior { " ^ interior ^ " } }")).objects.(0) in
  let o = glass "fade_distance 1" in
  (* §13.11: fade_power 0 gives (d/fd)^0 = 1, the factor 1/2 for the rays but shadow rays *)
  rgb_eq ~eps:1e-7 "camera ray inside, fade_power 0" (Rgb.grey 0.5) (Segment.through Ray.Camera o [ o.iid ] 2. Rgb.white);
  rgb_eq ~eps:1e-7 "transmitted ray inside, fade_power 0" (Rgb.grey 0.5) (Segment.through Ray.Transmitted o [ o.iid ] 2. Rgb.white);
  rgb_eq "shadow ray inside, fade_power 0: no fade (§4)" Rgb.white (Segment.through Ray.Shadow o [ o.iid ] 2. Rgb.white);
  rgb_eq "outside the interior: no fade" Rgb.white (Segment.through Ray.Camera o [] 2. Rgb.white);
  let o = glass "fade_distance 1 fade_power 2" in
  (* 1/(1 + (2/1)²) *)
  rgb_eq ~eps:1e-7 "shadow ray inside, fade_power 2" (Rgb.grey 0.2) (Segment.through Ray.Shadow o [ o.iid ] 2. Rgb.white);
  rgb_eq "no fade_distance: no fade" Rgb.white (Segment.through Ray.Reflected (glass "fade_power 2") [ 0 ] 2. Rgb.white)

let test_camera_inside () =
  (* the camera at the centre of a transmit-1 sphere of radius 1 with fade: start_interiors = [0], so the
     exit at distance 1 fades by 1/(1 + (1/1)²) = 0.5; with interiors [] it would not fade *)
  let text =
    v37 ^ "background { rgb 1 }\nsphere { 0, 1 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { fade_distance 1 fade_power 2 } }"
  in
  let c = compile text in
  Alcotest.(check (list int)) "camera inside" [ 0 ] c.start_interiors;
  (* rgbt 1 = <1,1,1,0,1>: filcol = 1 *)
  result_eq "fade from inside" (0.5, 0.5, 0.5) (trace_ray c origin plus_z)

let test_conserve_energy () =
  (* a transmit-1 plane z = 5 (filcol 1) with reflection 0.5, white background: the transmitted ray
     (ior 1, continued) and the reflected ray (−z) both see the background.
     Without conserve_energy: 1·1 + 0.5·1 = 1.5; with it filcol ·= min(1, 1 − 0.5): 0.5 + 0.5 = 1 *)
  let plane extra =
    v37 ^ "background { rgb 1 }\nplane { -z, -5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 reflection 0.5 " ^ extra ^ " } }"
  in
  result_eq "without conserve_energy" (1.5, 1.5, 1.5) (trace_text (plane "") origin plus_z);
  result_eq "with conserve_energy" (1., 1., 1.) (trace_text (plane "conserve_energy") origin plus_z)

let test_metallic_reflection () =
  (* normal incidence: x = acos(1)/(π/2) = 0, F = 0.014567225/1.12² − 0.011612903 ≈ 0 (clamped);
     refl ·= 1 + 1·(1 − F)(C − 1) = C: a red mirror reflects <1,0,0>·background *)
  result_eq "metallic mirror" (1., 0., 0.)
    (trace_text
       (v37 ^ "background { rgb 1 }\nplane { -z, -5 pigment { rgb <1,0,0> } finish { ambient 0 diffuse 0 reflection { 1 metallic } } }")
       origin plus_z);
  (* metallic 0.5: 1 + 0.5·(0 − 1) = 0.5 on green and blue *)
  result_eq "half metallic" (1., 0.5, 0.5)
    (trace_text
       (v37 ^ "background { rgb 1 }\nplane { -z, -5 pigment { rgb <1,0,0> } finish { ambient 0 diffuse 0 reflection { 1 metallic 0.5 } } }")
       origin plus_z)

let test_sky_sphere () =
  (* §18.1, 3.7: one pigment rgbt <1,0,0,0.5>, emission 0.5, background <0,0,1>:
     col = <1,0,0>·(1 − 0 − 0.5)·1·0.5 = <0.25,0,0>; fil = rgb·f + t = 0.5; + bg·0.5 = <0.25,0,0.5> *)
  result_eq "3.7 one layer" (0.25, 0., 0.5)
    (trace_text (v37 ^ "background { rgb <0,0,1> }\nsky_sphere { pigment { rgbt <1,0,0,0.5> } emission 0.5 }") origin plus_z);
  (* two layers, the last written on top: rgb <0,1,0> under rgbt <1,0,0,0.5>, emission 1:
     top: col = <0.5,0,0>, fil = 0.5; bottom: col += <0,1,0>·1·0.5 = <0.5,0.5,0>, fil = 0: no background *)
  result_eq "3.7 two layers" (0.5, 0.5, 0.)
    (trace_text
       (v37 ^ "background { rgb <0,0,1> }\nsky_sphere { pigment { rgb <0,1,0> } pigment { rgbt <1,0,0,0.5> } }")
       origin plus_z);
  (* legacy, one layer rgbf <1,0.5,0,0.5>, emission 1, background rgb 1:
     col = rgb·1·(1 − 0.5) = <0.5,0.25,0>; F = <1,0.5,0,0.5,0>; bg·(F.rgb·F.f + F.t) = <0.5,0.25,0>;
     total <1,0.5,0> *)
  result_eq "legacy one layer" (1., 0.5, 0.)
    (trace_text "background { rgb 1 }\nsky_sphere { pigment { rgbf <1,0.5,0,0.5> } }" origin plus_z)

let tests =
  [
    Alcotest.test_case "diffuse head-on" `Quick test_diffuse_head_on;
    Alcotest.test_case "ambient and emission" `Quick test_ambient;
    Alcotest.test_case "light without colour" `Quick test_light_without_colour;
    Alcotest.test_case "diffuse at an angle" `Quick test_diffuse_angle;
    Alcotest.test_case "phong" `Quick test_phong;
    Alcotest.test_case "specular" `Quick test_specular;
    Alcotest.test_case "light fade" `Quick test_light_fade;
    Alcotest.test_case "shadows" `Quick test_shadows;
    Alcotest.test_case "shadow with interior fade" `Quick test_shadow_fade;
    Alcotest.test_case "shadow cache" `Quick test_shadow_cache;
    Alcotest.test_case "equal depths" `Quick test_depth_ties;
    Alcotest.test_case "a tie overtaken by the bounding tree" `Quick test_overtaking_tie;
    Alcotest.test_case "shadowless light" `Quick test_shadowless;
    Alcotest.test_case "miss" `Quick test_miss;
    Alcotest.test_case "reflection" `Quick test_reflection;
    Alcotest.test_case "reflection falloff and fresnel" `Quick test_reflection_falloff;
    Alcotest.test_case "fresnel at normal incidence" `Quick test_fresnel_normal;
    Alcotest.test_case "max_trace_level" `Quick test_max_trace_level;
    Alcotest.test_case "distance limits" `Quick test_distances;
    Alcotest.test_case "adc_bailout" `Quick test_adc_bailout;
    Alcotest.test_case "transmit and levels" `Quick test_transmit;
    Alcotest.test_case "att" `Quick test_att;
    Alcotest.test_case "interior fade" `Quick test_interior_fade;
    Alcotest.test_case "what a ray meets on its way (Segment)" `Quick test_segment;
    Alcotest.test_case "camera inside" `Quick test_camera_inside;
    Alcotest.test_case "conserve_energy" `Quick test_conserve_energy;
    Alcotest.test_case "metallic reflection" `Quick test_metallic_reflection;
    Alcotest.test_case "sky_sphere" `Quick test_sky_sphere;
  ]
