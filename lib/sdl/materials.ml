(* Pigments, finishes, textures and interiors (POVRAY-3.7 §5, §10.1). *)

open Token
open Reader
open Expr



let ident_of_kind st f =
  match peek st with
  | Ident s -> ( match cur_value st s with Some v -> (match f v with Some r -> advance st; Some r | None -> None) | None -> None)
  | _ -> None

let parse_pigment st (base : Scene.pigment) : Scene.pigment =
  open_block st "pigment";
  let p =
    match ident_of_kind st (function V.Pigment p -> Some p | _ -> None) with
    | Some p -> p
    | None -> base
  in
  let rec loop p =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; p
    | Ident s when is_colour_start st -> ignore s; loop (Scene.Solid (parse_colour st))
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        (* a plain colour is the same everywhere: the pattern transform changes nothing yet *)
        ignore (parse_op st);
        loop p
    | Ident ("quick_color" | "quick_colour") -> advance st; ignore (parse_colour st); loop p
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a pigment" s)
    | _ -> unexpected st "a colour or '}' in a pigment"
  in
  loop p

let parse_reflection_block st (r : Scene.reflection) : Scene.reflection =
  (* reflection { MIN [, MAX] [fresnel [b]] [falloff F] [exponent E] [metallic [M]] } (§5.1) *)
  open_block st "reflection";
  let r, one_colour =
    if peek st == RBrace then (r, false)
    else
      let mn = parse_rgb st "reflection" in
      if accept st Comma then ({ r with rmin = mn; rmax = parse_rgb st "reflection" }, false)
      else ({ r with rmin = mn; rmax = mn }, true)
  in
  let rec loop (r : Scene.reflection) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; r
    | Ident "fresnel" -> advance st; loop { r with fresnel = parse_bool_opt st }
    | Ident "falloff" -> advance st; loop { r with falloff = parse_float st }
    | Ident "exponent" -> advance st; loop { r with exponent = parse_float st }
    | Ident "metallic" -> advance st; loop { r with refl_metallic = (if float_follows st then parse_float st else 1.) }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in reflection" s)
    | _ -> unexpected st "'fresnel', 'falloff', 'exponent', 'metallic' or '}' in reflection"
  in
  let r = loop r in
  (* §5.1: with fresnel and a single colour, that colour is the maximum and the minimum is 0 *)
  if r.fresnel && one_colour then { r with rmin = Rgb.black } else r

let parse_finish st (base : Scene.finish) : Scene.finish =
  open_block st "finish";
  let f = match ident_of_kind st (function V.Finish f -> Some f | _ -> None) with Some f -> f | None -> base in
  let diffuse_albedo = ref false and phong_albedo = ref false and specular_albedo = ref false in
  let rec loop (f : Scene.finish) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; f
    | Ident "ambient" -> advance st; loop { f with ambient = parse_rgb st "ambient" }
    | Ident "emission" -> advance st; loop { f with emission = parse_rgb st "emission" }
    | Ident "diffuse" ->
        advance st;
        diffuse_albedo := accept_ident st "albedo";
        let d = parse_float st in
        if accept st Comma then begin
          let l = peek_loc st in
          let back = parse_float st in
          if back <> 0. then not_supported l "a back-side diffuse value"
        end;
        loop { f with diffuse = d }
    | Ident "brilliance" -> advance st; loop { f with brilliance = parse_float st }
    | Ident "phong" -> advance st; phong_albedo := accept_ident st "albedo"; loop { f with phong = parse_float st }
    | Ident "phong_size" -> advance st; loop { f with phong_size = parse_float st }
    | Ident "specular" -> advance st; specular_albedo := accept_ident st "albedo"; loop { f with specular = parse_float st }
    | Ident "roughness" ->
        advance st;
        let r = parse_float st in
        if r = 0. then warn st loc "zero roughness used";
        loop { f with roughness = r }
    | Ident "metallic" -> advance st; loop { f with metallic = (if float_follows st then parse_float st else 1.) }
    | Ident "reflection" ->
        advance st;
        if peek st == LBrace then loop { f with reflection = parse_reflection_block st f.reflection }
        else
          (* old syntax: min = max = value, falloff 1, type 0 (§5.1) *)
          let c = parse_rgb st "reflection" in
          loop { f with reflection = { f.reflection with rmin = c; rmax = c; falloff = 1.; fresnel = false } }
    | Ident "reflection_exponent" -> advance st; loop { f with reflection = { f.reflection with exponent = parse_float st } }
    | Ident "conserve_energy" -> advance st; loop { f with conserve_energy = parse_bool_opt st }
    | Ident "refraction" ->
        advance st;
        warn st loc "refraction value unnecessary to turn on refraction; to attenuate, the fade_power and fade_distance keywords should be specified in 'interior{...}'";
        loop { f with refraction = parse_float st }
    | Ident "ior" ->
        advance st;
        warn st loc "index of refraction value should be specified in 'interior{...}' statement";
        loop { f with legacy_ior = Some (parse_float st) }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a finish" s)
    | _ -> unexpected st "a finish keyword or '}'"
  in
  let f = loop f in
  (* albedo forms are converted with the final values (§10.1) *)
  let f = if !diffuse_albedo then { f with diffuse = f.diffuse *. (f.brilliance +. 1.) /. 2. } else f in
  let f = if !phong_albedo then { f with phong = f.phong *. (f.phong_size +. 1.) /. 2. } else f in
  let f =
    if !specular_albedo then
      let e = 1. /. f.roughness in
      { f with specular = f.specular *. (e +. 2.) /. (4. *. (2. -. Float.pow 2. (-.e /. 2.))) }
    else f
  in
  f

let parse_texture st (base : Scene.texture) : Scene.texture =
  open_block st "texture";
  let t = match ident_of_kind st (function V.Texture t -> Some t | _ -> None) with Some t -> t | None -> base in
  let rec loop (t : Scene.texture) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; t
    | Ident "pigment" -> advance st; loop { t with pigment = parse_pigment st t.pigment }
    | Ident "finish" -> advance st; loop { t with finish = parse_finish st t.finish }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") -> ignore (parse_op st); loop t
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a texture" s)
    | _ -> unexpected st "'pigment', 'finish' or '}' in a texture"
  in
  loop t

let parse_interior st (base : Scene.interior) : Scene.interior =
  open_block st "interior";
  let i = match ident_of_kind st (function V.Interior i -> Some i | _ -> None) with Some i -> i | None -> base in
  let rec loop (i : Scene.interior) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; i
    | Ident "ior" -> advance st; loop { i with ior = parse_float st }
    | Ident "fade_distance" -> advance st; loop { i with fade_distance = parse_float st }
    | Ident "fade_power" -> advance st; loop { i with fade_power = parse_float st }
    | Ident ("fade_color" | "fade_colour") -> advance st; loop { i with fade_colour = parse_rgb st "fade_color" }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in an interior" s)
    | _ -> unexpected st "'ior', 'fade_distance', 'fade_power', 'fade_color' or '}' in an interior"
  in
  loop i

