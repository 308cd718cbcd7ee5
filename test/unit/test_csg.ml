(* CSG (docs/povray-rules.md §16): parsing (difference, inverse and the De Morgan morph, split_union, members'
   textures and interiors), every crossing of each primitive (all-hits), the Inside test of each
   shape and each CSG kind, which hits each kind keeps, the nearest hit and its leaf, coincident
   boundaries, bounding boxes, shading of the primitive hit and the shared interior. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let members_of (o : Scene.obj) =
  match o.shape with
  | Csg { kind; members; _ } -> (kind, members)
  | _ -> Alcotest.fail "expected a CSG"

let kind_name : Scene.csg_kind -> string = function
  | Union -> "union" | Merge -> "merge" | Intersection -> "intersection" | Clipped -> "clipped" | Bounded -> "bounded" | Boxed -> "boxed"
let check_kind msg e a = Alcotest.(check string) msg (kind_name e) (kind_name a)
let inverted_flags ms = List.map (fun (m : Scene.member) -> m.inverted) ms

(* ---------------------------------------------------------------------------------------------- *)
(* Parsing *)

let test_parse_kinds () =
  let kind, ms = members_of (the_object (scene "merge { sphere { 0, 1 } sphere { x, 1 } }")) in
  check_kind "merge" Merge kind;
  Alcotest.(check (list bool)) "merge: nothing inverted" [ false; false ] (inverted_flags ms);
  (* §16.1: difference {A B C} is intersection {A, inverse B, inverse C} *)
  let kind, ms = members_of (the_object (scene "difference { box { -1, 1 } sphere { 0, 1 } sphere { x, 1 } }")) in
  check_kind "difference" Intersection kind;
  Alcotest.(check (list bool)) "difference: members 2… inverted" [ false; true; true ] (inverted_flags ms);
  (* a union is dissolved by default (§16.4) … *)
  let s = scene "union { sphere { 0, 1 } sphere { x, 1 } }" in
  Alcotest.(check int) "split union: two objects" 2 (List.length s.objects);
  (* … and kept whole with split_union off *)
  let kind, ms = members_of (the_object (scene "union { sphere { 0, 1 } sphere { x, 1 } split_union off }")) in
  check_kind "kept union" Union kind;
  Alcotest.(check int) "kept union: two members" 2 (List.length ms);
  (* an intersection nested in a dissolved union is a top-level object of its own *)
  let s = scene "union { intersection { sphere { 0, 1 } sphere { x, 1 } } sphere { 5*x, 1 } }" in
  Alcotest.(check int) "nested in a split union" 2 (List.length s.objects)

let test_parse_inverse () =
  (* §16.3: an inverted union is an intersection of inverted members … *)
  let kind, ms = members_of (the_object (scene "union { sphere { 0, 1 } sphere { x, 1 } inverse }")) in
  check_kind "inverse union" Intersection kind;
  Alcotest.(check (list bool)) "inverse union: members inverted" [ true; true ] (inverted_flags ms);
  (* … an inverted intersection a merge, and a difference inverted twice gives back its member *)
  let kind, ms = members_of (the_object (scene "difference { sphere { 0, 1 } sphere { x, 1 } inverse }")) in
  check_kind "inverse difference" Merge kind;
  Alcotest.(check (list bool)) "inverse difference" [ true; false ] (inverted_flags ms);
  (* a plane turns over instead of being flagged *)
  let _, ms = members_of (the_object (scene "intersection { plane { y, 1 inverse } sphere { 0, 1 } }")) in
  (match ms with
  | { mobj = { shape = Plane { normal; offset; _ }; _ }; inverted; _ } :: _ ->
      vec_eq "plane normal negated" (v 0. (-1.) 0.) normal;
      float_eq "plane offset negated" (-1.) offset;
      Alcotest.(check bool) "plane not flagged" false inverted
  | _ -> Alcotest.fail "expected a plane first");
  (* an inverted sphere at top level enters as an intersection of itself alone *)
  let kind, ms = members_of (the_object (scene "sphere { 0, 1 inverse }")) in
  check_kind "top-level inverse" Intersection kind;
  Alcotest.(check (list bool)) "top-level inverse: flagged" [ true ] (inverted_flags ms);
  (* inverse twice is the sphere itself *)
  ignore (sphere_of (the_object (scene "sphere { 0, 1 inverse inverse }")))

let test_parse_textures_interiors () =
  let o =
    the_object
      (scene
         "intersection { sphere { 0, 1 pigment { rgb x } } sphere { x, 1 } box { -1, 1 interior { ior 2 } } \
          pigment { rgb y } interior { ior 1.5 } }")
  in
  let _, ms = members_of o in
  let reds = List.map (fun (m : Scene.member) -> (pigment_of m.mobj).red) ms in
  Alcotest.(check (list (float 0.))) "own pigment kept, others the CSG's (§16.5)" [ 1.; 0.; 0. ] reds;
  Alcotest.(check (list bool)) "own interiors" [ false; false; true ] (List.map (fun (m : Scene.member) -> m.own_interior) ms);
  Alcotest.(check (list (float 0.))) "interiors: shared 1.5, own 2" [ 1.5; 1.5; 2. ] (List.map (fun (m : Scene.member) -> m.mobj.interior.ior) ms);
  float_eq "the CSG's interior" 1.5 o.interior.ior

let test_parse_lights_and_transforms () =
  (* §19.1: a light in a CSG is a global light moved by the CSG's transforms; the members move too *)
  let s = scene "intersection { box { -1, 1 } light_source { <0, 5, 0>, 1 } sphere { 0, 1.2 } translate <2, 0, 0> }" in
  (match s.lights with [ l ] -> vec_eq "light moved" (v 2. 5. 0.) l.position | _ -> Alcotest.fail "expected one light");
  let _, ms = members_of (the_object s) in
  (match ms with
  | [ { mobj = { shape = Box { lo; hi; _ }; _ }; _ }; { mobj = { shape = Sphere { centre; _ }; _ }; _ } ] ->
      vec_eq "box moved lo" (v 1. (-1.) (-1.)) lo;
      vec_eq "box moved hi" (v 3. 1. 1.) hi;
      vec_eq "sphere moved" (v 2. 0. 0.) centre
  | _ -> Alcotest.fail "expected a box and a sphere");
  (* §16.4: a kept union whose members all have no_shadow has it too; one that has not, not *)
  let o = the_object (scene "union { sphere { 0, 1 no_shadow } sphere { x, 1 no_shadow } split_union off }") in
  Alcotest.(check bool) "all no_shadow" true o.no_shadow;
  let o = the_object (scene "union { sphere { 0, 1 no_shadow } sphere { x, 1 } split_union off }") in
  Alcotest.(check bool) "one no_shadow" false o.no_shadow

let test_parse_warnings () =
  let w = warnings "difference { sphere { 0, 1 } }" in
  Alcotest.(check bool) "fewer than two members: a warning" true
    (List.exists (fun (e : Error.t) -> contains ~sub:"at least two members" e.msg) w);
  let kind, _ = members_of (the_object (scene "merge { sphere { 0, 1 } sphere { x, 1 } split_union on }")) in
  check_kind "split_union on a merge: accepted, still a merge" Merge kind;
  expect_scene_error "split_union on an intersection" "intersection { sphere { 0, 1 } sphere { x, 1 }\n split_union off }" ~line:2
    ~col:2 ~sub:"split_union found in a non-union object";
  expect_scene_error "a non-object in a CSG" "difference { sphere { 0, 1 } 42 }" ~line:1 ~col:30 ~sub:"expected"

let test_parse_clipped_by () =
  (* clipped_by makes a Clipped node: the object first, then the clip objects; the texture stays on
     the node (a later pigment reaches the object), later transforms move the clip objects too *)
  let o = the_object (scene "sphere { 0, 1 clipped_by { plane { y, 0 } box { -1, 1 } } pigment { rgb x } translate y }") in
  let kind, ms = members_of o in
  check_kind "clipped" Clipped kind;
  Alcotest.(check int) "object and two clip objects" 3 (List.length ms);
  float_eq "the node's pigment" 1. (pigment_of o).red;
  (match ms with
  | [ s; { mobj = { shape = Plane { offset; _ }; _ }; _ }; _ ] ->
      float_eq "the object takes the node's pigment" 1. (pigment_of s.mobj).red;
      float_eq "the clip plane moved by the later translate" 1. offset
  | _ -> Alcotest.fail "expected sphere, plane, box");
  (* a second clipped_by adds clip objects *)
  let _, ms = members_of (the_object (scene "sphere { 0, 1 clipped_by { plane { y, 0 } } clipped_by { box { -1, 1 } } }")) in
  Alcotest.(check int) "two clipped_by" 3 (List.length ms);
  (* a union with clipped_by is kept whole (§16.4) *)
  let kind, _ = members_of (the_object (scene "union { sphere { 0, 1 } sphere { x, 1 } clipped_by { plane { y, 0 } } }")) in
  check_kind "clipped union kept" Clipped kind;
  (* inverse inverts the object, not its clip objects *)
  let _, ms = members_of (the_object (scene "sphere { 0, 1 clipped_by { plane { y, 0 } } inverse }")) in
  (match ms with
  | [ s; { mobj = { shape = Plane { normal; _ }; _ }; inverted; _ } ] ->
      Alcotest.(check bool) "the sphere inverted" true s.inverted;
      Alcotest.(check bool) "the plane not" false inverted;
      vec_eq "the plane not turned over" (v 0. 1. 0.) normal
  | _ -> Alcotest.fail "expected sphere, plane");
  expect_scene_error "empty clipped_by" "sphere { 0, 1 clipped_by { } }" ~line:1 ~col:28 ~sub:"expected an object in clipped_by";
  expect_scene_error "clipped_by { bounded_by } after clips" "sphere { 0, 1 clipped_by { box { 0, 1 } } clipped_by { bounded_by } }" ~line:1 ~col:56
    ~sub:"Cannot link bounds with previous clips"

(* ---------------------------------------------------------------------------------------------- *)
(* All hits of each primitive *)

let setup text =
  let c = compile (v37 ^ text) in
  (c, Trace.make_ctx c (Stats.create ()))

(* The hits of object [i] along the ray: (depth, sub, leaf id) each. *)
let hits ?(i = 0) ?(lo = 1e-4) (c, ctx) o d =
  let n = Shape.all_hits ctx.Context.shapes (Compile.member c.Compiled.objects.(i)) o (Vec.normalize d) lo 0 in
  List.init n (fun j ->
      let h = ctx.Context.shapes.hits.room and b = j * Scratch.hit_width in
      (h.(b), int_of_float h.(b + 1), int_of_float h.(b + 2)))

let depths l = List.map (fun (t, _, _) -> t) l
let check_depths msg e a = Alcotest.(check (list (float 1e-12))) msg e (depths a)

let test_all_hits_sphere () =
  let s = setup "sphere { 0, 1 }" in
  check_depths "through: both roots" [ 4.; 6. ] (hits s (v 0. 0. (-5.)) (v 0. 0. 1.));
  check_depths "from the centre: only the far root" [ 1. ] (hits s Vec.zero (v 0. 0. 1.));
  (* tangent: h² = r² − |OC|² + tca² = 1 − 26 + 25 = 0 ≤ 0 *)
  check_depths "grazing" [] (hits s (v 1. 0. (-5.)) (v 0. 0. 1.));
  check_depths "moving away" [] (hits s (v 0. 0. 5.) (v 0. 0. 1.));
  (* the lower limit [lo] drops the near root *)
  check_depths "lo = 5" [ 6. ] (hits ~lo:5. s (v 0. 0. (-5.)) (v 0. 0. 1.));
  (* an ellipsoid: the unit sphere scaled by 2 along x, crossed at x = ±2 *)
  let e = setup "sphere { 0, 1 scale <2, 1, 1> rotate y*0.0 }" in
  check_depths "ellipsoid" [ 3.; 7. ] (hits e (v (-5.) 0. 0.) (v 1. 0. 0.))

let test_all_hits_box_plane () =
  let b = setup "box { -1, 1 }" in
  let h = hits b (v 0. 0. (-5.)) (v 0. 0. 1.) in
  check_depths "box: near and far" [ 4.; 6. ] h;
  Alcotest.(check (list int)) "box: sides Z− then Z+" [ 5; 6 ] (List.map (fun (_, s, _) -> s) h);
  check_depths "box from inside: the far side only" [ 1. ] (hits b Vec.zero (v 1. 0. 0.));
  (* a ray in the plane of a face (y = 1) is inside the slab: both X faces are crossed *)
  check_depths "box: along a face" [ 4.; 6. ] (hits b (v (-5.) 1. 0.) (v 1. 0. 0.));
  check_depths "box: missed just above" [] (hits b (v (-5.) 1.000001 0.) (v 1. 0. 0.));
  (* a rotated box: the unit cube turned 45° about y, crossed at x = ±√2 *)
  let r = setup "box { -1, 1 rotate y*45 }" in
  check_depths "rotated box" [ 5. -. sqrt 2.; 5. +. sqrt 2. ] (hits r (v (-5.) 0. 0.) (v 1. 0. 0.));
  let p = setup "plane { y, 0 }" in
  check_depths "plane: one crossing" [ 2. ] (hits p (v 0. 2. 0.) (v 0. (-1.) 0.));
  check_depths "plane: parallel" [] (hits p (v 0. 2. 0.) (v 1. 0. 0.))

let test_all_hits_triangle_mesh () =
  let t = setup "triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }" in
  check_depths "triangle" [ 3. ] (hits t (v 0. 0. (-3.)) (v 0. 0. 1.));
  check_depths "triangle missed" [] (hits t (v 2. 0. (-3.)) (v 0. 0. 1.));
  let m =
    setup
      "mesh { triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> } triangle { <-1, -1, 1>, <1, -1, 1>, <0, 1, 1> } }"
  in
  let h = hits m (v 0. 0. (-3.)) (v 0. 0. 1.) in
  Alcotest.(check (list (float 1e-6))) "mesh: every face crossed" [ 3.; 4. ] (List.sort compare (depths h));
  Alcotest.(check (list int)) "mesh: faces" [ 0; 1 ] (List.sort compare (List.map (fun (_, f, _) -> f) h));
  (* a moved mesh: depths stay world depths *)
  let m2 =
    setup
      "mesh { triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> } triangle { <-1, -1, 1>, <1, -1, 1>, <0, 1, 1> } scale 2 }"
  in
  Alcotest.(check (list (float 1e-6))) "scaled mesh" [ 3.; 5. ] (List.sort compare (depths (hits m2 (v 0. 0. (-3.)) (v 0. 0. 1.))))

(* ---------------------------------------------------------------------------------------------- *)
(* Inside *)

let inside_of (c : Compiled.t) i p = Shape.inside (Array.make 512 0.) c.objects.(i).shape p

let test_inside_shapes () =
  let c, _ = setup "sphere { 0, 1 }" in
  Alcotest.(check bool) "sphere: centre" true (inside_of c 0 Vec.zero);
  Alcotest.(check bool) "sphere: surface is outside (strict)" false (inside_of c 0 (v 1. 0. 0.));
  let c, _ = setup "box { -1, 1 }" in
  Alcotest.(check bool) "box: face is inside (closed)" true (inside_of c 0 (v 1. 0. 0.));
  Alcotest.(check bool) "box: corner is inside" true (inside_of c 0 (v 1. 1. 1.));
  Alcotest.(check bool) "box: beyond" false (inside_of c 0 (v 1.0000001 0. 0.));
  let c, _ = setup "plane { y, 0 }" in
  Alcotest.(check bool) "plane: below" true (inside_of c 0 (v 0. (-1.) 0.));
  let c, _ = setup "plane { y, 0 inverse }" in
  Alcotest.(check bool) "inverse plane: below is outside" false (inside_of c 0 (v 0. (-1.) 0.));
  Alcotest.(check bool) "inverse plane: above is inside" true (inside_of c 0 (v 0. 1. 0.));
  let c, _ = setup "triangle { <-1, -1, 0>, <1, -1, 0>, <0, 1, 0> }" in
  Alcotest.(check bool) "triangle: never inside" false (inside_of c 0 Vec.zero);
  let c, _ = setup "sphere { 0, 1 inverse }" in
  Alcotest.(check bool) "inverse sphere: centre is outside" false (inside_of c 0 Vec.zero);
  Alcotest.(check bool) "inverse sphere: surface is inside" true (inside_of c 0 (v 1. 0. 0.))

let two = "sphere { <-0.5, 0, 0>, 1 } sphere { <0.5, 0, 0>, 1 }"

let test_inside_csg () =
  let p_a = v (-1.2) 0. 0. and p_both = Vec.zero and p_none = v 3. 0. 0. in
  let check name text (ea, eboth, enone) =
    let c, _ = setup text in
    Alcotest.(check (list bool)) name [ ea; eboth; enone ] [ inside_of c 0 p_a; inside_of c 0 p_both; inside_of c 0 p_none ]
  in
  check "union: inside any" ("union { " ^ two ^ " split_union off }") (true, true, false);
  check "merge: inside any" ("merge { " ^ two ^ " }") (true, true, false);
  check "intersection: inside every" ("intersection { " ^ two ^ " }") (false, true, false);
  check "difference: in the first, not the second" ("difference { " ^ two ^ " }") (true, false, false);
  (* De Morgan: inverse of the union is the intersection of the complements *)
  check "inverse union" ("union { " ^ two ^ " inverse }") (false, false, true);
  check "inverse intersection" ("intersection { " ^ two ^ " inverse }") (true, false, true)

(* ---------------------------------------------------------------------------------------------- *)
(* Which hits each CSG keeps, and the nearest *)

(* Two unit spheres at x = ∓0.5, the ray along +x from x = −5: A is crossed at x = −1.5 and 0.5
   (depths 3.5, 5.5), B at −0.5 and 1.5 (4.5, 6.5). Leaves: A is object 1, B object 2. *)
let ray_o = v (-5.) 0. 0.
let ray_d = v 1. 0. 0.

let check_hits msg e a = Alcotest.(check (list (pair (float 1e-12) int))) msg e (List.map (fun (t, _, l) -> (t, l)) a)

let test_csg_hits () =
  check_hits "union: every hit in member order" [ (3.5, 1); (5.5, 1); (4.5, 2); (6.5, 2) ]
    (hits (setup ("union { " ^ two ^ " split_union off }")) ray_o ray_d);
  (* merge: A's exit and B's entry lie inside the other sphere *)
  check_hits "merge: the outer surfaces" [ (3.5, 1); (6.5, 2) ] (hits (setup ("merge { " ^ two ^ " }")) ray_o ray_d);
  check_hits "intersection: the inner surfaces" [ (5.5, 1); (4.5, 2) ] (hits (setup ("intersection { " ^ two ^ " }")) ray_o ray_d);
  (* difference A − B: A's entry (outside B) and B's entry (inside A) *)
  check_hits "difference" [ (3.5, 1); (4.5, 2) ] (hits (setup ("difference { " ^ two ^ " }")) ray_o ray_d);
  (* a member's kept hits come off its own stack reversed: A's two hits inside the box *)
  check_hits "intersection: reversed per member" [ (5.5, 1); (3.5, 1) ]
    (hits (setup "intersection { sphere { <-0.5, 0, 0>, 1 } box { -3, 3 } }") ray_o ray_d);
  (* nested: (A ∪ B) − C with C around x = 0.5: the union's hits are filtered by the difference
     (and reversed, having come off the union's stack) *)
  (* objects: 0 the difference, 1 the union, 2 A, 3 B, 4 C; A's exit (x = 0.5) is inside C; C's
     crossings (x = 0.2, 0.8) are inside A and B *)
  check_hits "nested" [ (6.5, 3); (4.5, 3); (3.5, 2); (5.8, 4); (5.2, 4) ]
    (hits (setup ("difference { union { " ^ two ^ " } sphere { <0.5, 0, 0>, 0.3 } }")) ray_o ray_d)

let test_clipped_hits () =
  (* the unit sphere clipped by y ≤ 0 (plane { y, 0 }): the ray along +z at y = −0.5 crosses both
     halves' surface below the plane; at y = 0.5 nothing is left *)
  let s = setup "sphere { 0, 1 clipped_by { plane { y, 0 } } }" in
  let h = sqrt 0.75 in
  check_hits "below: both crossings" [ (5. -. h, 1); (5. +. h, 1) ] (hits s (v 0. (-0.5) (-5.)) (v 0. 0. 1.));
  check_hits "above: clipped away" [] (hits s (v 0. 0.5 (-5.)) (v 0. 0. 1.));
  (* an open shell: through the cut, the far inside surface is seen *)
  (* from y = 2 down: the top crossing (y = 1, depth 1) is clipped, the bottom one (y = −1) seen *)
  check_hits "through the opening" [ (3., 1) ] (hits s (v 0. 2. 0.) (v 0. (-1.) 0.));
  (* order: a clipped primitive keeps its own order; a clipped union takes each member's hits off a
     stack of its own, reversed (objects: 0 the clipped node, 1 the union, 2 A, 3 B, 4 the box) *)
  check_hits "clipped sphere: in order" [ (3.5, 1); (5.5, 1) ]
    (hits (setup "sphere { <-0.5, 0, 0>, 1 clipped_by { box { -3, 3 } } }") ray_o ray_d);
  check_hits "clipped union: reversed per member" [ (5.5, 2); (3.5, 2); (6.5, 3); (4.5, 3) ]
    (hits (setup ("union { " ^ two ^ " clipped_by { box { -3, 3 } } }")) ray_o ray_d);
  (* the clip objects' own surfaces are never hits, and the Inside asks them *)
  let c, _ = s in
  Alcotest.(check (list bool)) "Inside: in the sphere and below the plane" [ true; false; false ]
    (List.map (inside_of c 0) [ v 0. (-0.5) 0.; v 0. 0.5 0.; v 0. (-2.) 0. ])

let nearest_leaf (c, ctx) o d =
  let t = Shape.depth ctx.Context.shapes c.Compiled.objects.(0).shape o (Vec.normalize d) 1e-4 in
  (t, ctx.Context.shapes.leaf)

let test_nearest () =
  let t, leaf = nearest_leaf (setup ("intersection { " ^ two ^ " }")) ray_o ray_d in
  float_eq "intersection: nearest depth" 4.5 t;
  Alcotest.(check int) "intersection: the leaf is B" 2 leaf;
  let t, leaf = nearest_leaf (setup ("difference { " ^ two ^ " }")) (v 0. 0. 0.) ray_d in
  (* from the origin (inside B, so outside A − B): A's exit at 0.5 is inside B, B's exit at 1.5 outside A *)
  Alcotest.(check bool) "difference from inside the hole: nothing" true (t = infinity);
  ignore leaf;
  (* the bounding box is tested first: a ray that misses it misses the CSG *)
  let t, _ = nearest_leaf (setup ("merge { " ^ two ^ " }")) (v (-5.) 1.01 0.) ray_d in
  Alcotest.(check bool) "outside the box" true (t = infinity)

let test_coincident () =
  (* boxes sharing the face x = 1: Box::Inside is closed, so each face is inside the other box and
     both hits at depth 6 survive; the last pushed (the second box's) wins the tie *)
  let s = setup "intersection { box { -1, 1 } box { <1, -1, -1>, <2, 1, 1> } }" in
  check_hits "shared face: both kept" [ (6., 1); (6., 2) ] (hits s ray_o ray_d);
  let t, leaf = nearest_leaf s ray_o ray_d in
  float_eq "shared face: depth" 6. t;
  Alcotest.(check int) "shared face: the last pushed wins" 2 leaf;
  (* spheres touching at x = 0: Sphere::Inside is strict, so in a merge both touching hits stay *)
  let s = setup "merge { sphere { <-1, 0, 0>, 1 } sphere { <1, 0, 0>, 1 } }" in
  check_hits "touching spheres: merge keeps the contact (reversed per member)" [ (5., 1); (3., 1); (7., 2); (5., 2) ] (hits s ray_o ray_d);
  (* … and in an intersection neither contact point is strictly inside the other sphere *)
  check_hits "touching spheres: intersection is empty" []
    (hits (setup "intersection { sphere { <-1, 0, 0>, 1 } sphere { <1, 0, 0>, 1 } }") ray_o ray_d)

(* ---------------------------------------------------------------------------------------------- *)
(* Compiled: ids, interiors, boxes; shading *)

let test_compiled () =
  let c, _ =
    setup
      "difference { box { -1, 1 } sphere { 0, 1 interior { ior 2 } } sphere { x, 0.5 } interior { ior 1.5 } } \
       sphere { 5*x, 1 }"
  in
  Alcotest.(check int) "objects: CSG, 3 members, sphere" 5 (Array.length c.objects);
  Alcotest.(check (list int)) "tops" [ 0; 0; 0; 0; 4 ] (Array.to_list (Array.map (fun (o : Compiled.obj) -> o.top) c.objects));
  (* §16.5: members without an interior share the CSG's *)
  Alcotest.(check (list int)) "interior identities" [ 0; 0; 2; 0; 4 ] (Array.to_list (Array.map (fun (o : Compiled.obj) -> o.iid) c.objects));
  float_eq "shared ior" 1.5 c.objects.(3).interior.ior;
  float_eq "own ior" 2. c.objects.(2).interior.ior;
  Alcotest.(check int) "groups hold top-level objects" 2 (Array.length c.all.bounded + Array.length c.all.unbounded);
  (* bounding boxes: an intersection's is the overlap of its members' that are not inverted *)
  let c, _ = setup "intersection { box { -1, 1 } sphere { x, 1 } sphere { 0, 0.5 inverse } }" in
  Alcotest.(check (list (float 0.))) "intersection box" [ 0.; -1.; -1.; 1.; 2.; 2. ] (Array.to_list c.objects.(0).pbox);
  let c, _ = setup ("union { " ^ two ^ " split_union off }") in
  Alcotest.(check (list (float 0.))) "union box" [ -1.5; -1.; -1.; 3.; 2.; 2. ] (Array.to_list c.objects.(0).pbox);
  (* an inverted CSG (morphed) is left out of an enclosing intersection's box: ¬(box ∩ ¬S) is not
     bounded by its members' boxes; the intersection's box is the outer box's *)
  let c, _ = setup "intersection { difference { box { -0.5, 0.5 } sphere { 0, 0.4 } inverse } box { -0.7, 0.7 } }" in
  Alcotest.(check (list (float 1e-7))) "inverted CSG member" [ -0.7; -0.7; -0.7; 1.4; 1.4; 1.4 ] (Array.to_list c.objects.(0).pbox);
  (* … and its Inside is the morphed CSG's own: outside the inner box, or in the sphere *)
  Alcotest.(check (list bool)) "inverted CSG member: Inside" [ true; true; false ]
    (List.map (inside_of c 1) [ v 0.6 0. 0.; Vec.zero; v 0.45 0. 0. ]);
  (* an inverted sphere alone keeps the sphere's box, as POV-Ray's inverted primitive does *)
  let c, _ = setup "sphere { 0, 1 inverse }" in
  Alcotest.(check (list (float 0.))) "inverse sphere box" [ -1.; -1.; -1.; 2.; 2.; 2. ] (Array.to_list c.objects.(0).pbox);
  (* a union with a plane is unbounded *)
  let c, _ = setup "union { plane { y, 0 } sphere { 0, 1 } split_union off }" in
  Alcotest.(check int) "union with a plane: unbounded" 1 (Array.length c.all.unbounded);
  (* the camera inside a CSG starts inside its interior (§6.4) *)
  let c = compile (v37 ^ "camera { location 0 look_at z } merge { sphere { 0, 1 } sphere { x, 1 } interior { ior 1.5 } }") in
  Alcotest.(check (list int)) "camera inside: the CSG's interior" [ 0 ] c.start_interiors

let test_shading () =
  (* the cut surface of a difference shows the subtracted sphere's own texture (§16.5): its pigment
     on the default finish (ambient 0.1), not the CSG's finish *)
  let text =
    v37
    ^ "camera { location <0, 0, -5> look_at 0 } \
       difference { box { -1, 1 } sphere { <0, 0, -1>, 0.5 pigment { rgb <0, 0, 1> } } sphere { <0, 0, 1>, 0.5 } \
       pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }"
  in
  result_eq "the hole: its own texture" (0., 0., 0.1) (trace_text text (v 0. 0. (-5.)) (v 0. 0. 1.));
  result_eq "the box face: the CSG's" (1., 0., 0.) (trace_text text (v 0.8 0. (-5.)) (v 0. 0. 1.));
  (* the other sphere has no pigment: from behind, the difference's *)
  result_eq "the far hole: the CSG's" (1., 0., 0.) (trace_text text (v 0. 0. 5.) (v 0. 0. (-1.)))

let test_shadow_cache () =
  (* an opaque CSG that blocks a light is cached as the top-level object *)
  let c = compile (v37 ^ "light_source { <0, 10, 0>, 1 } intersection { box { -1, 1 } sphere { 0, 1.2 } translate y*3 } plane { y, 0 }") in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  ignore (Trace.trace ctx ~level:0 ~weight:1. ~interiors:[] ~continued:false (v 0. 1. (-5.)) (Vec.normalize (v 0. (-1.) 5.)));
  Alcotest.(check bool) "cached: the CSG" true (Array.exists (fun i -> i = 0) ctx.shadow_cache);
  (* opaque members but a transparent texture on the CSG itself: POV-Ray tests the CSG's OPAQUE
     flag before caching, so nothing is cached, though the shadow is full *)
  let c =
    compile
      (v37
     ^ "light_source { <0, 10, 0>, 1 } intersection { box { -1, 1 pigment { rgb 1 } } sphere { 0, 1.2 pigment { rgb 1 } } \
        pigment { rgbt <1, 1, 1, 0.5> } translate y*3 } plane { y, 0 finish { ambient 0 } }")
  in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  let r = Trace.trace ctx ~level:0 ~weight:1. ~interiors:[] ~continued:false (v 0. 1. (-5.)) (Vec.normalize (v 0. (-1.) 5.)) in
  result_eq "full shadow" (0., 0., 0.) r;
  Alcotest.(check bool) "not cached" true (Array.for_all (fun i -> i < 0) ctx.shadow_cache)

let test_light_at_infinity () =
  (* a light written at -1e400 (−infinity) over a transparent merge: the shadow walk ends *)
  let c =
    compile
      (v37
     ^ "light_source { <-1e400, 8, -5>, rgb 1 } merge { box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> } sphere { <0, 1, 0>, 0.5 } \
        pigment { rgbf <0.8, 1, 0.8, 0.9> } } plane { y, 0 }")
  in
  let ctx = Trace.make_ctx c (Stats.create ()) in
  ignore (Trace.trace ctx ~level:0 ~weight:1. ~interiors:[] ~continued:false (v 0. 0.5 (-5.)) (v 0. 0. 1.))

let tests =
  [
    Alcotest.test_case "parse: kinds" `Quick test_parse_kinds;
    Alcotest.test_case "parse: inverse and De Morgan" `Quick test_parse_inverse;
    Alcotest.test_case "parse: textures and interiors" `Quick test_parse_textures_interiors;
    Alcotest.test_case "parse: lights and transforms" `Quick test_parse_lights_and_transforms;
    Alcotest.test_case "parse: warnings and errors" `Quick test_parse_warnings;
    Alcotest.test_case "parse: clipped_by" `Quick test_parse_clipped_by;
    Alcotest.test_case "clipped_by: hits and Inside" `Quick test_clipped_hits;
    Alcotest.test_case "all hits: sphere, ellipsoid" `Quick test_all_hits_sphere;
    Alcotest.test_case "all hits: box, plane" `Quick test_all_hits_box_plane;
    Alcotest.test_case "all hits: triangle, mesh" `Quick test_all_hits_triangle_mesh;
    Alcotest.test_case "inside: shapes" `Quick test_inside_shapes;
    Alcotest.test_case "inside: CSG kinds" `Quick test_inside_csg;
    Alcotest.test_case "hits kept by each kind" `Quick test_csg_hits;
    Alcotest.test_case "nearest hit and leaf" `Quick test_nearest;
    Alcotest.test_case "coincident boundaries" `Quick test_coincident;
    Alcotest.test_case "compiled ids, interiors, boxes" `Quick test_compiled;
    Alcotest.test_case "shading the primitive hit" `Quick test_shading;
    Alcotest.test_case "shadow cache" `Quick test_shadow_cache;
    Alcotest.test_case "a light at infinity" `Quick test_light_at_infinity;
  ]
