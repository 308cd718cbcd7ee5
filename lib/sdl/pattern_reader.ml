(* What pigments and normals share: the pattern keyword with its arguments, the pattern modifiers,
   turbulence and warps (POV-Ray 3.7's Parse_Pattern and Parse_Warp). A pattern is read as POV-Ray
   reads it: the pattern first, then any modifiers, each editing the pattern read so far. *)

open Token
open Reader
open Expr

type kind = Pigment_pattern | Normal_pattern

type header = {
  pat : Scene.pattern option;
  frequency : float;
  phase : float;
  wave : Scene.wave;
  warps : Scene.warp list;
  noise : int;
}

let plain = { pat = None; frequency = 1.; phase = 0.; wave = Ramp; warps = []; noise = 0 }
let f32 = Precision.f32

let default_turb = Warp.default_turb

(* Check_Turb: the classic turbulence is the list's last element, added there when missing *)
let with_classic_turb (ws : Scene.warp list) (edit : Scene.turb -> Scene.turb) =
  let rec go = function
    | [] -> [ Scene.Classic_turb (edit default_turb) ]
    | [ Scene.Classic_turb t ] -> [ Scene.Classic_turb (edit t) ]
    | w :: rest -> w :: go rest
  in
  go ws

let octaves_of f = max 1 (min 10 (int_of_float f))

let uv st what =
  let loc = peek_loc st in
  match parse_expr st with
  | V.Float f -> (f, f)
  | V.Vector [| a; b |] -> (a, b)
  | V.Vector a when Array.length a > 2 -> (a.(0), a.(1))
  | v -> Error.raise_at loc "expected a 2-term vector for %s but found %s" what (V.kind_name v)

let unit_vector st =
  let loc = peek_loc st in
  let v = parse_vector st in
  let len = Vec.length v in
  if len = 0. then Error.raise_at loc "a zero-length vector cannot be normalised";
  Vec.scale (1. /. len) v

(* Check_BH_Parameters, run when a repeating black hole gets its repeat or its turbulence: on each
   repeated axis the centre is at least the radius, and the repeat at least the centre plus the
   radius plus the uncertainty (with a warning), or ignored below 1e-10 *)
let check_black_hole st loc (centre : Vec.t) radius (repeat : Vec.t) (uncertainty : Vec.t option) =
  let u = Option.value uncertainty ~default:Vec.zero in
  let axis name c r u =
    if r > 0. then begin
      let c = if c < radius then radius else c in
      let r =
        if r < c +. radius +. u then begin
          let r = c +. radius +. u in
          warn st loc "black hole repeat vector %s too small; increased to %g" name r;
          r
        end
        else r
      in
      if r < Precision.epsilon then begin
        warn st loc "black hole repeat vector %s is less than %f; ignored" name (Precision.f32 Precision.epsilon);
        (c, 0.)
      end
      else (c, r)
    end
    else (c, r)
  in
  let cx, rx = axis "X" centre.x repeat.x u.x in
  let cy, ry = axis "Y" centre.y repeat.y u.y in
  let cz, rz = axis "Z" centre.z repeat.z u.z in
  (Vec.make cx cy cz, Vec.make rx ry rz)

(* warp { … } after the keyword: one warp, pushed on the head of the list (Parse_Warp) *)
let parse_warp st (ws : Scene.warp list) : Scene.warp list =
  open_block st "warp";
  let loc = peek_loc st in
  let w : Scene.warp =
    match peek st with
    | Ident "turbulence" ->
        advance st;
        let v = parse_vector st in
        let rec mods (t : Scene.turb) =
          match peek st with
          | Ident "octaves" -> advance st; mods { t with octaves = octaves_of (parse_float st) }
          | Ident "omega" -> advance st; mods { t with omega = f32 (parse_float st) }
          | Ident "lambda" -> advance st; mods { t with lambda = f32 (parse_float st) }
          | _ -> t
        in
        Turb_warp (mods { default_turb with turbulence = v })
    | Ident "repeat" ->
        advance st;
        let v = parse_vector st in
        let axes = List.filter (fun (_, c) -> c <> 0.) [ (0, v.x); (1, v.y); (2, v.z) ] in
        let axis, width =
          match axes with
          | [ (a, c) ] -> (a, c)
          | [] -> Error.raise_at loc "no axis specified in repeat"
          | _ -> Error.raise_at loc "can only repeat along 1 axis"
        in
        let rec mods offset flip =
          match peek st with
          | Ident "offset" -> advance st; mods (parse_vector st) flip
          | Ident "flip" ->
              advance st;
              let f = parse_vector st in
              let s c = if c <> 0. then -1. else 1. in
              mods offset (Vec.make (s f.x) (s f.y) (s f.z))
          | _ -> (offset, flip)
        in
        let offset, flip = mods Vec.zero (Vec.make 1. 1. 1.) in
        Repeat_warp { axis; width = f32 width; offset; flip }
    | Ident "black_hole" ->
        advance st;
        let centre = parse_vector st in
        ignore (accept st Comma);
        let radius = parse_float st in
        let rec mods (b : Scene.warp) =
          match (b, peek st) with
          | Black_hole r, Ident "strength" -> advance st; mods (Black_hole { r with strength = parse_float st })
          | Black_hole r, Ident "falloff" -> advance st; mods (Black_hole { r with power = parse_float st })
          | Black_hole r, Ident "inverse" -> advance st; mods (Black_hole { r with inverted = true })
          | Black_hole r, Ident "type" -> advance st; mods (Black_hole { r with bh_type = int_of_float (parse_float st) })
          | Black_hole r, Ident "repeat" ->
              advance st;
              let v = parse_vector st in
              let centre, repeat = check_black_hole st loc r.centre r.radius v r.uncertainty in
              mods (Black_hole { r with centre; repeat = Some repeat })
          | Black_hole r, Ident "turbulence" -> (
              advance st;
              let u = parse_vector st in
              match r.repeat with
              | None -> mods (Black_hole { r with uncertainty = Some u })
              | Some v ->
                  let centre, repeat = check_black_hole st loc r.centre r.radius v (Some u) in
                  mods (Black_hole { r with centre; repeat = Some repeat; uncertainty = Some u }))
          | _ -> b
        in
        mods (Black_hole { centre; radius; strength = 1.; power = 2.; inverted = false; bh_type = 0; repeat = None; uncertainty = None })
    | Ident (("cylindrical" | "spherical") as kw) ->
        advance st;
        let rec mods o e =
          match peek st with
          | Ident "orientation" -> advance st; mods (unit_vector st) e
          | Ident "dist_exp" -> advance st; mods o (parse_float st)
          | _ -> (o, e)
        in
        let orientation, dist_exp = mods (Vec.make 0. 0. 1.) 0. in
        if kw = "cylindrical" then Cylindrical_warp { orientation; dist_exp } else Spherical_warp { orientation; dist_exp }
    | Ident "toroidal" ->
        advance st;
        let rec mods o e r =
          match peek st with
          | Ident "orientation" -> advance st; mods (unit_vector st) e r
          | Ident "dist_exp" -> advance st; mods o (parse_float st) r
          | Ident "major_radius" -> advance st; mods o e (parse_float st)
          | _ -> (o, e, r)
        in
        let orientation, dist_exp, major_radius = mods (Vec.make 0. 0. 1.) 0. 1. in
        Toroidal_warp { orientation; dist_exp; major_radius }
    | Ident "planar" ->
        advance st;
        if peek st = RBrace then Planar_warp { orientation = Vec.make 0. 0. 1.; offset = 0. }
        else
          let orientation = unit_vector st in
          ignore (accept st Comma);
          Planar_warp { orientation; offset = parse_float st }
    | Ident "cubic" -> advance st; Cubic_warp
    | _ -> unexpected st "a warp type (turbulence, repeat, black_hole, cylindrical, spherical, toroidal, planar, cubic)"
  in
  close_block st "warp";
  w :: ws

(* a fractal's iterations run at every point: bounded by povml's limit *)
let iterations_of st loc f =
  (* stored unsigned, as POV-Ray's (int) cast into an unsigned int: a negative count is huge *)
  let n = int_of_float (Float.max (-1e18) (Float.min f 1e18)) in
  let n = if n < 0 then n + 4294967296 else n in
  if n > st.opts.limits.pattern_steps then
    Error.limit_at loc "%s iterations at every point are beyond povml's limit of %s pattern steps (raise it with --max-pattern-steps N)"
      (commas n) (commas st.opts.limits.pattern_steps);
  n

let fractal_defaults fkind iterations exponent : Scene.fractal =
  { fkind; iterations; exponent; interior_type = 0; exterior_type = 1; ifactor = 1.; efactor = 1. }

(* The keyword of a pattern that needs no list of colours or pigments, with its arguments; the
   block patterns (checker, hexagon, brick, square, triangular, cubic) are read by the caller.
   None when the next token is no such keyword. *)
let rec pattern_keyword st kind (h : header) : header option =
  let loc = peek_loc st in
  let set ?(wave = h.wave) ?(frequency = h.frequency) p = Some { h with pat = Some p; wave; frequency } in
  match peek st with
  | Ident "agate" -> advance st; Some { (Option.get (set (Agate 1.))) with warps = with_classic_turb h.warps Fun.id }
  | Ident "bozo" -> advance st; set Bozo
  | Ident "spotted" -> advance st; set Spotted
  | Ident "bumps" -> advance st; set Bumps
  | Ident "granite" -> advance st; set Granite
  | Ident "leopard" -> advance st; set Leopard
  | Ident "marble" -> advance st; set ~wave:Triangle_wave Marble
  | Ident "wood" -> advance st; set ~wave:Triangle_wave Wood
  | Ident "onion" -> advance st; set Onion
  | Ident "radial" -> advance st; set Radial
  | Ident "cells" -> advance st; set Cells
  | Ident "crackle" -> advance st; set (Crackle { form = Vec.make (-1.) 1. 0.; metric = 2.; offset = 0.; solid = false })
  | Ident "wrinkles" -> advance st; set Wrinkles
  | Ident "dents" -> advance st; set Dents
  | Ident "waves" -> advance st; set (Waves st.number_of_waves)
  | Ident "ripples" -> advance st; set (Ripples st.number_of_waves)
  | Ident "quilted" -> advance st; set ~frequency:0. (Quilted { control0 = 1.; control1 = 1. })
  | Ident "facets" ->
      if kind = Pigment_pattern then Error.raise_at loc "'facets' can only be used in a normal";
      advance st;
      set (Facets { fsize = 0.1; coords = 0.; fmetric = 2. })
  | Ident ("spiral1" | "spiral2" as kw) ->
      advance st;
      let arms = int_of_float (parse_float st) in
      set ~wave:Triangle_wave (if kw = "spiral1" then Spiral1 arms else Spiral2 arms)
  | Ident "planar" -> advance st; set Planar
  | Ident "boxed" -> advance st; set Boxed
  | Ident "spherical" -> advance st; set Spherical
  | Ident "cylindrical" -> advance st; set Cylindrical
  | Ident "aoi" -> advance st; set Aoi
  | Ident "average" -> advance st; set Average
  | Ident "mandel" ->
      advance st;
      let nl = peek_loc st in
      let n = iterations_of st nl (parse_float st) in
      set (Fractal (fractal_defaults Mandel n 2))
  | Ident "julia" ->
      advance st;
      let c = uv st "julia" in
      ignore (accept st Comma);
      let nl = peek_loc st in
      let n = iterations_of st nl (parse_float st) in
      set (Fractal (fractal_defaults (Julia (fst c, snd c)) n 2))
  | Ident "magnet" ->
      advance st;
      let tl = peek_loc st in
      let t = int_of_float (parse_float st) in
      let kind =
        match peek st with
        | Ident "mandel" ->
            advance st;
            if t <> 1 && t <> 2 then Error.raise_at tl "invalid magnet-mandel pattern type: valid types are 1 and 2";
            Scene.Magnet_mandel t
        | Ident "julia" ->
            advance st;
            if t <> 1 && t <> 2 then Error.raise_at tl "invalid magnet-julia pattern type: valid types are 1 and 2";
            let c = uv st "magnet julia" in
            ignore (accept st Comma);
            Magnet_julia (t, (fst c, snd c))
        | _ -> unexpected st "'mandel' or 'julia' after the magnet type"
      in
      let nl = peek_loc st in
      let n = iterations_of st nl (parse_float st) in
      set (Fractal (fractal_defaults kind n 0))
  | Ident "pavement" -> advance st; set (Pavement { side = 3; tile = 1; number = 1; exterior = 0; interior = 0; form = 0 })
  | Ident "tiling" ->
      advance st;
      let n = int_of_float (parse_float st) in
      set (Tiling n)
  | Ident "slope" -> advance st; set (Slope (parse_slope st))
  | Ident "gradient" ->
      advance st;
      let vl = peek_loc st in
      let v = parse_vector st in
      (* §17.5: the direction is normalised when parsed *)
      if Vec.length v = 0. then Error.raise_at vl "the gradient vector is <0,0,0>";
      set (Gradient (Vec.normalize v))
  | Ident (("image_map" | "bump_map" | "image_pattern") as kw) ->
      (* image_map only in a pigment, bump_map only in a normal; all three take frequency 0 *)
      (match (kw, kind) with
      | "image_map", Normal_pattern -> Error.raise_at loc "'image_map' can only be used in a pigment"
      | "bump_map", Pigment_pattern -> Error.raise_at loc "'bump_map' can only be used in a normal"
      | _ -> ());
      advance st;
      set ~frequency:0. (Image_reader.parse st kw)
  | Ident "pigment_pattern" ->
      (* pigment_pattern { PIGMENT }: the pigment read from a black one, its grey the value *)
      advance st;
      let p = st.read_pigment st in
      let gen = st.noise_generator in
      let grey q =
        let c, found = Pigment.colour_found gen p Patterns.no_hit q in
        if found then Precision.f32 ((0.297 *. c.red) +. (0.589 *. c.green) +. (0.114 *. c.blue)) else 0.
      in
      set (Pigment_pattern { grey; pshown = Dump.pigment p })
  | Ident "function" -> advance st; set (Function_pattern (Fn_reader.anonymous st))
  | Ident ("density_file" as s) ->
      not_supported loc (Printf.sprintf "'%s' as a pattern" s)
  | _ -> None

(* slope { <v> [, lo, hi] [altitude <v> [, lo, hi]] } or slope <v>, as POV-Ray stores it *)
and parse_slope st : Scene.slope =
  let loc = peek_loc st in
  let range what =
    let lo = if accept st Comma then parse_float st else 0. in
    let hi = if accept st Comma then parse_float st else 0. in
    if hi <> 0. && hi = lo then begin
      warn st loc "zero %s range, ignoring" what;
      (0., 0.)
    end
    else (lo, hi -. lo)
  in
  let slope_vector, slope_mod, altit_vector, altit_mod, point_at =
    if peek st = LBrace then begin
      advance st;
      let point_at = accept_ident st "point_at" in
      let sv = parse_vector st in
      let sm = range "slope" in
      let av, am =
        if is_ident st "altitude" then begin
          if point_at then Error.raise_at (peek_loc st) "'altitude' cannot be used with 'point_at' in a slope pattern";
          advance st;
          let av = parse_vector st in
          (av, range "gradient")
        end
        else (Vec.zero, (0., 0.))
      in
      close_block st "slope";
      (sv, sm, av, am, point_at)
    end
    else (parse_vector st, (0., 0.), Vec.zero, (0., 0.), false)
  in
  let base (v : Vec.t) =
    let c = [| v.x; v.y; v.z |] in
    let rec go i = if i = 3 then 0 else if c.(i) = 1. then i + 1 else if c.(i) = -1. then -(i + 1) else go (i + 1) in
    go 0
  in
  if point_at then
    { slope_vector; altit_vector; slope_base = 0; altit_base = 0; slope_len = 1.; altit_len = 0.; slope_mod; altit_mod; point_at }
  else
    let sl = Vec.length slope_vector and al = Vec.length altit_vector in
    let slope_vector = if sl <> 0. then Vec.normalize slope_vector else slope_vector in
    let altit_vector = if al <> 0. then Vec.normalize altit_vector else altit_vector in
    (* Tot_Len is single precision *)
    let tot = f32 (sl +. al) in
    if tot = 0. then Error.raise_at loc "zero length for both slope and gradient";
    let slope_len = sl /. tot in
    let altit_len = 1. -. slope_len in
    { slope_vector; altit_vector; slope_base = base slope_vector; altit_base = base altit_vector; slope_len; altit_len; slope_mod; altit_mod; point_at }

let only_in loc what where = Error.raise_at loc "'%s' can only be used in %s" what where

(* A modifier every pattern takes, or one of the pattern's own fields; None when the next token is
   not one. *)
let modifier st (h : header) : header option =
  let loc = peek_loc st in
  let field what where (edit : Scene.pattern -> Scene.pattern option) =
    advance st;
    match Option.bind h.pat edit with Some p -> Some { h with pat = Some p } | None -> only_in loc what where
  in
  match peek st with
  | Ident "turbulence" ->
      advance st;
      let v = parse_vector st in
      Some { h with warps = with_classic_turb h.warps (fun t -> { t with turbulence = v }) }
  | Ident "octaves" ->
      advance st;
      let n = octaves_of (parse_float st) in
      Some { h with warps = with_classic_turb h.warps (fun t -> { t with octaves = n }) }
  | Ident "omega" ->
      advance st;
      let w = f32 (parse_float st) in
      Some { h with warps = with_classic_turb h.warps (fun t -> { t with omega = w }) }
  | Ident "lambda" ->
      advance st;
      let l = f32 (parse_float st) in
      Some { h with warps = with_classic_turb h.warps (fun t -> { t with lambda = l }) }
  | Ident "warp" -> advance st; Some { h with warps = parse_warp st h.warps }
  | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
      let t = Place.op_transform (parse_op st) in
      Some { h with warps = Place.transform_warps h.warps t }
  (* §17.1: frequency, phase and the poly_wave exponent are stored in single precision *)
  | Ident "frequency" -> advance st; Some { h with frequency = f32 (parse_float st) }
  | Ident "phase" -> advance st; Some { h with phase = f32 (parse_float st) }
  | Ident "ramp_wave" -> advance st; Some { h with wave = Ramp }
  | Ident "triangle_wave" -> advance st; Some { h with wave = Triangle_wave }
  | Ident "sine_wave" -> advance st; Some { h with wave = Sine_wave }
  | Ident "scallop_wave" -> advance st; Some { h with wave = Scallop_wave }
  | Ident "cubic_wave" -> advance st; Some { h with wave = Cubic_wave }
  | Ident "poly_wave" ->
      advance st;
      let e = match h.wave with Poly_wave e -> e | _ -> 1. in
      Some { h with wave = Poly_wave (if float_follows st then f32 (parse_float st) else e) }
  | Ident "noise_generator" ->
      advance st;
      let n = int_of_float (parse_float st) in
      if n < 0 || n > 3 then Error.raise_at loc "the value for noise_generator must be 0, 1, 2 or 3";
      Some { h with noise = n }
  | Ident "agate_turb" ->
      advance st;
      let v = f32 (parse_float st) in
      (match h.pat with Some (Agate _) -> () | _ -> Error.raise_at loc "'agate_turb' cannot be used with a non-agate pattern");
      Some { h with pat = Some (Agate v); warps = with_classic_turb h.warps Fun.id }
  | Ident "brick_size" -> (
      advance st;
      let v = parse_vector st in
      match h.pat with
      | Some (Brick b) -> Some { h with pat = Some (Brick { b with size = v }) }
      | _ -> Error.raise_at loc "'brick_size' is only valid in a brick pattern")
  | Ident "mortar" -> (
      advance st;
      let m = parse_float st in
      match h.pat with
      | Some (Brick b) -> Some { h with pat = Some (Brick { b with mortar = f32 (m -. 2e-10) }) }
      | _ -> Error.raise_at loc "'mortar' is only valid in a brick pattern")
  | Ident "solid" -> field "solid" "crackle" (function Crackle c -> Some (Crackle { c with solid = true }) | _ -> None)
  | Ident "offset" ->
      advance st;
      let o = parse_float st in
      (match h.pat with Some (Crackle c) -> Some { h with pat = Some (Crackle { c with offset = o }) } | _ -> only_in loc "offset" "crackle")
  | Ident "metric" -> (
      advance st;
      (* a vector for backwards compatibility: only its x is used *)
      let m = (parse_vector st).x in
      match h.pat with
      | Some (Crackle c) -> Some { h with pat = Some (Crackle { c with metric = m }) }
      | Some (Facets f) -> Some { h with pat = Some (Facets { f with fmetric = m }) }
      | _ -> only_in loc "metric" "facets or crackle")
  | Ident "form" -> (
      advance st;
      match h.pat with
      | Some (Crackle c) -> Some { h with pat = Some (Crackle { c with form = parse_vector st }) }
      | Some (Pavement p) -> Some { h with pat = Some (Pavement { p with form = int_of_float (parse_float st) land 255 }) }
      | _ -> only_in loc "form" "crackle or pavement")
  | Ident "coords" -> (
      advance st;
      let c = parse_float st in
      match h.pat with Some (Facets f) -> Some { h with pat = Some (Facets { f with coords = c }) } | _ -> only_in loc "coords" "facets")
  | Ident "size" -> (
      advance st;
      let s = parse_float st in
      match h.pat with Some (Facets f) -> Some { h with pat = Some (Facets { f with fsize = s }) } | _ -> only_in loc "size" "facets")
  | Ident ("control0" | "control1" as kw) -> (
      advance st;
      let c = f32 (parse_float st) in
      match h.pat with
      | Some (Quilted { control0; control1 }) ->
          let control0, control1 = if kw = "control0" then (c, control1) else (control0, c) in
          Some { h with pat = Some (Quilted { control0; control1 }) }
      | _ -> Error.raise_at loc "'%s' cannot be used with this pattern" kw)
  | Ident "exponent" -> (
      advance st;
      let el = loc in
      let e = int_of_float (parse_float st) in
      match h.pat with
      | Some (Fractal ({ fkind = Mandel | Julia _; _ } as f)) ->
          let e =
            if e >= 2 && e <= 33 then e
            else begin
              warn st el "invalid %s pattern exponent found; supported exponents are 2 to 33; using the default exponent 2"
                (match f.fkind with Mandel -> "mandel" | _ -> "julia");
              2
            end
          in
          Some { h with pat = Some (Fractal { f with exponent = e }) }
      | _ -> only_in loc "exponent" "mandel or julia")
  | Ident ("interior" | "exterior" as kw) -> (
      advance st;
      let t = int_of_float (parse_float st) in
      match h.pat with
      | Some (Pavement p) ->
          let interior, exterior = if kw = "interior" then (t land 255, p.exterior) else (p.interior, t land 255) in
          Some { h with pat = Some (Pavement { p with interior; exterior }) }
      | Some (Fractal f) ->
          if kw = "exterior" && (t < 0 || t > 8) then Error.raise_at loc "invalid fractal pattern exterior type: valid types are 0 to 8";
          if kw = "interior" && (t < 0 || t > 6) then Error.raise_at loc "invalid fractal pattern interior type: valid types are 0 to 6";
          ignore (accept st Comma);
          let factor = parse_float st in
          Some
            {
              h with
              pat =
                Some (Fractal (if kw = "interior" then { f with interior_type = t; ifactor = factor } else { f with exterior_type = t; efactor = factor }));
            }
      | _ -> only_in loc kw "mandel, julia, magnet or pavement")
  | Ident ("number_of_sides" | "number_of_tiles" | "pattern" as kw) -> (
      advance st;
      let n = int_of_float (parse_float st) land 255 in
      match h.pat with
      | Some (Pavement p) ->
          let side, tile, number =
            match kw with "number_of_sides" -> (n, p.tile, p.number) | "number_of_tiles" -> (p.side, n, p.number) | _ -> (p.side, p.tile, n)
          in
          Some { h with pat = Some (Pavement { p with side; tile; number }) }
      | _ -> only_in loc kw "pavement")
  | _ -> None

(* The checks Parse_Pattern makes at its end. *)
let finish st loc (h : header) =
  ignore st;
  match h.pat with
  | Some (Pavement { side; tile; number; exterior; interior; form }) ->
      let interior = interior mod 3 and exterior = exterior mod 3 in
      let check max_tiles valid =
        if tile < 1 || tile > max_tiles then Error.raise_at loc "number_of_tiles of pavement must be between 1 and %d" max_tiles
        else if number < 1 || number > valid.(tile - 1) then
          Error.raise_at loc "pattern value for pavement is out of range: the maximum per tile is (%s)"
            (String.concat "," (Array.to_list (Array.map string_of_int valid)))
      in
      let form =
        match side with
        | 4 -> check 6 [| 1; 1; 2; 5; 12; 35 |]; form mod 4
        | 6 -> check 5 [| 1; 1; 3; 7; 22 |]; form mod 3
        | 3 -> check 6 [| 1; 1; 1; 3; 4; 12 |]; form mod 3
        | _ -> Error.raise_at loc "number_of_sides of pavement must be 3, 4 or 6"
      in
      { h with pat = Some (Pavement { side; tile; number; exterior; interior; form }) }
  | Some (Tiling n) when n < 1 || n > 27 -> Error.raise_at loc "the tiling number must be between 1 and 27"
  | _ -> h
