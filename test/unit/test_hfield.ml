(* The height field (POV-Ray's hfield.cpp): hits and normals against POV-Ray 3.7.0.10's trace() of
   test/unit/data/hfield.pov (17 digits), hits against brute-force sampling of the triangle
   surface, Inside, how image samples become heights, the blocks, and the parser's errors. *)

open Helpers

let v = Vec.make

(* the repository's root, where scenes/images is *)
let root =
  let rec up d n =
    if Sys.file_exists (Filename.concat d "scenes/images/hf_grey8.png") then d
    else if n = 0 then Alcotest.fail "scenes/images not found above the working directory"
    else up (Filename.dirname d) (n - 1)
  in
  lazy (up (Sys.getcwd ()) 8)

(* the compiled height field of [text] (its one object), file names relative to the root *)
let field_of text =
  let root = Lazy.force root in
  let opts = { opts with access = Access.allow_read opts.access root } in
  let s, _ = Interp.load_string opts ~file:(Filename.concat root "t.pov") text in
  match Shape.compile ~iso_slot:0 (List.hd s.objects).shape with
  | Some (Compiled.Height_field h) -> h
  | Some _ | None -> Alcotest.fail "expected a height field"

let scratch () = Scratch.create ~robust:false (Stats.create ())

(* POV-Ray's trace(): the nearest hit from 1e-4 along the normalised direction, and its normal *)
let trace h o d =
  let w = scratch () in
  let d = Transform.normalize d in
  let t = Hfield.depth w h o d Precision.min_isect_depth in
  if t = infinity then Alcotest.fail "expected a hit";
  let p = Vec.add o (Vec.scale t d) in
  (p, Hfield.normal w h w.part p)

let test_pov_flat () =
  let h = field_of "height_field { png \"scenes/images/hf_grey8.png\" }" in
  let p, n = trace h (v (-0.2) 0.45 0.5) (v 0.96087257926379466 0.1703210656168497 0.21843676665360973) in
  vec_eq ~eps:1e-16 "point" (v 0.02607498616693207 0.49007329731770327 0.55139400380995440) p;
  vec_eq ~eps:1e-16 "normal" (v 0.48650571169211759 0.79526185576809882 0.36176065741208746) n;
  let p, n = trace h (v (-0.2) 0.45 0.5) (v 0.94147652444244967 (-0.24862159092761274) 0.22761647226944762) in
  vec_eq ~eps:1e-16 "point" (v 0.15393586945301113 0.35653394251984405 0.58556945598003463) p;
  vec_eq ~eps:1e-16 "normal" (v 0.88873545076966598 0.44700394094844037 (-0.10166993322414325)) n

let test_pov_smooth () =
  let h = field_of "height_field { png \"scenes/images/hf_grey16.png\" smooth scale <2, 0.5, 1> rotate y*30 }" in
  let p, n = trace h (v 0.3 1.5 (-1.)) (v 0.2 (-0.8) 0.6) in
  vec_eq ~eps:1e-16 "point" (v 0.56844132536781178 0.42623469852875284 (-0.19467602389656480)) p;
  vec_eq ~eps:1e-16 "normal" (v 0.20108706274113197 0.94001545282596888 (-0.27556295405321213)) n;
  let p, n = trace h (v (-0.5) 0.3 0.2) (v 1. (-0.1) 0.05) in
  vec_eq ~eps:1e-16 "point" (v 0.48379881720995055 0.20162011827900492 0.24918994086049756) p;
  vec_eq ~eps:1e-16 "normal" (v 0.63459304882082701 0.77078185154265655 0.05645351823192246) n

(* a synthetic field of [nx]×[nz] vertices, placed by its scaling only *)
let synthetic ?(water = 0.) ?(smooth = false) nx nz f =
  let heights = Array.init (nx * nz) (fun k -> f (k mod nx) (k / nx)) in
  let field = Hfield.make ~width:nx ~height:nz ~heights ~water ~smooth in
  { Hfield.field; tr = Hfield.scaling field }

let bumpy x z = int_of_float (30000. +. (20000. *. sin (float_of_int x /. 3.) *. cos (float_of_int z /. 4.)))

(* the surface's height in field space over (x, z): the triangle the point lies over, as
   Inside picks it *)
let surface (f : Hfield.field) x z =
  let px = int_of_float x and pz = int_of_float z in
  let fx = x -. float_of_int px and fz = z -. float_of_int pz in
  let h i j = Bigarray.Array1.get f.map ((j * f.width) + i) in
  if fx +. fz <= 1. then h px pz +. (fx *. (h (px + 1) pz -. h px pz)) +. (fz *. (h px (pz + 1) -. h px pz))
  else
    let y4 = h (px + 1) (pz + 1) in
    y4 +. ((1. -. fx) *. (h px (pz + 1) -. y4)) +. ((1. -. fz) *. (h (px + 1) pz -. y4))

(* Random rays from above: the depth found is where brute-force sampling along the ray first goes
   below the surface (to the sampling step), and the hit lies on the surface. *)
let test_brute_force () =
  let h = synthetic 30 25 bumpy in
  let f = h.field in
  let rnd = Random.State.make [| 7 |] in
  let w = scratch () in
  for _ = 1 to 300 do
    (* from above the field: a ray entering through a side below the surface crosses no triangle *)
    let o = v (Random.State.float rnd 1.) 1.2 (Random.State.float rnd 1.) in
    let target = v (0.1 +. Random.State.float rnd 0.8) 0. (0.1 +. Random.State.float rnd 0.8) in
    let d = Vec.normalize (Vec.sub target o) in
    let t = Hfield.depth w h o d 1e-4 in
    (* brute force: march in field space until below the surface *)
    let step = 1e-4 in
    let rec march s =
      if s > 3. then infinity
      else
        let q = Transform.inv_point h.tr (Vec.add o (Vec.scale s d)) in
        if q.x >= 0. && q.x < float_of_int (f.width - 1) && q.z >= 0. && q.z < float_of_int (f.height - 1) && q.y < surface f q.x q.z then s
        else march (s +. step)
    in
    let expected = march 0. in
    if expected = infinity then Alcotest.(check bool) "no hit" true (t = infinity)
    else begin
      float_eq ~eps:(2. *. step) "depth against sampling" expected t;
      let q = Transform.inv_point h.tr (Vec.add o (Vec.scale t d)) in
      float_eq ~eps:1e-3 "on the surface (height steps)" (surface f q.x q.z) q.y
    end
  done

(* a CSG member walks every cell: its hits alternate in and out of the surface *)
let test_all_hits () =
  let h = synthetic 30 25 bumpy in
  let w = scratch () in
  let o = v (-0.1) 0.5 0.5 and d = Vec.normalize (v 1. 0. 0.02) in
  let n = Hfield.hits w h 0 o d 1e-4 0 in
  Alcotest.(check bool) "several crossings" true (n >= 2);
  let first = w.hits.room.(0) in
  float_eq ~eps:1e-12 "the first is the nearest" (Hfield.depth w h o d 1e-4) first

let test_normals () =
  (* a tilted plane y = 1000·x + 500·z: every normal is the plane's *)
  let plane x z = 1000 + (1000 * x) + (500 * z) in
  let expected tr = Transform.normalize (Transform.normal tr (v (-1000.) 1. (-500.))) in
  let flat = synthetic 8 6 plane and smooth = synthetic ~smooth:true 8 6 plane in
  let w = scratch () in
  let o = v 0.4 1. 0.3 and d = v 0. (-1.) 0. in
  let t = Hfield.depth w flat o d 1e-4 in
  vec_eq ~eps:1e-12 "flat" (expected flat.tr) (Hfield.normal w flat w.part (Vec.add o (Vec.scale t d)));
  let t = Hfield.depth w smooth o d 1e-4 in
  (* the stored shorts truncate the vertex normals (their tiny y most, which the scaling then
     magnifies): close to the plane's, not exact *)
  vec_eq ~eps:1e-2 "smooth" (expected smooth.tr) (Hfield.normal w smooth w.part (Vec.add o (Vec.scale t d)))

let test_inside () =
  let h = synthetic 10 10 (fun _ _ -> 32768) in
  let y = 32768. /. 65536. in
  Alcotest.(check bool) "below" true (Hfield.inside h (v 0.5 (y -. 0.01) 0.5));
  Alcotest.(check bool) "above" false (Hfield.inside h (v 0.5 (y +. 0.01) 0.5));
  Alcotest.(check bool) "outside in x" false (Hfield.inside h (v 1.01 0.1 0.5));
  Alcotest.(check bool) "the far side is out" false (Hfield.inside h (v 1. 0.1 0.5));
  Alcotest.(check bool) "the near side is in" true (Hfield.inside h (v 0. 0.1 0.5));
  (* the bumpy field is 12000 high at vertex (6, 12); the water at 32768 raises it *)
  let p = v (6. /. 29.) 0.4 0.5 in
  Alcotest.(check bool) "above the dry surface" false (Hfield.inside (synthetic 30 25 bumpy) p);
  Alcotest.(check bool) "below the water" true (Hfield.inside (synthetic ~water:32768. 30 25 bumpy) p);
  Alcotest.(check bool) "above the water" false (Hfield.inside (synthetic ~water:32768. 30 25 bumpy) (v (6. /. 29.) 0.51 0.5))

let test_heights () =
  let grey max values = { Image_file.width = 2; height = 1; pixels = Grey { max; grey = values; alpha = None; lut = None }; premultiplied = false } in
  (* 16-bit grey: v/65535 in single precision, times 65535, truncated *)
  Alcotest.(check (array int)) "16-bit grey" [| 12345; 65535 |] (Hfield_reader.heights_of_image (grey 65535 [| 12345; 65535 |]));
  Alcotest.(check (array int)) "8-bit grey" [| 257 * 100; 65535 |] (Hfield_reader.heights_of_image (grey 255 [| 100; 255 |]));
  let rgb = { Image_file.width = 1; height = 1; pixels = Colour { max = 255; rgb = [| 3; 200; 9 |]; alpha = None; lut = None }; premultiplied = false } in
  Alcotest.(check (array int)) "8-bit colour: red high, green low" [| (3 * 256) + 200 |] (Hfield_reader.heights_of_image rgb);
  (* the image's bottom row is z = 0 *)
  let two = { Image_file.width = 1; height = 2; pixels = Grey { max = 255; grey = [| 10; 20 |]; alpha = None; lut = None }; premultiplied = false } in
  Alcotest.(check (array int)) "rows flipped" [| 20 * 257; 10 * 257 |] (Hfield_reader.heights_of_image two)

let test_blocks () =
  let h = synthetic 40 30 bumpy in
  (* √38 = 6 blocks of ⌈40/6⌉ = 7 cells, one more block as 6·7 ≥ 40; √28 = 5 of 6 *)
  Alcotest.(check (list int)) "grid" [ 6; 5; 7; 6 ] [ h.field.nbx; h.field.nbz; h.field.wbx; h.field.wbz ];
  let off = Hfield.with_hierarchy h.field false in
  Alcotest.(check (list int)) "no hierarchy" [ 1; 1 ] [ off.nbx; off.nbz ];
  let sealed = Hfield.with_hierarchy (Hfield.seal h.field) false in
  Alcotest.(check int) "sealed: kept" 6 sealed.nbx

let test_parse () =
  let h = field_of "height_field { png \"scenes/images/hf_grey8.png\" water_level 0.5 smooth hierarchy off translate y }" in
  float_eq "water" 32768. h.field.water;
  Alcotest.(check bool) "smooth" true h.field.smooth;
  Alcotest.(check int) "one block" 1 h.field.nbx;
  float_eq "translated" 1. h.tr.m31;
  expect_scene_error "function" "height_field { tiff \"x.tif\" }" ~line:1 ~col:16 ~sub:"not supported yet: 'tiff' images";
  expect_scene_error "missing file" "height_field { png \"no_such.png\" }" ~line:1 ~col:16 ~sub:"cannot find the image file"

let tests =
  [
    Alcotest.test_case "POV-Ray's trace(): flat field" `Quick test_pov_flat;
    Alcotest.test_case "POV-Ray's trace(): smooth field, scaled and rotated" `Quick test_pov_smooth;
    Alcotest.test_case "hits against brute-force sampling" `Quick test_brute_force;
    Alcotest.test_case "every crossing of a CSG member" `Quick test_all_hits;
    Alcotest.test_case "normals of a tilted plane" `Quick test_normals;
    Alcotest.test_case "Inside: below the surface and the water" `Quick test_inside;
    Alcotest.test_case "heights from image samples" `Quick test_heights;
    Alcotest.test_case "the block grid and hierarchy" `Quick test_blocks;
    Alcotest.test_case "parsing and its errors" `Quick test_parse;
  ]
