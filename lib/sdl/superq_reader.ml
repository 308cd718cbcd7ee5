(* Readers of superellipsoid (Parse_Superellipsoid), ovus (Parse_Ovus) and sphere_sweep
   (Parse_Sphere_Sweep), after the keyword and its '{'. *)

open Reader

let superellipsoid st =
  let e, n = Spline_reader.uv_vector st in
  Scene.Superellipsoid (Superellipsoid.make e n)

(* Parse_Ovus: bottom radius, top radius; a top radius of twice the bottom one or more makes a
   sphere of the top radius at the bottom radius's height instead, with POV-Ray's warning *)
let ovus st loc =
  let bottom = Expr.parse_float st in
  skip_comma st;
  let top = Expr.parse_float st in
  if top < 0. || bottom < 0. then Error.raise_at loc "Both Ovus radii must be positive";
  match Ovus.set_up bottom top with
  | Some v -> Scene.Ovus v
  | None ->
      warn st loc "Ovus second radius should be less than twice first radius: a sphere replaces the ovus, as in POV-Ray";
      Scene.Sphere { centre = Vec.make 0. bottom 0.; radius = top; trans = None; uv_trans = None }

(* Parse_Sphere_Sweep: the interpolation keyword, the number of modeling spheres (truncated), at
   least 2, or 4 for the cubic kinds, each a centre and a radius, then an optional tolerance *)
let sphere_sweep st =
  let kind =
    match peek st with
    | Ident "linear_spline" -> advance st; Sphere_sweep.Linear
    | Ident "cubic_spline" -> advance st; Sphere_sweep.Catmull_rom
    | Ident "b_spline" -> advance st; Sphere_sweep.B_spline
    | _ -> Error.raise_at (peek_loc st) "Invalid type of interpolation."
  in
  skip_comma st;
  let nloc = peek_loc st in
  let n = Expr.c_int (Expr.parse_float st) in
  if n < 2. || (kind <> Sphere_sweep.Linear && n < 4.) then Error.raise_at nloc "Too few modeling spheres for interpolation type.";
  let spheres =
    read_items (int_of_float n) (fun _ ->
        skip_comma st;
        let c = Expr.parse_vector st in
        skip_comma st;
        let r = Expr.parse_float st in
        (c, r))
  in
  let tolerance =
    match peek st with
    | Ident "tolerance" -> advance st; Expr.parse_float st
    | _ -> Sphere_sweep.depth_tolerance
  in
  Scene.Sphere_sweep (Sphere_sweep.make kind spheres tolerance)
