(* Mesh: storage, set-up, intersection, inside test and per-face textures of meshes
   (docs/povray-rules.md §2.6), built with Mesh.build or from mesh {} / mesh2 {} scenes. Values by hand. *)

open Helpers

let f32 x = Int32.float_of_bits (Int32.bits_of_float x)
let f32v (p : Vec.t) = v (f32 p.x) (f32 p.y) (f32 p.z)
let s2 = sqrt 2.
let stack () = Array.make 512 0.
let flat_array l = Array.concat (List.map (fun (p : Vec.t) -> [| p.x; p.y; p.z |]) l)

let build ?(normals = []) ?(fn = [||]) ?(ftex = [||]) ?inside verts fv =
  Mesh.build ~vertices:(flat_array verts) ~vertex_normals:(flat_array normals) ~fv ~fn ~ftex ~corners:None ~inside_vector:inside

(* The mesh of a scene with one mesh object: the shared data, the placement (the point the
   transform takes the origin to) and the texture list. *)
let mesh_of text =
  match (the_object (scene text)).shape with
  | Mesh { mesh; trans; textures } ->
      (mesh, (match trans with None -> Vec.zero | Some t -> Transform.point t Vec.zero), textures)
  | _ -> Alcotest.fail "expected a mesh"

(* The triangle of Test_triangle, in the plane z = 2 with face normal <0,0,-1>. *)
let p1 = v (-1.) (-1.) 2.
let p2 = v 1. (-1.) 2.
let p3 = v 0. 1. 2.
let plus_z = v 0. 0. 1.

(* ---- storage ---- *)

let test_single_precision () =
  (* §2.6: vertices are floats: 0.1 is stored as the float nearest 0.1 (0.100000001490116…) *)
  let m, _, _ = mesh_of "mesh2 { vertex_vectors { 3, <0.1,0,0.1>, <1,0,0.1>, <0,1,0.1> } face_indices { 1, <0,1,2> } }" in
  Alcotest.(check int) "faces" 1 m.faces;
  float_eq ~eps:0. "mesh2 x" (f32 0.1) m.vertices.{0};
  float_eq ~eps:0. "mesh2 z" (f32 0.1) m.vertices.{2};
  Alcotest.(check bool) "f32 0.1 is not 0.1" true (f32 0.1 <> 0.1);
  (* N = normalize((P3 − P1) × (P2 − P1)) = normalize(<-a,1,0> × <1 − a,0,0>) (a = f32 0.1)
       = normalize(<0, 0, −(1 − a)>) = <0,0,-1>; Distance = −N·P1 = z1.
     mesh2: from the float values, so f32 0.1; the ray up the z axis from <0.2,0.2,0> meets it
     at t = −(Distance + N·O)/(N·D) = Distance *)
  float_eq ~eps:0. "mesh2 distance from floats" (f32 0.1) m.fdist.(0);
  let hit = [| 0. |] in
  Alcotest.(check int) "mesh2 hit" 0 (Mesh.nearest m (stack ()) (v 0.2 0.2 0.) plus_z 0. hit);
  float_eq ~eps:1e-15 "mesh2 depth" (f32 0.1) hit.(0);
  (* mesh: the vertices are floats too; Distance is computed from the parsed doubles, and like
     mesh2's it is stored in single precision (MESH_TRIANGLE's SNGL Distance) *)
  let m, _, _ = mesh_of "mesh { triangle { <0.1,0,0.1>, <1,0,0.1>, <0,1,0.1> } }" in
  float_eq ~eps:0. "mesh x" (f32 0.1) m.vertices.{0};
  float_eq ~eps:0. "mesh z" (f32 0.1) m.vertices.{2};
  float_eq ~eps:0. "mesh distance, single precision" (f32 0.1) m.fdist.(0);
  Alcotest.(check int) "mesh hit" 0 (Mesh.nearest m (stack ()) (v 0.2 0.2 0.) plus_z 0. hit);
  float_eq ~eps:1e-15 "mesh depth" (f32 0.1) hit.(0);
  (* far from the origin the rounding shows: the plane z = 100000.3 is stored at the nearest
     float, 100000.296875 (floats are 1/128 apart there), and is hit there *)
  let m, _, _ = mesh_of "mesh { triangle { <1e5,0,100000.3>, <100001,0,100000.3>, <1e5,1,100000.3> } }" in
  float_eq ~eps:0. "far distance" 100000.296875 m.fdist.(0);
  Alcotest.(check int) "far hit" 0 (Mesh.nearest m (stack ()) (v 100000.2 0.2 0.) plus_z 0. hit);
  float_eq ~eps:0. "far depth" 100000.296875 hit.(0);
  (* normal_vectors are normalised, then stored as floats: <0,3,4>/5 = <0,0.6,0.8> *)
  let m, _, _ =
    mesh_of
      "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } normal_vectors { 3, <0,3,4>, <0,0,2>, <0,0,1> } face_indices { 1, <0,1,2> } }"
  in
  float_eq ~eps:0. "normal y" (f32 0.6) m.vnormals.{1};
  float_eq ~eps:0. "normal z" (f32 0.8) m.vnormals.{2};
  float_eq ~eps:0. "second normal z" 1. m.vnormals.{5}

let test_degenerate_dropped () =
  (* faces: a good one (texture 5), collinear corners, a repeated corner, a good one (texture 7) *)
  let m =
    build
      [ p1; p2; p3; v 0. 0. 0.; v 1. 2. 3.; v 2. 4. 6. ]
      [| 0; 1; 2; 3; 4; 5; 0; 0; 1; 0; 2; 1 |]
      ~ftex:[| 5; -1; -1; 7 |]
  in
  Alcotest.(check int) "two faces kept" 2 m.faces;
  (* the kept faces keep their order and their texture indices *)
  Alcotest.(check int) "first face's texture" 5 (Mesh.texture m 0);
  Alcotest.(check int) "last face's texture" 7 (Mesh.texture m 1);
  (* both lie in z = 2 around the origin: the nearest from the origin is at 2 *)
  let hit = [| 0. |] in
  Alcotest.(check bool) "hit" true (Mesh.nearest m (stack ()) (v 0. 0. 0.) plus_z 0. hit >= 0);
  float_eq "depth" 2. hit.(0);
  (* in a mesh {}: dropped silently (§2.6), no warning *)
  let text =
    "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n\
     mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <0,0,0>, <1,1,1>, <2,2,2> } }"
  in
  let m, _, _ = mesh_of text in
  Alcotest.(check int) "mesh {}: one face" 1 m.faces;
  Alcotest.(check (list string)) "mesh {}: no warning" [] (List.map (fun (e : Error.t) -> e.msg) (warnings text))

let test_flat_from_equal_normals () =
  let up = v 0. 0. 1. in
  (* three equal normals <0,0,1>: the face is flat and uses its geometric normal <0,0,-1> *)
  let m = build [ p1; p2; p3 ] [| 0; 1; 2 |] ~normals:[ up; up; up ] ~fn:[| 0; 1; 2 |] in
  Alcotest.(check int32) "no normal index" (-1l) m.fidx.{3};
  vec_eq "face normal, not the vertex normal" (v 0. 0. (-1.)) (Mesh.normal m 0 (v 0. 0. 2.));
  vec_eq "same at a vertex" (v 0. 0. (-1.)) (Mesh.normal m 0 p1);
  (* nearly equal: <0,5e-6,1> normalised differs from <0,0,1> by |.|² ≈ 2.5e-11 ≤ 1e-10: flat *)
  let near = f32v (Vec.normalize (v 0. 5e-6 1.)) in
  let m = build [ p1; p2; p3 ] [| 0; 1; 2 |] ~normals:[ up; near; up ] ~fn:[| 0; 1; 2 |] in
  Alcotest.(check int32) "nearly equal: flat" (-1l) m.fidx.{3};
  (* <0,2e-5,1>: |.|² ≈ 4e-10 > 1e-10: smooth, and at P2 the normal is that vertex normal *)
  let off = f32v (Vec.normalize (v 0. 2e-5 1.)) in
  let m = build [ p1; p2; p3 ] [| 0; 1; 2 |] ~normals:[ up; off; up ] ~fn:[| 0; 1; 2 |] in
  Alcotest.(check bool) "different: smooth" true (m.fidx.{3} >= 0l);
  vec_eq ~eps:1e-7 "smooth at P2" off (Mesh.normal m 0 p2);
  (* flat faces (no normal indices at all) use the face normal *)
  let m = build [ p1; p2; p3 ] [| 0; 1; 2 |] in
  vec_eq "flat mesh" (v 0. 0. (-1.)) (Mesh.normal m 0 (v 0. 0. 2.))

let test_smooth_normal () =
  let n1 = f32v (v (1. /. s2) 0. (1. /. s2)) and n2 = f32v (v 0. (1. /. s2) (1. /. s2)) and n3 = v 0. 0. 1. in
  (* normals as written order, and with the corners written clockwise (swapped at set-up) *)
  List.iter
    (fun (name, fv) ->
      let m = build [ p1; p2; p3 ] fv ~normals:[ n1; n2; n3 ] ~fn:fv in
      vec_eq ~eps:1e-7 (name ^ ": at P1") n1 (Mesh.normal m 0 p1);
      vec_eq ~eps:1e-7 (name ^ ": at P2") n2 (Mesh.normal m 0 p2);
      vec_eq ~eps:1e-7 (name ^ ": at P3") n3 (Mesh.normal m 0 p3);
      (* the centroid: normalize(n1 + n2 + n3) = <1/√2, 1/√2, 1 + √2>/√(4 + 2√2) *)
      let k = sqrt (4. +. (2. *. s2)) in
      vec_eq ~eps:1e-7 (name ^ ": at the centroid")
        (v (1. /. s2 /. k) (1. /. s2 /. k) ((1. +. s2) /. k))
        (Mesh.normal m 0 (v 0. (-1. /. 3.) 2.)))
    [ ("counter-clockwise", [| 0; 1; 2 |]); ("clockwise", [| 0; 2; 1 |]) ]

(* ---- intersection ---- *)

(* Two parallel faces around the z axis, the far one (z = 3) listed first, the near one (z = 1)
   second: corners <-2,-2,z>, <2,-2,z>, <0,2,z>. *)
let two_faces () =
  let tri z = [ v (-2.) (-2.) z; v 2. (-2.) z; v 0. 2. z ] in
  build (tri 3. @ tri 1.) [| 0; 1; 2; 3; 4; 5 |]

let test_nearest () =
  let m = two_faces () and hit = [| 0. |] in
  let nearest o d lo = Mesh.nearest m (stack ()) o d lo hit in
  Alcotest.(check int) "from the origin: the z = 1 face" 1 (nearest (v 0. 0. 0.) plus_z 0.);
  float_eq "at depth 1" 1. hit.(0);
  Alcotest.(check int) "lo = 1 keeps depth 1" 1 (nearest (v 0. 0. 0.) plus_z 1.);
  float_eq "at depth 1 (lo = 1)" 1. hit.(0);
  Alcotest.(check int) "lo = 1.5: the z = 3 face" 0 (nearest (v 0. 0. 0.) plus_z 1.5);
  float_eq "at depth 3" 3. hit.(0);
  Alcotest.(check int) "from z = 2 up" 0 (nearest (v 0. 0. 2.) plus_z 0.);
  float_eq "at depth 1 (up)" 1. hit.(0);
  Alcotest.(check int) "from z = 2 down" 1 (nearest (v 0. 0. 2.) (v 0. 0. (-1.)) 0.);
  float_eq "at depth 1 (down)" 1. hit.(0);
  (* oblique: towards <0.5,0.5,1> from the origin: |<0.5,0.5,1>| = √1.5 *)
  Alcotest.(check int) "oblique" 1 (nearest (v 0. 0. 0.) (Vec.normalize (v 0.5 0.5 1.)) 0.);
  float_eq "oblique depth" (sqrt 1.5) hit.(0);
  Alcotest.(check int) "beside the faces" (-1) (nearest (v 10. 10. 0.) plus_z 0.);
  Alcotest.(check int) "away from the faces" (-1) (nearest (v 0. 0. 0.) (v 0. 0. (-1.)) 0.);
  Alcotest.(check int) "past both" (-1) (nearest (v 0. 0. 0.) plus_z 3.5)

let test_any_hit () =
  let m = two_faces () in
  let any lo hi = Mesh.any_hit m (stack ()) (v 0. 0. 0.) plus_z lo hi in
  (* hits at 1 and 3; the interval is [lo, hi) *)
  Alcotest.(check bool) "[0, 1): 1 excluded" false (any 0. 1.);
  Alcotest.(check bool) "[0, 1.0001)" true (any 0. 1.0001);
  Alcotest.(check bool) "[1, 2): 1 included" true (any 1. 2.);
  Alcotest.(check bool) "[1.5, 3)" false (any 1.5 3.);
  Alcotest.(check bool) "[1.5, 3.5)" true (any 1.5 3.5);
  Alcotest.(check bool) "[3, 4)" true (any 3. 4.);
  Alcotest.(check bool) "[3.0001, 100)" false (any 3.0001 100.);
  Alcotest.(check bool) "miss" false (Mesh.any_hit m (stack ()) (v 10. 10. 0.) plus_z 0. 100.)

let test_bounds () =
  (* the faces span <-2,-2,1> … <2,2,3>; the box is rounded outwards to floats *)
  let b = Mesh.bounds (two_faces ()) in
  Array.iteri (fun i e -> float_eq ~eps:1e-6 (Printf.sprintf "bounds.(%d)" i) e b.(i)) [| -2.; -2.; 1.; 2.; 2.; 3. |];
  Alcotest.(check bool) "min ≤ -2" true (b.(0) <= -2.);
  Alcotest.(check bool) "max ≥ 3" true (b.(5) >= 3.)

(* ---- inside ---- *)

(* The octahedron |x| + |y| + |z| = 1: vertices ±x, ±y, ±z, one face per octant. *)
let octahedron_vertices = [ v 1. 0. 0.; v (-1.) 0. 0.; v 0. 1. 0.; v 0. (-1.) 0.; v 0. 0. 1.; v 0. 0. (-1.) ]

let octahedron_faces =
  Array.concat (List.concat_map (fun a -> List.concat_map (fun b -> List.map (fun c -> [| a; b; c |]) [ 4; 5 ]) [ 2; 3 ]) [ 0; 1 ])

let test_inside () =
  (* inside_vector <0.3,0.2,1>: general enough to miss every edge and vertex *)
  let m = build octahedron_vertices octahedron_faces ~inside:(v 0.3 0.2 1.) in
  Alcotest.(check int) "eight faces" 8 m.faces;
  let inside p = Mesh.inside m (stack ()) p in
  (* from the centre, P(s) = s<0.3,0.2,1> stays in the +++ octant and meets x + y + z = 1 once at
     s = 1/1.5 (<0.2,0.133,0.667>): one crossing, odd → inside *)
  Alcotest.(check bool) "centre" true (inside (v 0. 0. 0.));
  Alcotest.(check bool) "off centre" true (inside (v 0.1 (-0.2) 0.1));
  (* from <5,5,5> every face plane is behind: 0 crossings *)
  Alcotest.(check bool) "far point" false (inside (v 5. 5. 5.));
  (* from <0,0,-1.5>: |0.3s| + |0.2s| + |s − 1.5| < 1 for 1 < s < 5/3: two crossings, even → outside *)
  Alcotest.(check bool) "below, crossing twice" false (inside (v 0. 0. (-1.5)));
  (* the inside vector is stored normalised *)
  (match m.inside_vector with
  | Some iv -> vec_eq "inside vector" (Vec.normalize (v 0.3 0.2 1.)) iv
  | None -> Alcotest.fail "expected an inside vector");
  (* §2.6: hits on shared edges are not deduplicated. Along <0,0,1> from the centre the ray meets
     the vertex <0,0,1>, a corner of the four upper faces; a point on an edge or corner counts as
     inside each triangle, so there are 4 crossings, even: "outside" (as POV-Ray has it) *)
  let m_z = build octahedron_vertices octahedron_faces ~inside:(v 0. 0. 1.) in
  Alcotest.(check bool) "through a vertex: 4 hits, outside" false (Mesh.inside m_z (stack ()) (v 0. 0. 0.));
  (* without an inside vector a mesh has no inside *)
  let m = build octahedron_vertices octahedron_faces in
  Alcotest.(check bool) "no inside_vector: centre" false (Mesh.inside m (stack ()) (v 0. 0. 0.));
  Alcotest.(check bool) "no inside_vector: far" false (Mesh.inside m (stack ()) (v 5. 5. 5.))

let octahedron_mesh2 =
  "mesh2 { vertex_vectors { 6, <1,0,0>, <-1,0,0>, <0,1,0>, <0,-1,0>, <0,0,1>, <0,0,-1> }\n\
  \  face_indices { 8, <0,2,4>, <0,2,5>, <0,3,4>, <0,3,5>, <1,2,4>, <1,2,5>, <1,3,4>, <1,3,5> }\n\
  \  inside_vector <0.3,0.2,1> translate <5,0,0> }"

let test_inside_scene () =
  (* through the scene: the moved octahedron is centred at <5,0,0> *)
  let c = Compile.scene (scene octahedron_mesh2) in
  let shape = c.objects.(0).shape in
  Alcotest.(check bool) "moved centre" true (Shape.inside (stack ()) shape (v 5. 0. 0.));
  Alcotest.(check bool) "old centre" false (Shape.inside (stack ()) shape (v 0. 0. 0.));
  Alcotest.(check bool) "below the moved one" false (Shape.inside (stack ()) shape (v 5. 0. (-1.5)))

(* ---- textures ---- *)

let pigment_of_texture (t : Scene.texture) = match t with Layers (l :: _) -> l.pigment | _ -> Alcotest.fail "not a plain texture"
let red_of (t : Scene.texture) = match pigment_of_texture t with Solid c | Solid_placed { colour = c; _ } -> c.red | Pattern _ -> nan
let green_of (t : Scene.texture) = match pigment_of_texture t with Solid c | Solid_placed { colour = c; _ } -> c.green | Pattern _ -> nan

let test_textures () =
  let m, _, textures =
    mesh_of
      "mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }\n\
      \  texture_list { 2, texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,1,0> } } }\n\
      \  face_indices { 3, <0,1,2>, 1, <1,3,2>, <0,1,3>, 0 } }"
  in
  Alcotest.(check int) "two textures" 2 (Array.length textures);
  float_eq "texture 0 is red" 1. (red_of textures.(0));
  float_eq "texture 1 is green" 1. (green_of textures.(1));
  Alcotest.(check int) "face 0: texture 1" 1 (Mesh.texture m 0);
  Alcotest.(check int) "face 1: none" (-1) (Mesh.texture m 1);
  Alcotest.(check int) "face 2: texture 0" 0 (Mesh.texture m 2);
  (* a face written as a vector expression that starts with a vector identifier is the next face,
     not a texture index (POV-Ray's CASE_FLOAT; shapes.inc's HF macros write F1+A, F2+A); a float
     identifier is an index *)
  let m, _, _ =
    mesh_of
      "#declare F1 = <0,1,2>; #declare F2 = <1,3,2>; #declare A = 0; #declare T = 1;\n\
      \  mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }\n\
      \  texture_list { 2, texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,1,0> } } }\n\
      \  face_indices { 3, F1+A, F2+A, T, <0,1,3> } }"
  in
  Alcotest.(check int) "three faces" 3 m.faces;
  Alcotest.(check (list int)) "textures: none, T, none" [ -1; 1; -1 ] [ Mesh.texture m 0; Mesh.texture m 1; Mesh.texture m 2 ];
  (* without a texture_list every face uses the mesh's own *)
  let m, _, textures = mesh_of "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }" in
  Alcotest.(check int) "no list" 0 (Array.length textures);
  Alcotest.(check int) "no list: face 0" (-1) (Mesh.texture m 0);
  (* mesh {}: per-triangle textures are numbered in the order they appear *)
  let m, _, textures =
    mesh_of
      "#declare R = texture { pigment { rgb <1,0,0> } }\n\
       #declare G = texture { pigment { rgb <0,1,0> } }\n\
       mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> texture { G } }\n\
      \  triangle { <0,0,1>, <1,0,1>, <0,1,1> }\n\
      \  triangle { <0,0,2>, <1,0,2>, <0,1,2> texture { R } } }"
  in
  Alcotest.(check int) "mesh {}: two textures" 2 (Array.length textures);
  Alcotest.(check int) "mesh {}: face 0" 0 (Mesh.texture m 0);
  Alcotest.(check int) "mesh {}: face 1" (-1) (Mesh.texture m 1);
  Alcotest.(check int) "mesh {}: face 2" 1 (Mesh.texture m 2);
  float_eq "mesh {}: first is G" 1. (green_of textures.(0));
  float_eq "mesh {}: second is R" 1. (red_of textures.(1))

let test_translate () =
  (* translate moves the instance, not the shared data: translations compose *)
  let m, offset, _ =
    mesh_of "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } translate <1,2,3> translate <0,0,1> }"
  in
  vec_eq "offset" (v 1. 2. 4.) offset;
  float_eq "vertex unchanged" 1. m.vertices.{3}

let tests =
  [
    Alcotest.test_case "single precision" `Quick test_single_precision;
    Alcotest.test_case "degenerate faces dropped" `Quick test_degenerate_dropped;
    Alcotest.test_case "equal normals make a flat face" `Quick test_flat_from_equal_normals;
    Alcotest.test_case "smooth normal" `Quick test_smooth_normal;
    Alcotest.test_case "nearest" `Quick test_nearest;
    Alcotest.test_case "any_hit" `Quick test_any_hit;
    Alcotest.test_case "bounds" `Quick test_bounds;
    Alcotest.test_case "inside" `Quick test_inside;
    Alcotest.test_case "inside through a scene" `Quick test_inside_scene;
    Alcotest.test_case "texture indices" `Quick test_textures;
    Alcotest.test_case "translate" `Quick test_translate;
  ]


(* ---- tracing meshes (§2.6 with §3) ---- *)

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
let origin = v 0. 0. 0.

let test_trace_flat () =
  let tri = "mesh { triangle { <-1,-1,2>, <1,-1,2>, <0,1,2> } pigment { rgb <1,0.5,0.25> } finish { ambient 0 diffuse 0.8 } }\n" in
  (* hit at <0,0,2>, N = <0,0,-1>, light at the origin: L = <0,0,-1>, N·L = 1;
     C·lc·(N·L)·diffuse = <1,0.5,0.25>·0.8 = <0.8,0.4,0.2> *)
  result_eq "head-on" (0.8, 0.4, 0.2) (trace_text (v37 ^ tri ^ "light_source { <0,0,0> color rgb 1 }") origin plus_z);
  (* light at <2,0,0>: L = (<2,0,0> − <0,0,2>)/√8 = <1,0,-1>/√2, N·L = 1/√2:
     <0.8,0.4,0.2>/√2 *)
  let k = 1. /. s2 in
  result_eq "at 45°" (0.8 *. k, 0.4 *. k, 0.2 *. k) (trace_text (v37 ^ tri ^ "light_source { <2,0,0> color rgb 1 }") origin plus_z);
  (* beside the triangle: the background *)
  result_eq "miss" (0.1, 0.2, 0.3)
    (trace_text (v37 ^ tri ^ "background { rgb <0.1,0.2,0.3> } light_source { <0,0,0> color rgb 1 }") (v 3. 0. 0.) plus_z)

let test_trace_smooth () =
  (* normals <0,0,-1>, <0,0,-1>, <0,1,-1>/√2; the hit <0,0,2> has weights 1/4, 1/4, 1/2
     (−w1 + w2 = 0, −w1 − w2 + w3 = 0); N ∝ <0,0,-1>/2 + <0,1,-1>/(2√2) = <0, 0.35355, −0.85355>,
     i.e. <0, sin 22.5°, −cos 22.5°>; light at the origin, L = <0,0,-1>: N·L = cos 22.5° *)
  let text =
    v37
    ^ "mesh { smooth_triangle { <-1,-1,2>, <0,0,-1>, <1,-1,2>, <0,0,-1>, <0,1,2>, <0,1,-1> }\n\
      \  pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
       light_source { <0,0,0> color rgb 1 }"
  in
  let c = cos (Float.pi /. 8.) in
  result_eq "smooth" (c, c, c) (trace_text text origin plus_z)

let test_trace_moved () =
  let text =
    v37
    ^ "#declare M = mesh { triangle { <-1,-1,2>, <1,-1,2>, <0,1,2> } pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
       object { M translate <1,0,0> }\n\
       background { rgb <0.1,0.2,0.3> }\n\
       light_source { <0,0,0> color rgb 1 fade_distance 1 fade_power 2 }"
  in
  let c = compile text in
  (* towards H = <1.2,-0.3,2>: in the moved triangle (at y = −0.3 the unmoved one spans
     x ∈ [−0.65, 0.65], the moved one [0.35, 1.65]); d = |H| = √5.53, N·L = 2/√5.53,
     attenuation 2/(1 + d²) = 2/6.53 *)
  let d = sqrt 5.53 in
  let e = 2. /. d *. (2. /. 6.53) in
  result_eq "moved: hit where expected" (e, e, e) (trace_ray c origin (v 1.2 (-0.3) 2.));
  (* straight up from the origin: <0,0,2> is outside the moved triangle (left of its edge
     <0,-1>–<1,1>, x = 0.5 at y = 0) *)
  result_eq "moved: the old place is empty" (0.1, 0.2, 0.3) (trace_ray c origin plus_z);
  (* from <1,0,0> straight up: H = <1,0,2> (the moved centre line), |H| = √5, N·L = 2/√5,
     attenuation 2/(1 + 5) *)
  let e = 2. /. sqrt 5. *. (2. /. 6.) in
  result_eq "moved: from <1,0,0>" (e, e, e) (trace_ray c (v 1. 0. 0.) plus_z)

let test_trace_textures () =
  (* three triangles centred on x = 0, 3, 6 in z = 2; face 0 uses texture 1 (green), face 1 the
     mesh's own (blue), face 2 texture 0 (red); ambient 1, no diffuse: the pigment is the colour *)
  let text =
    v37
    ^ "mesh2 { vertex_vectors { 9, <-1,-1,2>, <1,-1,2>, <0,1,2>, <2,-1,2>, <4,-1,2>, <3,1,2>, <5,-1,2>, <7,-1,2>, <6,1,2> }\n\
      \  texture_list { 2, texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }\n\
      \                    texture { pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } } }\n\
      \  face_indices { 3, <0,1,2>, 1, <3,4,5>, <6,7,8>, 0 }\n\
      \  pigment { rgb <0,0,1> } finish { ambient 1 diffuse 0 } }"
  in
  let c = compile text in
  result_eq "face 0: texture 1" (0., 1., 0.) (trace_ray c (v 0. 0. 0.) plus_z);
  result_eq "face 1: the mesh's own" (0., 0., 1.) (trace_ray c (v 3. 0. 0.) plus_z);
  result_eq "face 2: texture 0" (1., 0., 0.) (trace_ray c (v 6. 0. 0.) plus_z);
  (* mesh {}: a triangle's texture { T } *)
  let text =
    v37
    ^ "#declare T = texture { pigment { rgb <1,0.5,0> } finish { ambient 1 diffuse 0 } }\n\
       mesh { triangle { <-1,-1,2>, <1,-1,2>, <0,1,2> texture { T } } triangle { <2,-1,2>, <4,-1,2>, <3,1,2> }\n\
      \  pigment { rgb <0,0.25,1> } finish { ambient 1 diffuse 0 } }"
  in
  let c = compile text in
  result_eq "mesh {}: T" (1., 0.5, 0.) (trace_ray c (v 0. 0. 0.) plus_z);
  result_eq "mesh {}: own" (0., 0.25, 1.) (trace_ray c (v 3. 0. 0.) plus_z);
  (* the nearer of two overlapping faces is seen, whatever their order: the far (red, z = 3) one is
     listed first *)
  let text =
    v37
    ^ "mesh2 { vertex_vectors { 6, <-1,-1,3>, <1,-1,3>, <0,1,3>, <-1,-1,2>, <1,-1,2>, <0,1,2> }\n\
      \  texture_list { 2, texture { pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } }\n\
      \                    texture { pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } } }\n\
      \  face_indices { 2, <0,1,2>, 0, <3,4,5>, 1 } }"
  in
  result_eq "nearer face" (0., 1., 0.) (trace_text text origin plus_z)

let trace_tests =
  [
    Alcotest.test_case "trace: flat mesh triangle" `Quick test_trace_flat;
    Alcotest.test_case "trace: smooth mesh triangle" `Quick test_trace_smooth;
    Alcotest.test_case "trace: moved mesh" `Quick test_trace_moved;
    Alcotest.test_case "trace: per-face textures" `Quick test_trace_textures;
  ]
