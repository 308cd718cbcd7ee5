(* UV coordinates (the shapes' UVCoord methods of POV-Ray 3.7) and uv_mapping (parstxtr.cpp's
   UV_MAPPING_TOKEN, pigment.cpp's and normal.cpp's UV_MAP_PATTERN, mesh and mesh2 UV data).

   Two kinds of expected values: exact ones worked out by hand from POV-Ray's formulas at chosen
   points, and POV-Ray's own, read from 16-bit renders of one pixel (so to about 2e-5): an
   orthographic camera looking along +z through (X, Y) at the object with

     #version 3.7; global_settings { assumed_gamma 1 }
     camera { orthographic location <X, Y, -10> direction z right x*1e-4 up y*1e-4 }
     #declare P = pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] } }
     object { OBJECT texture { pigment { P } finish { ambient 1 diffuse 0 } } }

   rendered with +W1 +H1 -A +FN16 File_Gamma=1.0 (and gradient y for v); the pixel's red is u. *)

open Helpers

let the_compiled text = (compile ("#version 3.7;\n" ^ text)).objects.(0)

(* the surface point seen along +z through (x, y) from z = −10, its part, and its UV coordinates *)
let probe text x y =
  let ob = the_compiled text in
  let w = Scratch.create ~robust:false (Stats.create ()) in
  let o = v x y (-10.) and d = v 0. 0. 1. in
  let t = Shape.depth w ob.shape o d 0. in
  if not (t < infinity) then Alcotest.fail "the probe ray misses";
  Shape.uv ob w.part w.crossing (Vec.madd o t d)

let uv_eq ?(eps = 1e-12) msg (u, v') (a : Vec.t) =
  float_eq ~eps (msg ^ ": u") u a.x;
  float_eq ~eps (msg ^ ": v") v' a.y;
  float_eq ~eps:0. (msg ^ ": 0") 0. a.z

(* POV-Ray's renders, read to 16 bits *)
let pov = 2e-5

let test_sphere_formula () =
  let c = Vec.zero in
  (* u = θ/2π from +x towards +z, v = 0.5 + asin(y)/π *)
  uv_eq "+x" (0., 0.5) (Sphere.uv_of (v 1. 0. 0.) c);
  uv_eq "+z: θ = π/2" (0.25, 0.5) (Sphere.uv_of (v 0. 0. 1.) c);
  uv_eq "−x: z = 0 and x ≤ 0 give π" (0.5, 0.5) (Sphere.uv_of (v (-1.) 0. 0.) c);
  uv_eq "−z: 2π − π/2" (0.75, 0.5) (Sphere.uv_of (v 0. 0. (-1.)) c);
  uv_eq "north pole: u = 0" (0., 1.) (Sphere.uv_of (v 0. 1. 0.) c);
  uv_eq "south pole" (0., 0.) (Sphere.uv_of (v 0. (-3.) 0.) c);
  uv_eq "the centre: (0, 0)" (0., 0.) (Sphere.uv_of c c);
  (* 45° up between +x and +z: v = 0.5 + asin(√½)/π = 0.75, u = 1/8 *)
  let s = sqrt 0.5 in
  uv_eq ~eps:1e-15 "up and round" (0.125, 0.75) (Sphere.uv_of (v 0.5 s 0.5) (v 0. 0. 0.))

let test_sphere () =
  (* unmoved: the world point about the centre *)
  let u = probe "sphere { <1, 2, 3>, 1 }" 1. 2. in
  uv_eq "facing −z: 3/4" (0.75, 0.5) u;
  (* rotated: the frame of its modifiers (POV-Ray: 0.879469, 0.488212) *)
  let u = probe "sphere { 0, 1 rotate <20, 30, 0> }" 0.3 0.2 in
  uv_eq ~eps:pov "rotated (POV-Ray)" (0.879469, 0.488212) u;
  (* the same by hand: the point brought back by the inverse rotation *)
  let p = v 0.3 0.2 (-.sqrt (1. -. 0.13)) in
  let q = Transform.inv_point (Transform.rotate (v 20. 30. 0.)) p in
  uv_eq ~eps:1e-12 "rotated (formula)" (let r = Sphere.uv_of q Vec.zero in (r.x, r.y)) u;
  (* an ellipsoid after a translate (POV-Ray: 0.801205, 0.576547) *)
  let u = probe "sphere { <0.2, 0, 0>, 0.8 translate <-0.2, 0, 0> scale <0.8, 1.3, 0.9> rotate <0, 0, 20> }" 0.1 0.3 in
  uv_eq ~eps:pov "ellipsoid (POV-Ray)" (0.801205, 0.576547) u

let test_sphere_translated () =
  (* a translate only: the point and the centre both brought back, u and v as unmoved *)
  let u = probe "sphere { 0, 1 translate <5, -1, 2> }" 5. (-1.) in
  uv_eq "front" (0.75, 0.5) u;
  let u = probe "sphere { 0, 2 scale 0.5 translate x }" 1. 0.5 in
  uv_eq ~eps:1e-15 "scaled: 30° up" (0.75, 0.5 +. (asin 0.5 /. Float.pi)) u

let test_box () =
  (* Z− side of box { <-1,-1,-1>, <1,2,3> } at (0.3, 0.2): P = (0.65, 0.4, 0), u = 1 − x/4, v = 1/3 + y/3
     (POV-Ray: 0.837507, 0.466667) *)
  let text = "box { <-1, -1, -1>, <1, 2, 3> }" in
  let u = probe text 0.3 0.2 in
  uv_eq "Z− by the formula" (1. -. (0.65 /. 4.), (1. /. 3.) +. (0.4 /. 3.)) u;
  uv_eq ~eps:pov "Z− (POV-Ray)" (0.837507, 0.466667) u;
  (* every side at its centre: the cross of a cube map *)
  let ob = the_compiled "box { <0, 0, 0>, <2, 4, 8> }" in
  let at side p = Shape.uv ob side Crossing.none p in
  uv_eq "X− centre" (0.125, 0.5) (at 1 (v 0. 2. 4.));
  uv_eq "X+ centre" (0.625, 0.5) (at 2 (v 2. 2. 4.));
  uv_eq "Y− centre" (0.375, 1. /. 6.) (at 3 (v 1. 0. 4.));
  uv_eq "Y+ centre" (0.375, 1. -. (0.5 /. 3.)) (at 4 (v 1. 4. 4.));
  uv_eq "Z− centre" (0.875, 0.5) (at 5 (v 1. 2. 0.));
  uv_eq "Z+ centre" (0.375, 0.5) (at 6 (v 1. 2. 8.));
  (* a rotated box in its own space: Z− of the unrotated box is seen after rotate y*90 from −x... *)
  let ob = the_compiled "box { <0, 0, 0>, <2, 4, 8> rotate y*90 }" in
  let q = Transform.point (Transform.rotate (v 0. 90. 0.)) (v 1. 2. 0.) in
  uv_eq ~eps:1e-12 "rotated: its Z− centre" (0.875, 0.5) (Shape.uv ob 5 Crossing.none q)

let test_torus () =
  let ob = the_compiled "torus { 1, 0.25 }" in
  (* on the outer equator at +x: atan2(0, 1.25) = 0: u = 1 − π/2π = 0.5; v = (0 + π)/2π = 0.5 *)
  uv_eq "outer +x" (0.5, 0.5) (Shape.uv ob (-1) Crossing.none (v 1.25 0. 0.));
  (* the top of the tube above +z: atan2(1, 0) = π/2, u = 1 − 3/4; ρ − R = 0, atan2(0.25, 0) = π/2 *)
  uv_eq ~eps:1e-15 "top over +z" (0.25, 0.75) (Shape.uv ob (-1) Crossing.none (v 0. 0.25 1.));
  (* rotated (POV-Ray: 0.505074, 0.71162) *)
  uv_eq ~eps:pov "rotated (POV-Ray)" (0.505074, 0.71162) (probe "torus { 1, 0.4 rotate <-70, 20, 0> }" 0.9 0.1)

let test_default () =
  (* shapes without a UVCoord of their own: the world x and y, whatever their transform (POV-Ray:
     0.100008, 0.2 for the cylinder) *)
  uv_eq ~eps:pov "rotated cylinder (POV-Ray)" (0.100008, 0.2) (probe "cylinder { <0, -1, 0>, <0, 1, 0>, 0.5 rotate z*30 }" 0.1 0.2);
  uv_eq "plane" (0.25, -0.5) (probe "plane { -z, 1 rotate x*10 }" 0.25 (-0.5));
  uv_eq "disc" (0.1, 0.2) (probe "disc { 0, z, 1 scale 2 }" 0.1 0.2)

let test_mesh () =
  (* POV-Ray: 0.500618, 0.475074 for the moved triangle; 0.420005, 0.465003 for the one whose
     corners the set-up swaps *)
  let moved = "mesh { triangle { <-1,-1,0>, <1,-1,0>, <0,1,0> uv_vectors <0.1,0.2>, <0.9,0.3>, <0.4,0.8> } rotate y*10 }" in
  uv_eq ~eps:pov "moved (POV-Ray)" (0.500618, 0.475074) (probe moved 0.1 (-0.2));
  let swapped = "mesh { triangle { <1,-1,0>, <-1,-1,0>, <0,1,0> uv_vectors <0.1,0.2>, <0.9,0.3>, <0.4,0.8> } }" in
  uv_eq ~eps:pov "swapped (POV-Ray)" (0.420005, 0.465003) (probe swapped 0.1 (-0.2));
  (* at the corners: their own UV coordinates, swap or not *)
  let ob = the_compiled swapped in
  uv_eq ~eps:1e-15 "corner 1" (0.1, 0.2) (Shape.uv ob 0 Crossing.none (v 1. (-1.) 0.));
  uv_eq ~eps:1e-15 "corner 2" (0.9, 0.3) (Shape.uv ob 0 Crossing.none (v (-1.) (-1.) 0.));
  uv_eq ~eps:1e-15 "corner 3" (0.4, 0.8) (Shape.uv ob 0 Crossing.none (v 0. 1. 0.));
  (* the centroid: the mean *)
  uv_eq ~eps:1e-15 "centroid" ((0.1 +. 0.9 +. 0.4) /. 3., (0.2 +. 0.3 +. 0.8) /. 3.) (Shape.uv ob 0 Crossing.none (v 0. (-1. /. 3.) 0.));
  (* a triangle without uv_vectors has (0, 0) at every corner, before and after one with them *)
  let ob =
    the_compiled
      "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <2,0,0>, <3,0,0>, <2,1,0> uv_vectors <1,1>, <1,1>, <1,1> } triangle { <4,0,0>, <5,0,0>, <4,1,0> } }"
  in
  uv_eq "first, none" (0., 0.) (Shape.uv ob 0 Crossing.none (v 0.2 0.2 0.));
  uv_eq ~eps:1e-15 "second, all (1, 1)" (1., 1.) (Shape.uv ob 1 Crossing.none (v 2.2 0.2 0.));
  uv_eq "third, none" (0., 0.) (Shape.uv ob 2 Crossing.none (v 4.2 0.2 0.));
  (* no uv_vectors at all: nothing is stored *)
  match (scene "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }").objects with
  | [ { shape = Mesh { mesh; _ }; _ } ] ->
      Alcotest.(check int) "no UVs stored" 0 (Array.length mesh.uvs);
      Alcotest.(check int) "no UV indices stored" 0 (Bigarray.Array1.dim mesh.fuv)
  | _ -> Alcotest.fail "expected one mesh"

let square = "vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> } "

let test_mesh2 () =
  (* uv_indices *)
  let ob =
    the_compiled ("mesh2 { " ^ square ^ "uv_vectors { 2, <0.5, 0.25>, <1, 2> } face_indices { 2, <0,1,2>, <0,2,3> } uv_indices { 2, <0,0,1>, <1,1,1> } }")
  in
  uv_eq "uv_indices: corner 1" (0.5, 0.25) (Shape.uv ob 0 Crossing.none (v 0. 0. 0.));
  uv_eq ~eps:1e-15 "uv_indices: corner 3" (1., 2.) (Shape.uv ob 0 Crossing.none (v 1. 1. 0.));
  uv_eq ~eps:1e-15 "uv_indices: second face" (1., 2.) (Shape.uv ob 1 Crossing.none (v 0.2 0.5 0.));
  (* as many UV vectors as vertices: the face indices *)
  let ob = the_compiled ("mesh2 { " ^ square ^ "uv_vectors { 4, <0,0>, <2,0>, <2,2>, <0,2> } face_indices { 2, <0,1,2>, <0,2,3> } }") in
  uv_eq ~eps:1e-15 "by the face indices" (1.2, 0.8) (Shape.uv ob 0 Crossing.none (v 0.6 0.4 0.));
  (* one UV vector: every corner *)
  let ob = the_compiled ("mesh2 { " ^ square ^ "uv_vectors { 1, <0.5, 0.5> } face_indices { 2, <0,1,2>, <0,2,3> } }") in
  uv_eq ~eps:1e-15 "one for all" (0.5, 0.5) (Shape.uv ob 1 Crossing.none (v 0.2 0.5 0.));
  expect_scene_error "neither as many nor uv_indices"
    ("mesh2 { " ^ square ^ "uv_vectors { 2, <0,0>, <1,1> } face_indices { 2, <0,1,2>, <0,2,3> } }")
    ~line:1 ~col:97 ~sub:"without uv_indices";
  expect_scene_error "uv index out of range"
    ("mesh2 { " ^ square ^ "uv_vectors { 2, <0,0>, <1,1> } face_indices { 1, <0,1,2> } uv_indices { 1, <0,1,2> } }")
    ~line:1 ~col:141 ~sub:"out of range";
  expect_scene_error "as many uv_indices as faces"
    ("mesh2 { " ^ square ^ "uv_vectors { 2, <0,0>, <1,1> } face_indices { 2, <0,1,2>, <0,2,3> } uv_indices { 1, <0,1,1> } }")
    ~line:1 ~col:134 ~sub:"uv_indices has 1 entries"

let patterned (p : Scene.pigment) = match p with Pattern pp -> pp | Solid _ | Solid_placed _ -> Alcotest.fail "a pattern pigment"

let test_parse () =
  let o = the_object (scene "sphere { 0, 1 pigment { uv_mapping checker rgb 1 rgb 0 scale 0.5 } rotate y*30 translate x }") in
  let pp = patterned (layer_of o).pigment in
  Alcotest.(check bool) "flagged" true pp.uv_mapping;
  (* only the pigment's own scale: the object's transforms go to the wrapper, never used *)
  (match pp.warps with
  | [ Transform_warp t ] -> vec_eq "its own scale" (v 2. 2. 2.) (Transform.inv_direction t (v 1. 1. 1.))
  | _ -> Alcotest.fail "one transform");
  (* a plain colour is the same everywhere *)
  (match (layer_of (the_object (scene "sphere { 0, 1 pigment { uv_mapping rgb <1, 0, 0> } }"))).pigment with
  | Solid _ -> ()
  | Solid_placed _ | Pattern _ -> Alcotest.fail "a plain colour");
  (* a declared uv-mapped pigment keeps its warps when edited *)
  let o = the_object (scene "#declare P = pigment { uv_mapping checker }\nsphere { 0, 1 pigment { P scale 3 } }") in
  Alcotest.(check int) "no warps" 0 (List.length (patterned (layer_of o).pigment).warps);
  (* a normal *)
  let o = the_object (scene "sphere { 0, 1 normal { uv_mapping bumps 0.7 scale 0.1 } scale 2 }") in
  (match (layer_of o).normal with
  | Some n ->
      Alcotest.(check bool) "normal flagged" true n.nuv_mapping;
      float_eq "its amount" (Precision.f32 0.7) n.amount;
      Alcotest.(check int) "its own scale only" 1 (List.length n.nwarps)
  | None -> Alcotest.fail "a normal");
  (* texture { uv_mapping … }: the rest of the block is a texture of its own (its scale moves its
     pigment), wrapped; the object's rotate goes to the wrapper, which only bends normals *)
  let o = the_object (scene "sphere { 0, 1 texture { uv_mapping pigment { checker } normal { bumps } scale 2 } rotate x*10 }") in
  (match o.texture with
  | Uv_mapped { uwarps; inner = Layers [ l ] } ->
      Alcotest.(check int) "texture: the wrapper's rotate" 1 (List.length uwarps);
      Alcotest.(check int) "texture: its pigment's own scale only" 1 (List.length (patterned l.pigment).warps);
      Alcotest.(check bool) "texture: its normal" true (l.normal <> None)
  | _ -> Alcotest.fail "a uv-mapped texture");
  (* only first *)
  expect_scene_error "after the pattern" "sphere { 0, 1 pigment { checker uv_mapping } }" ~line:1 ~col:33 ~sub:"comes first"

let test_eval () =
  (* the pattern sees the hit's (u, v, 0), not the point *)
  let o = the_object (scene "sphere { 0, 1 pigment { uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] } } }") in
  let hit = { Patterns.no_hit with uv = v 0.25 0.5 0. } in
  colour_eq "u = 0.25" (colour5 0.25 0.25 0.25 0. 0.) (Pigment.colour_at 2 (layer_of o).pigment hit (v 0.9 0.9 0.9));
  (* a pigment_map entry uv-mapped inside a pattern that is not *)
  let o =
    the_object (scene "sphere { 0, 1 pigment { gradient y pigment_map { [0 uv_mapping gradient x color_map { [0 rgb 0] [1 rgb 1] }] [1 rgb 1] } } }")
  in
  colour_eq "entry at u" (colour5 0.5 0.5 0.5 0. 0.) (Pigment.colour_at 2 (layer_of o).pigment { hit with uv = v 0.5 0. 0. } (v 0. 0. 0.));
  (* compiled surfaces ask for UV coordinates only when they read them *)
  let needs text = (surf_of (the_compiled text)).needs_uv in
  Alcotest.(check bool) "plain" false (needs "sphere { 0, 1 pigment { checker } normal { bumps } }");
  Alcotest.(check bool) "uv pigment" true (needs "sphere { 0, 1 pigment { uv_mapping checker } }");
  Alcotest.(check bool) "uv normal" true (needs "sphere { 0, 1 normal { uv_mapping bumps } }");
  Alcotest.(check bool) "uv normal_map entry" true (needs "sphere { 0, 1 normal { gradient x normal_map { [0 uv_mapping bumps] [1 dents] } } }")

let tests =
  [
    Alcotest.test_case "sphere formula" `Quick test_sphere_formula;
    Alcotest.test_case "sphere, moved and ellipsoid" `Quick test_sphere;
    Alcotest.test_case "sphere, translated and scaled" `Quick test_sphere_translated;
    Alcotest.test_case "box sides" `Quick test_box;
    Alcotest.test_case "torus" `Quick test_torus;
    Alcotest.test_case "default UVCoord" `Quick test_default;
    Alcotest.test_case "mesh uv_vectors" `Quick test_mesh;
    Alcotest.test_case "mesh2 uv_vectors and uv_indices" `Quick test_mesh2;
    Alcotest.test_case "uv_mapping parsed" `Quick test_parse;
    Alcotest.test_case "uv_mapping evaluated" `Quick test_eval;
  ]
