(* Shape kinds (Traits): a scene shape (Shape_kind.of_shape) and the shape compiled from it
   (Shape.traits) have the same traits, and they say what the stages asked of each shape before
   (which shapes the scene's search tests after their box, whose box test is free, which inverse
   sets the flag, which take sturm). *)

open Helpers

let v37 = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"

let bezier_points =
  "<-1.5, 0, -1.5>, <-0.5, 1, -1.5>, <0.5, -1, -1.5>, <1.5, 0, -1.5>, <-1.5, 0.5, -0.5>, <-0.5, 1.5, -0.5>, <0.5, 0.5, -0.5>, <1.5, 0, -0.5>, \
   <-1.5, -0.5, 0.5>, <-0.5, 0, 0.5>, <0.5, 1.5, 0.5>, <1.5, 0.5, 0.5>, <-1.5, 0, 1.5>, <-0.5, -0.5, 1.5>, <0.5, 0.5, 1.5>, <1.5, 0, 1.5>"

let parametric =
  "parametric { function { cos(u)*(1 + 0.35*cos(v)) }, function { 0.35*sin(v) }, function { sin(u)*(1 + 0.35*cos(v)) } \
   <0, 0>, <2*pi, 2*pi> contained_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } } }"

(* each shape as written, its traits' name, costly, box test free, inverse sets the flag, its
   Inside holds the inversion, a patch, how it reads sturm *)
let kinds : (string * string * bool * bool * bool * bool * bool * Traits.sturm) list =
  [
    ("sphere { 0, 1 }", "sphere", false, true, true, false, false, No_sturm);
    ("sphere { 0, 1 translate x }", "sphere", false, true, true, false, false, No_sturm);
    ("sphere { 0, 1 scale <1, 2, 3> }", "sphere", true, true, true, false, false, No_sturm);
    ("plane { y, 1 }", "plane", false, true, false, false, false, No_sturm);
    ("plane { y, 1 matrix <1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0> }", "plane", false, true, false, false, false, No_sturm);
    ("triangle { 0, x, y }", "triangle", false, true, true, false, true, No_sturm);
    ("smooth_triangle { 0, z, x, z, y, z }", "smooth_triangle", false, true, true, false, true, No_sturm);
    ("mesh { triangle { 0, x, y } }", "mesh", false, false, true, false, false, No_sturm);
    ("box { 0, 1 }", "box", false, true, true, false, false, No_sturm);
    ("box { 0, 1 rotate y*30 }", "box", true, true, true, false, false, No_sturm);
    ("cylinder { 0, y, 1 }", "cone", true, false, true, false, false, No_sturm);
    ("cone { 0, 1, y, 0.5 }", "cone", true, false, true, false, false, No_sturm);
    ("disc { 0, y, 1 }", "disc", true, false, true, false, false, No_sturm);
    ("torus { 1, 0.25 }", "torus", true, false, true, false, false, Sturm_flag);
    ("text { ttf \"timrom.ttf\" \"o\" 0.2, 0 }", "glyph", true, false, true, false, false, No_sturm);
    ("polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 0> }", "polygon", true, false, false, false, false, No_sturm);
    ("quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }", "quadric", true, false, true, true, false, No_sturm);
    ("quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1> }", "poly", true, true,
      true, false, false, Sturm_bool);
    ("blob { sphere { 0, 1, 1 } }", "blob", true, false, true, false, false, Sturm_float);
    ("superellipsoid { <0.5, 0.5> }", "superellipsoid", true, false, true, false, false, No_sturm);
    ("ovus { 1, 0.6 }", "ovus", true, false, true, false, false, Sturm_bool);
    ("sphere_sweep { linear_spline 2, 0, 0.3, x, 0.5 }", "sphere_sweep", true, false, true, false, false, No_sturm);
    ("prism { 0, 1, 5, <-1,-1>, <1,-1>, <1,1>, <-1,1>, <-1,-1> }", "prism", true, false, true, false, false, Sturm_flag);
    ("lathe { linear_spline 2, <1,0>, <1,2> }", "lathe", true, false, true, false, false, Sturm_flag);
    ("sor { 4, <1,-1>, <1,0>, <1,2>, <1,3> }", "sor", true, false, true, false, false, Sturm_flag);
    ("isosurface { function { x } }", "isosurface", true, false, true, false, false, No_sturm);
    ("julia_fractal { <-0.083, 0.0, -0.83, -0.025> }", "julia_fractal", true, false, false, true, false, No_sturm);
    (parametric, "parametric", true, false, false, false, true, No_sturm);
    ("bicubic_patch { type 1 flatness 0.05 u_steps 3 v_steps 3 " ^ bezier_points ^ " }", "bicubic_patch", true, false, false, false, true, No_sturm);
    ("merge { sphere { 0, 1 } sphere { x, 1 } }", "csg", false, false, true, true, false, No_sturm);
  ]

let test_kinds () =
  List.iter
    (fun (text, name, costly, free, flag, holds, patch, sturm) ->
      let s = (List.hd (scene (v37 ^ text)).objects).shape in
      let c = (compile (v37 ^ text)).objects.(0).shape in
      let t = Shape_kind.of_shape s in
      Alcotest.(check bool) (text ^ ": the compiled shape's traits are the scene shape's") true (Shape.traits c == t);
      Alcotest.(check string) (text ^ ": name") name t.name;
      Alcotest.(check bool) (text ^ ": costly") costly (Shape.costly c);
      Alcotest.(check bool) (text ^ ": box test free") free (Shape.box_test_free c);
      Alcotest.(check bool) (text ^ ": inverse sets the flag") flag t.inverse_flag;
      Alcotest.(check bool) (text ^ ": its Inside holds the inversion") holds t.inside_holds_inverse;
      Alcotest.(check bool) (text ^ ": a patch") patch t.patch;
      Alcotest.(check bool) (text ^ ": sturm") true (t.sturm = sturm);
      Alcotest.(check bool) (text ^ ": scaled as a matrix") (name = "smooth_triangle") t.scale_by_matrix)
    kinds

(* the height field, read from the repository's image *)
let test_height_field () =
  let root = Lazy.force Test_hfield.root in
  let opts = { opts with access = Access.allow_read opts.access root } in
  let s, _ = Interp.load_string opts ~file:(Filename.concat root "t.pov") "height_field { png \"scenes/images/hf_grey8.png\" }" in
  let s = (List.hd s.objects).shape in
  let t = Shape_kind.of_shape s in
  Alcotest.(check string) "name" "height_field" t.name;
  match Shape.compile ~iso_slot:0 s with
  | Some c ->
      Alcotest.(check bool) "the compiled shape's traits" true (Shape.traits c == t);
      Alcotest.(check bool) "costly" true (Shape.costly c)
  | None -> Alcotest.fail "expected a height field"

(* a clipped or bounded shape's box test is free when its own is *)
let test_wrapped () =
  let free text = Shape.box_test_free (compile (v37 ^ text)).objects.(0).shape in
  Alcotest.(check bool) "clipped sphere" true (free "sphere { 0, 1 clipped_by { plane { y, 0 } } }");
  Alcotest.(check bool) "clipped torus" false (free "torus { 1, 0.25 clipped_by { plane { y, 0 } } }")

let tests =
  [
    Alcotest.test_case "every kind" `Quick test_kinds;
    Alcotest.test_case "height field" `Quick test_height_field;
    Alcotest.test_case "under clipped_by" `Quick test_wrapped;
  ]
