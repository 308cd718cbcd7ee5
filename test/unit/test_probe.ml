(* trace(), inside(), min_extent() and max_extent() at parse time, against the values POV-Ray
   3.7.0.10 printed for the same calls with #debug vstr(3, V, ",", 0, 16) (the scene's objects are
   in [decls]); each result is read back as the centre of a sphere. *)

open Helpers

let decls =
  "#version 3.7;\n\
   #declare S = sphere { <0,1,0>, 1 };\n\
   #declare U = union { box { -1, 1 } sphere { <0,2,0>, 0.5 } rotate 20*y translate x };\n\
   #declare D = difference { box { -1, 1 } sphere { <0,0,-1>, 0.8 } };\n\
   #declare C = cylinder { 0, y, 1 rotate 30*z };\n\
   #declare Pl = plane { y, 0 };\n\
   #declare T = text { ttf \"timrom.ttf\" \"o\" 0.2, 0 };\n\
   #declare H = union { sphere { 0, 1 } sphere { <2,0,0>, 1 } rotate 45*z };\n\
   #declare H2 = union { object { H } box { 0, 0.5 } rotate 30*y translate 1 };\n\
   #declare N = <7,7,7>;\n"

(* the centres of the spheres [body] makes, in order; POV-Ray's 16 printed decimals are within
   1e-15 of the value, far below a single-precision step *)
let centres body =
  List.map (fun (o : Scene.obj) -> fst (sphere_of o)) (scene (decls ^ body)).objects

let one body = match centres body with [ c ] -> c | _ -> Alcotest.fail "expected one sphere"

let trace_hits () =
  vec_eq ~eps:0. "sphere hit" (v 0. 1. (-1.)) (one "sphere { trace(S, <0,1,-5>, z, N), 1 }");
  vec_eq ~eps:0. "sphere normal" (v 0. 0. (-1.)) (one "#declare P = trace(S, <0,1,-5>, z, N); sphere { N, 1 }");
  (* the hole of a difference: the inverted sphere's normal is negated *)
  vec_eq ~eps:1e-15 "difference hit" (v 0.1 0.2 (-0.2318854252131395)) (one "sphere { trace(D, <0.1,0.2,-5>, z, N), 1 }");
  vec_eq ~eps:1e-15 "difference normal" (v (-0.125) (-0.25) (-0.9601432184835756))
    (one "#declare P = trace(D, <0.1,0.2,-5>, z, N); sphere { N, 1 }")

let trace_misses () =
  vec_eq ~eps:0. "a miss is the origin" Vec.zero (one "sphere { trace(D, <3,0.2,-5>, z, N), 1 }");
  vec_eq ~eps:0. "a miss zeroes the normal" Vec.zero (one "#declare P = trace(U, <0.3,2.2,-5>, <0.01,-0.02,1>, N); sphere { N, 1 }")

let inside_points () =
  let flags = centres "sphere { <inside(S, <0,1.5,0>), inside(S, <0,2.5,0>), inside(D, <0,0,-0.9>)>, 1 } sphere { inside(D, <0,0,0.9>), 1 }" in
  match flags with
  | [ a; b ] ->
      vec_eq ~eps:0. "inside S, outside S, in the hole" (v 1. 0. 0.) a;
      vec_eq ~eps:0. "inside D" (v 1. 1. 1.) b
  | _ -> Alcotest.fail "two spheres"

let extents () =
  vec_eq ~eps:1e-15 "union min" (v (-0.2817127704620361) (-1.) (-1.2817127704620361)) (one "sphere { min_extent(U), 1 }");
  vec_eq ~eps:1e-15 "union max" (v 2.2817127704620361 2.5 1.2817127704620361) (one "sphere { max_extent(U), 1 }");
  vec_eq ~eps:1e-15 "sphere min" (v (-1.) 0. (-1.)) (one "sphere { min_extent(S), 1 }");
  vec_eq ~eps:1e-15 "difference max" (v 1. 1. 1.) (one "sphere { max_extent(D), 1 }");
  vec_eq ~eps:1e-15 "rotated cylinder min" (v (-1.3660254478454590) (-0.5) (-1.)) (one "sphere { min_extent(C), 1 }");
  vec_eq ~eps:1e-15 "rotated cylinder max" (v 0.8660254478454590 1.3660254478454590 1.) (one "sphere { max_extent(C), 1 }");
  vec_eq ~eps:1e-15 "plane: the huge box" (v (-1e10) (-1e10) (-1e10)) (one "sphere { min_extent(Pl), 1 }");
  vec_eq ~eps:1e-15 "text min" (v (-0.0000081839489212) (-0.0100034903734922) (-0.0000088888882601)) (one "sphere { min_extent(T), 1 }");
  vec_eq ~eps:1e-15 "text max" (v 0.4420036673545837 0.4690077304840088 0.2000091820955276) (one "sphere { max_extent(T), 1 }");
  (* a union's box is made when it is built and mapped by each later transform, not remade *)
  vec_eq ~eps:1e-15 "rotated union min" (v (-1.4142135381698608) (-1.4142135381698608) (-1.)) (one "sphere { min_extent(H), 1 }");
  vec_eq ~eps:1e-15 "rotated union max" (v 2.8284268379211426 2.8284268379211426 1.) (one "sphere { max_extent(H), 1 }");
  vec_eq ~eps:1e-15 "union of a rotated union, rotated: min" (v (-0.7247447967529297) (-0.4142135381698608) (-1.2802388668060303))
    (one "sphere { min_extent(H2), 1 }");
  vec_eq ~eps:1e-15 "union of a rotated union, rotated: max" (v 3.9494895935058594 3.8284268379211426 2.5731322765350342)
    (one "sphere { max_extent(H2), 1 }")

let errors () =
  expect_scene_error "trace needs an object" (decls ^ "#declare P = trace(N, x, y);") ~line:11 ~col:20 ~sub:"Object identifier expected";
  expect_scene_error "inside needs a solid" (decls ^ "#declare Tr = triangle { 0, x, y }\n#declare P = inside(Tr, x);") ~line:12 ~col:21
    ~sub:"Solid object identifier expected";
  expect_scene_error "the normal goes to a vector" (decls ^ "#declare P = trace(S, x, y, Q);") ~line:11 ~col:29 ~sub:"declared vector identifier"

let tests =
  [
    Alcotest.test_case "trace: hits and normals" `Quick trace_hits;
    Alcotest.test_case "trace: misses" `Quick trace_misses;
    Alcotest.test_case "inside" `Quick inside_points;
    Alcotest.test_case "min_extent and max_extent" `Quick extents;
    Alcotest.test_case "errors" `Quick errors;
  ]
