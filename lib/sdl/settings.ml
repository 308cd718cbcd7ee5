(* Camera, global settings, sky_sphere and background (docs/povray-rules.md §1, §7, §8). *)

open Token
open Reader
open Expr
open Materials

(* §1.3: POV-Ray's π/360 (M_PI_360, 0.00872664625997164788), by which the angle is multiplied: A·(π/360)
   and (A·π)/360 can differ in the last bit (they do for A = 48), and so can every camera ray. *)
let m_pi_360 = Float.pi /. 360.

let empty_camera =
  { c_location = None; c_direction = None; c_up = None; c_right = None; c_sky = None; c_look_at = None; c_angle = None; c_trans = None; c_ortho = false }

(* POV-Ray's camera types other than perspective and orthographic (Parse_Camera in parse.cpp). *)
let other_projections = [ "fisheye"; "ultra_wide_angle"; "omnimax"; "panoramic"; "spherical"; "cylinder"; "mesh_camera" ]

let parse_camera st =
  open_block st "camera";
  let base, from_identifier =
    match peek st with
    | Ident s -> ( match cur_value st s with Some (V.Camera c) -> advance st; (c, true) | _ -> (empty_camera, false))
    | _ -> (empty_camera, false)
  in
  (* Focal blur: POV-Ray blurs only when the aperture is not 0 and blur_samples was given
     (tracepixel.cpp: useFocalBlur), so focal_point, confidence, variance and bokeh change nothing
     without both. The last aperture written counts; after a camera identifier, whose aperture
     and samples povml does not keep, either of them is taken as turning the blur on. *)
  let aperture = ref None and samples = ref None in
  let rec loop c =
    let loc = peek_loc st in
    match peek st with
    | RBrace ->
        let blur_at =
          match (!aperture, !samples) with
          | Some (a, l), Some _ when a <> 0. -> Some l
          | Some (a, l), None when a <> 0. && from_identifier -> Some l
          | (None | Some _), Some l when from_identifier && (match !aperture with Some (a, _) -> a <> 0. | None -> true) -> Some l
          | (None | Some _), (None | Some _) -> None
        in
        (match blur_at with Some l -> not_supported l "focal blur (a camera with a nonzero aperture and blur_samples)" | None -> ());
        advance st;
        c
    | Ident "perspective" -> advance st; loop { c with c_ortho = false }
    | Ident "orthographic" -> advance st; loop { c with c_ortho = true }
    | Ident s when List.mem s other_projections -> not_supported loc (Printf.sprintf "'%s' in a camera (the %s projection)" s s)
    | Ident "location" -> advance st; loop { c with c_location = Some (parse_vector st) }
    | Ident "direction" -> advance st; loop { c with c_direction = Some (parse_vector st) }
    | Ident "up" -> advance st; loop { c with c_up = Some (parse_vector st) }
    | Ident "right" -> advance st; loop { c with c_right = Some (parse_vector st) }
    | Ident "sky" -> advance st; loop { c with c_sky = Some (parse_vector st) }
    | Ident "look_at" -> advance st; let l = peek_loc st in loop { c with c_look_at = Some (parse_vector st, l) }
    | Ident "angle" -> advance st; let l = peek_loc st in loop { c with c_angle = Some (parse_float st, l) }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let t = Place.op_transform (parse_op st) in
        loop { c with c_trans = Some (match c.c_trans with None -> t | Some t0 -> Transform.compose t0 t) }
    | Ident "aperture" -> advance st; aperture := Some (parse_float st, loc); loop c
    | Ident "blur_samples" ->
        (* blur_samples [MIN,] MAX, both truncated to integers (Parse_Camera_Mods) *)
        advance st;
        let l = peek_loc st in
        let first = int_of_float (c_int (parse_float st)) in
        if first <= 0 then Error.raise_at l "illegal number of focal blur samples: %d (it must be at least 1)" first;
        skip_comma st;
        let ml = peek_loc st in
        let second = if float_follows st then int_of_float (c_int (parse_float st)) else 0 in
        if second <> 0 && first > second then
          Error.raise_at ml "focal blur samples minimum %d must not be larger than maximum %d" first second;
        samples := Some loc;
        loop c
    | Ident "focal_point" -> advance st; ignore (parse_vector st); loop c
    | Ident "confidence" ->
        advance st;
        let l = peek_loc st in
        let k = parse_float st in
        if not (k > 0. && k < 1.) then warn st l "Illegal confidence value. Default is used.";
        loop c
    | Ident "variance" ->
        advance st;
        let l = peek_loc st in
        let k = parse_float st in
        if not (k >= 0. && k <= 1.) then warn st l "Illegal variance value. Default is used.";
        loop c
    | Ident "bokeh" ->
        (* bokeh { pigment { … } … }: the shape of the blur, read and unused without blur *)
        advance st;
        open_block st "bokeh";
        let rec pigments () = if accept_ident st "pigment" then (ignore (parse_pigment st (Scene.Solid Colour.black)); pigments ()) in
        pigments ();
        close_block st "bokeh";
        loop c
    | Ident s when is_unsupported s || s = "normal" (* a perturbed camera *) -> not_supported loc (Printf.sprintf "'%s' in a camera" s)
    | _ -> unexpected st "a camera keyword or '}'"
  in
  loop base

(* §1.3: the camera modifiers are applied in a fixed order, whatever order they were written in. *)
let build_camera st (c : camera_spec) : Scene.camera =
  let location = Option.value c.c_location ~default:Vec.zero in
  let direction = Option.value c.c_direction ~default:(Vec.make 0. 0. 1.) in
  let up = Option.value c.c_up ~default:(Vec.make 0. 1. 0.) in
  let right = Option.value c.c_right ~default:(Vec.make 1.33 0. 0.) in
  let sky = Option.value c.c_sky ~default:(Vec.make 0. 1. 0.) in
  let direction =
    match c.c_angle with
    | None -> direction
    | Some (a, loc) ->
        if a >= 180. then Error.raise_at loc "camera angle must be less than 180 degrees, not %g" a;
        if a <= 0. then Error.raise_at loc "camera angle must be greater than 0 degrees, not %g" a;
        Vec.scale (Vec.length right /. tan (a *. m_pi_360) /. 2.) (Vec.normalize direction)
  in
  let direction, right, up =
    match c.c_look_at with
    | None -> (direction, right, up)
    | Some (p, loc) ->
        let dl = Vec.length direction and ul = Vec.length up and rl = Vec.length right in
        let handedness = Vec.dot (Vec.cross up direction) right in
        let dv = Vec.sub p location in
        if Vec.length2 dv < 1e-10 then Error.raise_at loc "camera look_at point is the same as the location";
        let d = Vec.normalize dv in
        let r = Vec.cross sky d in
        let r =
          if Float.abs r.x < 1e-10 && Float.abs r.y < 1e-10 && Float.abs r.z < 1e-10 then begin
            warn st loc "camera location and look_at are in line with the sky vector; the old right vector is kept";
            right
          end
          else r
        in
        let r = Vec.normalize r in
        let u = Vec.cross d r in
        (Vec.scale dl d, Vec.scale (if handedness > 0. then rl else -.rl) r, Vec.scale ul u)
  in
  (* §18.4: an orthographic camera without up and right, or with an angle, sees as wide as the
     perspective one would at the look_at distance: right and up scaled by k1/k2 *)
  let right, up =
    if c.c_ortho && ((c.c_up = None && c.c_right = None) || c.c_angle <> None) then
      let look_at = match c.c_look_at with Some (p, _) -> p | None -> Vec.make 0. 0. 1. in
      let k1 = Vec.length (Vec.sub look_at location) and k2 = Vec.length direction in
      if k1 > 1e-10 && k2 > 1e-10 then (Vec.scale (k1 /. k2) right, Vec.scale (k1 /. k2) up) else (right, up)
    else (right, up)
  in
  let projection = if c.c_ortho then Scene.Orthographic else Scene.Perspective in
  match c.c_trans with
  | None -> { Scene.location; direction; up; right; projection }
  | Some t ->
      (* §14.8: the location as a point, the other vectors as directions *)
      {
        Scene.location = Transform.point t location;
        direction = Transform.direction t direction;
        up = Transform.direction t up;
        right = Transform.direction t right;
        projection;
      }

(* §7: clipped to 1 … 256; POV-Ray warns above 256 (not below 1) *)
let parse_max_trace_level st loc =
  let n = int_of_float (c_int (parse_float st)) in
  if n > 256 then warn st loc "Maximum max_trace_level is 256 but %d was specified. Going to use max_trace_level 256." n;
  st.max_trace_level <- max 1 (min 256 n)

let parse_global_settings st =
  open_block st "global_settings";
  let rec loop () =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st
    | Ident "assumed_gamma" ->
        advance st;
        if is_ident st "srgb" then not_supported (peek_loc st) "'srgb' as the assumed_gamma";
        let g = parse_float st in
        if g <= 0. then Error.raise_at loc "assumed_gamma must be positive, not %g" g;
        (* Parse_Gamma (parstxtr.cpp) warns below 1 once the scene's gamma mode is set, which it
           is by then *)
        if g < 1. then warn st loc "Suspicious value %g specified for gamma. Did you mean %g?" g (1. /. g);
        if st.assumed_gamma = None then st.assumed_gamma <- Some g
        else warn st loc "new instance of assumed_gamma ignored";
        loop ()
    | Ident "max_trace_level" -> advance st; parse_max_trace_level st loc; loop ()
    | Ident "adc_bailout" -> advance st; st.adc_bailout <- parse_float st; loop ()
    | Ident "ambient_light" -> advance st; st.ambient_light <- parse_rgb st "ambient_light"; loop ()
    | Ident "number_of_waves" ->
        (* read and checked as POV-Ray does; waves and ripples read after it use it *)
        advance st;
        let l = peek_loc st in
        let n = c_int (parse_float st) in
        if n <= 0. then begin
          warn st l "Illegal Value: number_of_waves must be greater than 0. Changed to 1.";
          st.number_of_waves <- 1
        end
        else if n > float_of_int st.opts.limits.pattern_steps then
          Error.limit_at l "%s waves at every point are beyond povml's limit of %s pattern steps (raise it with --max-pattern-steps N)"
            (commas (int_of_float n)) (commas st.opts.limits.pattern_steps)
        else st.number_of_waves <- int_of_float n;
        loop ()
    | Ident "noise_generator" ->
        (* parse.cpp: 1, 2 or 3; anything else is an error *)
        advance st;
        let l = peek_loc st in
        let n = c_int (parse_float st) in
        if n < 1. || n > 3. then Error.raise_at l "the noise_generator must be 1, 2 or 3, not %g" n;
        st.noise_generator <- int_of_float n;
        loop ()
    | Ident "max_intersections" ->
        advance st;
        ignore (parse_float st);
        if st.version >= 370 then warn st loc "'max_intersections' is no longer needed and has no effect in POV-Ray 3.7 or later.";
        loop ()
    | Ident "hf_gray_16" ->
        (* POV-Ray 3.7 ignores it, with a warning: grey output is a command-line option there *)
        advance st;
        if float_follows st then ignore (parse_float st);
        warn st loc
          "In POV-Ray 3.7 and later 'hf_gray_16' has to be specified as an option on the command-line (e.g. '+FNg'), in an INI file (e.g. 'Grayscale_Output=true'), or (on some platforms) in a dialog. The 'hf_gray_16' setting here is ignored.";
        loop ()
    | Ident "mm_per_unit" ->
        (* the scale of subsurface scattering only, which povml does not have *)
        advance st; ignore (parse_float st); loop ()
    | Ident "irid_wavelength" ->
        advance st;
        let c = parse_rgb st "irid_wavelength" in
        st.irid_wavelength <- Rgb.make (Precision.f32 c.r) (Precision.f32 c.g) (Precision.f32 c.b);
        loop ()
    | Ident "charset" ->
        (* §15.9: ascii (the default), utf8 or sys *)
        advance st;
        (match peek st with
         | Ident "ascii" -> advance st; st.charset <- Ascii
         | Ident "utf8" -> advance st; st.charset <- Utf8
         | Ident "sys" -> advance st; st.charset <- Sys
         | _ -> unexpected st "a charset name (ascii, utf8 or sys)");
        loop ()
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in global_settings" s)
    | _ -> unexpected st "a global_settings keyword or '}'"
  in
  loop ()

(* The block of a sky_sphere after its keyword: a declared sky_sphere's identifier first, whose
   pigments the new ones are added to (Parse_Skysphere). *)
let parse_sky st : Scene.sky =
  let loc = peek_loc st in
  open_block st "sky_sphere";
  let base = Materials.ident_of_kind st (function V.Sky s -> Some s | _ -> None) in
  (* §18.1: the sky's transforms compose into its own transform, which the lookup point goes
     through before each pigment's *)
  let rec loop pigs emission trans =
    let l = peek_loc st in
    match peek st with
    | RBrace ->
        advance st;
        if pigs = [] then Error.raise_at loc "a sky_sphere needs at least one pigment";
        { Scene.sky_pigments = List.rev pigs; sky_emission = emission; sky_trans = trans }
    | Ident "pigment" -> advance st; loop (parse_pigment st (Scene.Solid Colour.black) :: pigs) emission trans
    | Ident "emission" -> advance st; loop pigs (parse_rgb st "sky_sphere emission") trans
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let op = Place.op_transform (parse_op st) in
        loop pigs emission (Some (Transform.compose (Option.value trans ~default:Transform.identity) op))
    | Ident s when is_unsupported s -> not_supported l (Printf.sprintf "'%s' in a sky_sphere" s)
    | _ -> unexpected st "'pigment' or '}' in a sky_sphere"
  in
  match base with
  | None -> loop [] Rgb.white None
  | Some b -> loop (List.rev b.sky_pigments) b.sky_emission b.sky_trans

let parse_sky_sphere st =
  let loc = peek_loc st in
  advance st;
  if st.sky <> None then warn st loc "a second sky_sphere replaces the first";
  st.sky <- Some (parse_sky st)

(* §8.1: the version POV-Ray's renderer sees so far: 3.62 until a #version has been read. *)
let effective_version st = if st.version_set then st.version else 362

let parse_background st =
  advance st;
  open_block st "background";
  let c = parse_colour st in
  close_block st "background";
  (* §8.4: from 3.70 the transmit is folded into rgb; before, filter and transmit become 0 *)
  st.background <-
    Some
      (if effective_version st >= 370 then
         { Colour.red = c.red *. (1. -. c.transmit); green = c.green *. (1. -. c.transmit); blue = c.blue *. (1. -. c.transmit); filter = 0.; transmit = 0. }
       else { c with filter = 0.; transmit = 0. })


(* radiosity { importance I … }, in #default and in objects: read and checked, only radiosity
   reads it (Parse_Default, Parse_Object_Mods) *)
let parse_radiosity_importance st =
  open_block st "radiosity";
  while is_ident st "importance" do
    advance st;
    let l = peek_loc st in
    let i = parse_float st in
    if not (i > 0. && i <= 1.) then Error.raise_at l "radiosity importance must be greater than 0 and at most 1, not %g" i
  done;
  close_block st "radiosity"
