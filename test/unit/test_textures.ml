(* Layered and patterned textures, materials and interior textures as they are read: the layer
   order, texture maps and listed textures, tiles, materials, and POV-Ray's errors. *)

open Helpers

let v37 = "#version 3.7; global_settings { assumed_gamma 1 }\n"
let obj text = the_object (scene (v37 ^ text))
let red_of (l : Scene.layer) = match l.pigment with Solid c | Solid_placed { colour = c; _ } -> c.red | Pattern _ -> nan
let layers (o : Scene.obj) = match o.texture with Layers ls -> ls | _ -> Alcotest.fail "a patterned texture"

let test_layers () =
  (* the last written on top *)
  let ls = layers (obj "sphere { 0, 1 texture { pigment { rgb 0.1 } } texture { pigment { rgb 0.2 } } texture { pigment { rgb 0.3 } } }") in
  Alcotest.(check int) "three layers" 3 (List.length ls);
  float_eq ~eps:1e-7 "top layer" 0.3 (red_of (List.hd ls));
  float_eq ~eps:1e-7 "bottom layer" 0.1 (red_of (List.nth ls 2));
  (* a declared layered texture, and an object pigment editing its top layer *)
  let ls = layers (obj "#declare T = texture { pigment { rgb 0.1 } } texture { pigment { rgb 0.2 } }\nsphere { 0, 1 texture { T } pigment { rgb 0.5 } }") in
  Alcotest.(check int) "declared layers" 2 (List.length ls);
  float_eq ~eps:1e-7 "pigment edits the top" 0.5 (red_of (List.hd ls));
  float_eq ~eps:1e-7 "the bottom kept" 0.1 (red_of (List.nth ls 1));
  (* version 3.1: filter of a layer with one below becomes transmit *)
  let o = the_object (scene "#version 3.1;\nsphere { 0, 1 texture { pigment { rgbf <1,1,1,0.5> } } texture { pigment { rgbf <1,0,0,0.25> } } }") in
  match layers o with
  | [ top; bottom ] ->
      let c (l : Scene.layer) = match l.pigment with Solid c -> c | Solid_placed _ | Pattern _ -> Alcotest.fail "solid" in
      float_eq ~eps:1e-7 "top filter gone" 0. (c top).filter;
      float_eq ~eps:1e-7 "top transmit" 0.25 (c top).transmit;
      float_eq ~eps:1e-7 "bottom filter kept" 0.5 (c bottom).filter
  | _ -> Alcotest.fail "two layers"

let entries (o : Scene.obj) = match o.texture with Texture_pattern { tmap; _ } -> tmap | _ -> Alcotest.fail "a plain texture"

let test_patterned () =
  let m = entries (obj "plane { y, 0 texture { gradient x texture_map { [0.2 pigment { rgb 1 }] [0.7 pigment { rgb 0.5 }] } } }") in
  Alcotest.(check int) "two entries" 2 (Array.length m);
  float_eq ~eps:1e-7 "first value" 0.2 m.(0).tvalue;
  (* listed textures: values 0, 1, 2; missing ones the default texture *)
  let m = entries (obj "plane { y, 0 texture { hexagon texture { pigment { rgb 1 } } } }") in
  Alcotest.(check int) "three entries" 3 (Array.length m);
  float_eq "third value" 2. m.(2).tvalue;
  (* tiles: the first texture at checker value 1 *)
  let m = entries (obj "plane { y, 0 texture { tiles { texture { pigment { rgb 0.25 } } tile2 texture { pigment { rgb 0.75 } } } } }") in
  (match (m.(0).ttexture, m.(1).ttexture) with
  | Layers [ a ], Layers [ b ] ->
      float_eq ~eps:1e-7 "tile2 at 0" 0.75 (red_of a);
      float_eq ~eps:1e-7 "first tile at 1" 0.25 (red_of b)
  | _ -> Alcotest.fail "two plain tiles");
  (* average: values left out are 1 *)
  let m = entries (obj "plane { y, 0 texture { average texture_map { [pigment { rgb 1 }] [3 pigment { rgb 0 }] } } }") in
  float_eq "average default weight" 1. m.(0).tvalue;
  float_eq "average weight" 3. m.(1).tvalue

let test_uv_object () =
  (* an object's uv_mapping: transforms after it leave its texture *)
  let o = obj "sphere { 0, 1 uv_mapping pigment { checker } scale 2 }" in
  Alcotest.(check bool) "flagged" true o.uv_mapped;
  let pp = match (List.hd (layers o)).pigment with Pattern p -> p | Solid _ | Solid_placed _ -> Alcotest.fail "a pattern" in
  Alcotest.(check int) "the texture not moved" 0 (List.length pp.warps);
  (* the members of a union that take its texture take its uv_mapping *)
  let s = scene (v37 ^ "union { sphere { 0, 1 } sphere { x, 1 pigment { rgb 1 } } uv_mapping pigment { checker } }") in
  Alcotest.(check (list bool)) "members" [ true; false ] (List.map (fun (o : Scene.obj) -> o.uv_mapped) s.objects)

let test_material () =
  let o = obj "#declare M = material { texture { pigment { rgb 0.5 } } interior { ior 1.5 } }\nsphere { 0, 1 texture { pigment { rgb 0.1 } } material { M } }" in
  (match layers o with
  | [ top; bottom ] -> float_eq ~eps:1e-7 "material on top" 0.5 (red_of top); float_eq ~eps:1e-7 "object's below" 0.1 (red_of bottom)
  | _ -> Alcotest.fail "two layers");
  float_eq "material interior" 1.5 o.interior.ior;
  let o = obj "sphere { 0, 1 texture { pigment { rgb 0.1 } } interior_texture { pigment { rgb 0.9 } } }" in
  match o.interior_texture with Some (Layers [ l ]) -> float_eq ~eps:1e-7 "interior texture" 0.9 (red_of l) | _ -> Alcotest.fail "an interior texture"

let test_errors () =
  expect_scene_error "over a patterned texture" (v37 ^ "sphere { 0, 1 texture { checker texture { } texture { } } texture { pigment { rgb 1 } } }")
    ~line:2 ~col:59 ~sub:"cannot layer over a patterned texture";
  expect_scene_error "a patterned texture over another" (v37 ^ "sphere { 0, 1 texture { pigment { rgb 1 } } texture { checker texture { } texture { } } }")
    ~line:2 ~col:45 ~sub:"cannot layer a patterned texture over another";
  expect_scene_error "pigment on a patterned texture" (v37 ^ "sphere { 0, 1 texture { checker texture { } texture { } } pigment { rgb 1 } }")
    ~line:2 ~col:59 ~sub:"cannot layer over a patterned texture";
  expect_scene_error "no texture_map" (v37 ^ "sphere { 0, 1 texture { bozo } }") ~line:2 ~col:30 ~sub:"must have a texture_map";
  expect_scene_error "texture_map on a block pattern" (v37 ^ "sphere { 0, 1 texture { checker texture_map { [0 pigment { rgb 1 }] } } }")
    ~line:2 ~col:33 ~sub:"cannot use texture_map with this pattern type";
  expect_scene_error "interior texture alone" (v37 ^ "sphere { 0, 1 interior_texture { pigment { rgb 1 } } }") ~line:2 ~col:54
    ~sub:"requires an exterior texture";
  expect_scene_error "uv_mapping after a texture" (v37 ^ "sphere { 0, 1 pigment { rgb 1 } uv_mapping }") ~line:2 ~col:33
    ~sub:"uv_mapping must be specified before texture";
  (* #default's normal may have no pattern, as a base; an object that keeps it is refused *)
  let o = obj "#default { normal { bump_size 1.5 } }\nsphere { 0, 1 normal { bumps } }" in
  (match (List.hd (layers o)).normal with
  | Some n -> float_eq ~eps:1e-7 "the default's bump size" 1.5 n.amount
  | None -> Alcotest.fail "a normal");
  expect_scene_error "a patternless default normal kept" (v37 ^ "#default { normal { bump_size 1.5 } }\nsphere { 0, 1 pigment { rgb 1 } }") ~line:3 ~col:1
    ~sub:"no normal type given";
  expect_scene_error "a normal without a pattern" (v37 ^ "sphere { 0, 1 normal { bump_size 1 } }") ~line:2 ~col:24 ~sub:"needs a pattern";
  expect_scene_error "layered default" (v37 ^ "#default { texture { checker texture { } texture { } } }") ~line:2 ~col:12
    ~sub:"default texture cannot be"

let tests =
  [
    Alcotest.test_case "layers" `Quick test_layers;
    Alcotest.test_case "patterned textures" `Quick test_patterned;
    Alcotest.test_case "materials" `Quick test_material;
    Alcotest.test_case "uv_mapping on objects" `Quick test_uv_object;
    Alcotest.test_case "errors" `Quick test_errors;
  ]
