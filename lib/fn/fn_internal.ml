(* POV-Ray 3.7's table of internal functions (fnintern.cpp's POVFPU_TrapTable): for each
   internal(k), functions.inc's name and the parameter count, and the implementation, found in
   Fn_algebraic, Fn_shapes or Fn_noise. *)

(* internal(k): name, parameter count (x, y, z included) *)
let table =
  [|
    ("f_algbr_cyl1", 8); ("f_algbr_cyl2", 8); ("f_algbr_cyl3", 8); ("f_algbr_cyl4", 8);
    ("f_bicorn", 5); ("f_bifolia", 5); ("f_blob", 8); ("f_blob2", 7); ("f_boy_surface", 5);
    ("f_comma", 4); ("f_cross_ellipsoids", 7); ("f_crossed_trough", 4); ("f_cubic_saddle", 4);
    ("f_cushion", 4); ("f_devils_curve", 4); ("f_devils_curve_2d", 9); ("f_dupin_cyclid", 9);
    ("f_ellipsoid", 6); ("f_enneper", 4); ("f_flange_cover", 7); ("f_folium_surface", 6);
    ("f_folium_surface_2d", 9); ("f_glob", 4); ("f_heart", 4); ("f_helical_torus", 13);
    ("f_helix1", 10); ("f_helix2", 10); ("f_hex_x", 4); ("f_hex_y", 4); ("f_hetero_mf", 9);
    ("f_hunt_surface", 4); ("f_hyperbolic_torus", 6); ("f_isect_ellipsoids", 7);
    ("f_kampyle_of_eudoxus", 6); ("f_kampyle_of_eudoxus_2d", 9); ("f_klein_bottle", 4);
    ("f_kummer_surface_v1", 4); ("f_kummer_surface_v2", 7); ("f_lemniscate_of_gerono", 4);
    ("f_lemniscate_of_gerono_2d", 9); ("f_mesh1", 8); ("f_mitre", 4); ("f_nodal_cubic", 4);
    ("f_odd", 4); ("f_ovals_of_cassini", 7); ("f_paraboloid", 4); ("f_parabolic_torus", 6);
    ("f_ph", 3); ("f_pillow", 4); ("f_piriform", 4); ("f_piriform_2d", 10); ("f_poly4", 8);
    ("f_polytubes", 9); ("f_quantum", 4); ("f_quartic_paraboloid", 4); ("f_quartic_saddle", 4);
    ("f_quartic_cylinder", 6); ("f_r", 3); ("f_ridge", 9); ("f_ridged_mf", 9);
    ("f_rounded_box", 7); ("f_sphere", 4); ("f_spikes", 8); ("f_spikes_2d", 7); ("f_spiral", 9);
    ("f_steiners_roman", 4); ("f_strophoid", 7); ("f_strophoid_2d", 10);
    ("f_superellipsoid", 5); ("f_th", 3); ("f_torus", 5); ("f_torus2", 6);
    ("f_torus_gumdrop", 4); ("f_umbrella", 4); ("f_witch_of_agnesi", 5);
    ("f_witch_of_agnesi_2d", 9); ("f_noise3d", 3); ("f_pattern", 3); ("f_noise_generator", 4);
  |]

let count = Array.length table

let entry k =
  if k < 0 || k >= count then invalid_arg (Printf.sprintf "Fn_internal: internal(%d) does not exist" k);
  table.(k)

let name k = fst (entry k)
let arity k = snd (entry k)

let loop_parameter k =
  match name k with "f_hetero_mf" | "f_ridged_mf" -> Some 5 | "f_ridge" -> Some 4 | "f_polytubes" -> Some 3 | _ -> None

let make ~noise_generator k =
  match Fn_algebraic.find k with
  | Some f -> Some f
  | None -> (
      match Fn_shapes.find k with
      | Some f -> Some f
      | None -> Fn_noise.make ~noise_generator k)
