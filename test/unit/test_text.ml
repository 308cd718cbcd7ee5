(* The text object (docs/povray-rules.md §15.9): the font tables of cyrvetic.ttf (values checked against the
   file with an independent reader), the layout of a string, the glyph intersection and inside
   test on hand-made outlines (a unit square, a parabola arch) whose depths are computed by hand,
   and on real letters: a ray through the stem of an I, through the ring of an O and through its
   counter. *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let font =
  lazy
    (let ic = open_in_bin (Filename.concat Access.standard_include_dir "cyrvetic.ttf") in
     let s = really_input_string ic (in_channel_length ic) in
     close_in ic;
     match Font.parse s with Ok f -> f | Error e -> Alcotest.fail e)

let letter c =
  let f = Lazy.force font in
  match Font.outline f (Font.glyph_index f (Char.code c)) ~char_code:(Char.code c) with
  | Ok (o, _) -> o
  | Error e -> Alcotest.fail e

let glyph ?(depth = 0.25) outline = { Glyph.outline; depth; tr = Transform.identity }

let hits g o d =
  let out = Array.make (Glyph.max_hits g.Glyph.outline) 0. in
  let k = Glyph.crossings g o d out in
  List.init k (fun i -> (out.(2 * i), int_of_float out.((2 * i) + 1)))

let depths g o d = List.map fst (hits g o d)
let sorted g o d = List.sort compare (depths g o d)
let floats msg e a = Alcotest.(check (list (float 1e-12))) msg e a

let test_tables () =
  let f = Lazy.force font in
  Alcotest.(check int) "units per em" 1000 (Font.units_per_em f);
  (* the Macintosh format-0 map comes first: I is glyph 42, O glyph 48, the space glyph 1 *)
  Alcotest.(check int) "I" 42 (Font.glyph_index f (Char.code 'I'));
  Alcotest.(check int) "O" 48 (Font.glyph_index f (Char.code 'O'));
  Alcotest.(check int) "space" 1 (Font.glyph_index f 32);
  let i = letter 'I' and o = letter 'O' and sp = letter ' ' in
  Alcotest.(check (list int)) "I: one contour of four lines, its box" [ 1; 4; 79; 0; 178; 728 ] [ i.contours; i.nseg; i.xmin; i.ymin; i.xmax; i.ymax ];
  Alcotest.(check (list int)) "O: two contours, its box" [ 2; 37; -21; 713; 749 ] [ o.contours; o.xmin; o.ymin; o.xmax; o.ymax ];
  Alcotest.(check (list int)) "a space has no outline" [ 0; 0 ] [ sp.contours; sp.nseg ];
  (* the I's stem: every segment is a line with x at 79 or 178 units *)
  for k = 0 to i.nseg - 1 do
    Alcotest.(check (float 0.)) "a line" 0. i.segs.(7 * k);
    let x = i.segs.((7 * k) + 1) in
    Alcotest.(check bool) "on the stem's sides" true (x = 0.079 || x = 0.178)
  done;
  Alcotest.(check bool) "garbage is not a font" true (Result.is_error (Font.parse (String.make 64 'x')))

let test_layout () =
  let f = Lazy.force font in
  let places s offset = match Font.layout f (Array.init (String.length s) (fun i -> Char.code s.[i])) ~offset with Ok l -> List.map snd l | Error e -> Alcotest.fail e in
  (* the first glyph's left edge at 0 (−79/1000); the next one after the I's advance 263 less its
     left bearing 79, plus the O's bearing 37 less its xMin 37 *)
  (match places "IO" (Vec.make 0. 0. 0.) with
  | [ a; b ] -> vec_eq "I" (Vec.make (-0.079) 0. 0.) a; vec_eq "O" (Vec.make 0.184 0. 0.) b
  | _ -> Alcotest.fail "two letters");
  (* the offset is added after each letter; its z is not used *)
  match places "IO" (Vec.make 0.1 0.2 0.3) with
  | [ a; b ] -> vec_eq "I" (Vec.make (-0.079) 0. 0.) a; vec_eq "O, offset" (Vec.make 0.284 0.2 0.) b
  | _ -> Alcotest.fail "two letters"

(* the unit square (0,0) (1,0) (1,1) (0,1), all on the curve *)
let square =
  Glyph.outline_of_contours ~units_per_em:1 ~xmin:0 ~ymin:0 ~xmax:1 ~ymax:1
    [ ([| 0.; 1.; 1.; 0. |], [| 0.; 0.; 1.; 1. |], [| true; true; true; true |]) ]

let test_square () =
  let g = glyph ~depth:0.5 square in
  Alcotest.(check int) "four lines" 4 square.nseg;
  (* straight through: the front face at t = 1, the back one at 1.5 *)
  Alcotest.(check (list (pair (float 1e-12) int))) "faces" [ (1., 0); (1.5, 1) ] (hits g (Vec.make 0.5 0.5 (-1.)) (Vec.make 0. 0. 1.));
  vec_eq "front normal" (Vec.make 0. 0. (-1.)) (Glyph.normal g 0);
  vec_eq "back normal" (Vec.make 0. 0. 1.) (Glyph.normal g 1);
  (* along +x between the faces: the walls x = 0 and x = 1 *)
  floats "walls" [ 1.; 2. ] (sorted g (Vec.make (-1.) 0.5 0.25) (Vec.make 1. 0. 0.));
  (match hits g (Vec.make (-1.) 0.5 0.25) (Vec.make 1. 0. 0.) with
  | [ (_, p1); (_, p2) ] ->
      (* the segments in contour order: (1,0)→(1,1) faces +x, (0,1)→(0,0) faces −x *)
      vec_eq "x = 1" (Vec.make 1. 0. 0.) (Glyph.normal g p1);
      vec_eq "x = 0" (Vec.make (-1.) 0. 0.) (Glyph.normal g p2)
  | _ -> Alcotest.fail "two walls");
  (* grazing the bottom edge: the edge itself is parallel, the corners are met on the side walls *)
  floats "grazing the edge y = 0" [ 1.; 2. ] (sorted g (Vec.make (-1.) 0. 0.25) (Vec.make 1. 0. 0.));
  (* beyond the depth, or above the square: nothing *)
  floats "behind the back face" [] (depths g (Vec.make (-1.) 0.5 0.75) (Vec.make 1. 0. 0.));
  floats "above" [] (depths g (Vec.make 0.5 1.5 (-1.)) (Vec.make 0. 0. 1.));
  (* from inside: only the back face ahead *)
  floats "from inside" [ 0.25 ] (depths g (Vec.make 0.5 0.5 0.25) (Vec.make 0. 0. 1.));
  (* hits at or below 1e-6 are not kept *)
  floats "starting on the face" [ 0.5 ] (depths g (Vec.make 0.5 0.5 0.) (Vec.make 0. 0. 1.));
  (* a diagonal ray: enters the front face at (0.5, 0.5) at t = 1.25, leaves through the back face
     at (0.875, 0.5) at t = 1.875; it meets x = 1 only beyond the depth (z = 2/3) *)
  let d = Vec.make 0.6 0. 0.8 in
  floats "diagonal" [ 1.25; 1.875 ] (depths g (Vec.make (0.5 -. 0.75) 0.5 (-1.)) d);
  (* the inside test, faces included (inverse is CSG's, §16.3) *)
  Alcotest.(check bool) "inside" true (Glyph.inside g (Vec.make 0.5 0.5 0.25));
  Alcotest.(check bool) "on the back face" true (Glyph.inside g (Vec.make 0.5 0.5 0.5));
  Alcotest.(check bool) "beyond the depth" false (Glyph.inside g (Vec.make 0.5 0.5 0.51));
  Alcotest.(check bool) "in front" false (Glyph.inside g (Vec.make 0.5 0.5 (-0.01)));
  Alcotest.(check bool) "beside" false (Glyph.inside g (Vec.make 1.01 0.5 0.25));
  (* the box: the header's, the depth widened by 1e-6 *)
  Alcotest.(check (array (float 1e-15))) "box" [| 0.; 0.; -1e-6; 1.; 1.; 0.5 +. 1e-6 |] (Glyph.box g)

(* an arch: from (0,0) by the control point (1,2) to (2,0), back along the X axis; on the curve
   x = 2s, y = 4s(1 − s) *)
let arch =
  Glyph.outline_of_contours ~units_per_em:1 ~xmin:0 ~ymin:0 ~xmax:2 ~ymax:1
    [ ([| 0.; 1.; 2. |], [| 0.; 2.; 0. |], [| true; false; true |]) ]

let test_arch () =
  let g = glyph ~depth:0.5 arch in
  (* POV-Ray's walk: the curve, then a line of no length to the curve's own end point, then the
     closing line *)
  Alcotest.(check int) "a curve and two lines" 3 arch.nseg;
  (* y = 0.75: 4s² − 4s + 0.75 = 0 at s = 0.75 (found first) and 0.25, x = 1.5 and 0.5 *)
  (match hits g (Vec.make (-1.) 0.75 0.1) (Vec.make 1. 0. 0.) with
  | [ (t1, p1); (t2, p2) ] ->
      float_eq "s = 0.75" 2.5 t1;
      float_eq "s = 0.25" 1.5 t2;
      (* the derivative (2, 4 − 8s) turned a quarter: (4 − 8s, −2) *)
      vec_eq ~eps:1e-9 "normal at s = 0.25" (Vec.normalize (Vec.make 2. (-2.) 0.)) (Glyph.normal g p2);
      vec_eq ~eps:1e-9 "normal at s = 0.75" (Vec.normalize (Vec.make (-2.) (-2.) 0.)) (Glyph.normal g p1)
  | l -> Alcotest.failf "two crossings, not %d" (List.length l));
  (* tangent at the top (y = 1): the discriminant is 0, below POV-Ray's 1e-10, so no crossing *)
  floats "tangent at the top" [] (depths g (Vec.make (-1.) 1. 0.1) (Vec.make 1. 0. 0.));
  (* inside: under the arch; outside: above it, or left of the left crossing *)
  Alcotest.(check bool) "under the arch" true (Glyph.inside_outline arch 1. 0.5);
  Alcotest.(check bool) "above the arch" false (Glyph.inside_outline arch 1. 1.2);
  Alcotest.(check bool) "left of the curve" false (Glyph.inside_outline arch 0.2 0.5);
  Alcotest.(check bool) "right of x = 0.293 at y = 0.5" true (Glyph.inside_outline arch 0.3 0.5)

let test_letters () =
  let i = glyph (letter 'I') and o = glyph (letter 'O') in
  (* through the I's stem (x from 0.079 to 0.178): the front face at 1, the back at 1.25 *)
  floats "through the I" [ 1.; 1.25 ] (depths i (Vec.make 0.128 0.364 (-1.)) (Vec.make 0. 0. 1.));
  floats "across the I's walls" [ 1.079; 1.178 ] (sorted i (Vec.make (-1.) 0.364 0.1) (Vec.make 1. 0. 0.));
  (* the O: through its ring, and through its counter, where nothing is met *)
  floats "through the O's ring" [ 1.; 1.25 ] (depths o (Vec.make 0.06 0.364 (-1.)) (Vec.make 0. 0. 1.));
  floats "through the O's counter" [] (depths o (Vec.make 0.375 0.364 (-1.)) (Vec.make 0. 0. 1.));
  Alcotest.(check bool) "the counter is outside" false (Glyph.inside o (Vec.make 0.375 0.364 0.1));
  Alcotest.(check bool) "the ring is inside" true (Glyph.inside o (Vec.make 0.06 0.364 0.1));
  (* across the O at its middle height: four walls, two on each side of the counter *)
  Alcotest.(check int) "four walls" 4 (List.length (depths o (Vec.make (-1.) 0.364 0.1) (Vec.make 1. 0. 0.)))

let glyph_of (o : Scene.obj) =
  match o.shape with
  | Glyph { depth; trans; _ } -> (depth, trans)
  | _ -> Alcotest.fail "expected a glyph"

let test_scene () =
  let s = scene (v37 ^ "text { ttf \"cyrvetic.ttf\" \"I O\", 0.25, 0 translate y pigment { rgb 1 } }") in
  (* a union of one glyph per character, the space included, dissolved into the scene *)
  Alcotest.(check int) "three letters" 3 (List.length s.objects);
  let depth, trans = glyph_of (List.hd s.objects) in
  float_eq "depth" 0.25 depth;
  (* the I's origin: (−0.079, 0, 0), turned by 0.001° about x, y and z, then moved up *)
  let p = Transform.point trans (Vec.make 0. 0. 0.) in
  vec_eq ~eps:1e-5 "placed" (Vec.make (-0.079) 1. 0.) p;
  Alcotest.(check bool) "the tiny turn is there" true (p.y <> 1. && p.z <> 0.);
  expect_scene_error "no string" (v37 ^ "text { ttf \"cyrvetic.ttf\", 0.25, 0 }") ~line:3 ~col:28 ~sub:"the string to render";
  expect_scene_error "no font" (v37 ^ "text { ttf \"nofont.ttf\" \"a\", 0.25, 0 }") ~line:3 ~col:12 ~sub:"cannot find the font file"

let tests =
  [
    Alcotest.test_case "cyrvetic.ttf: tables, maps, outlines" `Quick test_tables;
    Alcotest.test_case "layout: advances, bearings, the offset" `Quick test_layout;
    Alcotest.test_case "a square: faces, walls, grazing, from inside, inside" `Quick test_square;
    Alcotest.test_case "an arch: the curve's roots, normals, tangent, inside" `Quick test_arch;
    Alcotest.test_case "letters: through an I, an O's ring and its counter" `Quick test_letters;
    Alcotest.test_case "the text object in a scene, errors" `Quick test_scene;
  ]
