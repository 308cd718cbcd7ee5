(* Pigments, finishes, textures and interiors (docs/povray-rules.md §5, §10.1). *)

open Token
open Reader
open Expr



let ident_of_kind st f =
  match peek st with
  | Ident s -> ( match cur_value st s with Some v -> (match f v with Some r -> advance st; Some r | None -> None) | None -> None)
  | _ -> None

(* color_map { [v COLOUR] … } or color_map { Id } (docs/povray-rules.md §17.3): entries in the order written,
   the old form [v1 v2 COLOUR1 COLOUR2] giving two; values and colours in single precision. *)
let parse_colour_map st what : Scene.map_entry array =
  let loc = peek_loc st in
  open_block st what;
  match ident_of_kind st (function V.Colour_map m -> Some m | _ -> None) with
  | Some m -> close_block st what; m
  | None ->
      let colour () =
        if is_colour_start st then parse_colour st
        else unexpected st (Printf.sprintf "a colour ('rgb …', 'color …' or a colour identifier) in a %s entry" what)
      in
      let rec entries acc n =
        match peek st with
        | RBrace -> advance st; List.rev acc
        | LBracket ->
            let el = peek_loc st in
            if n >= 256 then Error.raise_at el "a %s has at most 256 entries" what;
            advance st;
            let v = parse_float st in
            ignore (accept st Comma);
            let acc, n =
              if is_colour_start st then (Pigment.f32_entry v (colour ()) :: acc, n + 1)
              else if float_follows st then begin
                (* the old two-entry form *)
                let v2 = parse_float st in
                ignore (accept st Comma);
                let c1 = colour () in
                ignore (accept st Comma);
                let c2 = colour () in
                (Pigment.f32_entry v2 c2 :: Pigment.f32_entry v c1 :: acc, n + 2)
              end
              else (ignore (colour ()); (acc, n))
            in
            expect st RBracket (Printf.sprintf "']' closing a %s entry" what);
            entries acc n
        | Ident s when acc = [] && (match cur_value st s with Some (V.Unsupported _) | None -> false | Some _ -> true) ->
            let v = Option.get (cur_value st s) in
            Error.raise_at (peek_loc st) "'%s' is %s, not a color_map" s (V.kind_name v)
        | _ -> unexpected st (Printf.sprintf "'[' starting a %s entry, or '}'" what)
      in
      let es = entries [] 0 in
      if es = [] then Error.raise_at loc "a %s needs at least one entry" what;
      if List.length es > 256 then Error.raise_at loc "a %s has at most 256 entries" what;
      Array.of_list es

(* The entries of a map block after its '{': "[" VALUE [,] ENTRY "]" … "}" in the order written, at
   most 256, at least one (Parse_Blend_Map); [entry] reads what follows the value, its ']' included.
   [value] reads the value (an average's may be left out); an empty map is an error at [loc]. *)
let map_entries st what ~loc ~value (entry : float -> 'a) : 'a array =
  let rec entries acc n =
    match peek st with
    | RBrace -> advance st; List.rev acc
    | LBracket ->
        let el = peek_loc st in
        if n >= 256 then Error.raise_at el "a %s has at most 256 entries" what;
        advance st;
        let v = value () in
        ignore (accept st Comma);
        entries (entry (Precision.f32 v) :: acc) (n + 1)
    | _ -> unexpected st (Printf.sprintf "'[' starting a %s entry, or '}'" what)
  in
  let es = entries [] 0 in
  if es = [] then Error.raise_at loc "a %s needs at least one entry" what;
  Array.of_list es

(* A pigment while it is read: what POV-Ray edits in place (§17.9). [h.pat] is None for a plain
   colour; [map] is None until colours or a color_map are given; [pigments] is not empty for a
   pigment_map or a list of pigments. *)
type pig = {
  solid : Colour.t;
  h : Pattern_reader.header;
  map : Scene.map_entry array option;
  pigments : Scene.pigment_entry array;
  uv : Scene.warp list option;
      (* a uv-mapped pigment being edited: its warps, which stay as they are (POV-Ray's edit goes
         to the UV_MAP_PATTERN wrapper, whose warps are never used) *)
}

let pig_of (p : Scene.pigment) =
  let plain = Pattern_reader.plain in
  match p with
  | Solid c -> { solid = c; h = plain; map = None; pigments = [||]; uv = None }
  | Solid_placed { colour; strans } -> { solid = colour; h = { plain with warps = [ Transform_warp strans ] }; map = None; pigments = [||]; uv = None }
  | Pattern pp ->
      {
        solid = Colour.black;
        h = { pat = Some pp.pattern; frequency = pp.frequency; phase = pp.phase; wave = pp.wave; warps = pp.warps; noise = pp.noise_generator };
        map = Some pp.map;
        pigments = pp.pigments;
        uv = (if pp.uv_mapping then Some pp.warps else None);
      }

let pigment_of (g : pig) : Scene.pigment =
  let h = g.h in
  match h.pat with
  | None -> (
      (* a plain colour keeps only its transform (Post_Pigment drops its warps) *)
      match List.find_map (function Scene.Transform_warp t -> Some t | _ -> None) h.warps with
      | None -> Solid g.solid
      | Some strans -> Solid_placed { colour = g.solid; strans })
  | Some pattern ->
      let map = match g.map with Some m -> m | None -> Pigment.default_map pattern in
      let warps, uv_mapping = match g.uv with Some w -> (w, true) | None -> (h.warps, false) in
      Pattern { pattern; frequency = h.frequency; phase = h.phase; wave = h.wave; map; warps; noise_generator = h.noise; pigments = g.pigments; uv_mapping }

(* UV_MAP_PATTERN around a pigment: a pattern is evaluated at the hit's UV coordinates; a plain
   colour is the same everywhere *)
let uv_mapped (p : Scene.pigment) : Scene.pigment =
  match p with Pattern pp -> Pattern { pp with uv_mapping = true } | Solid _ | Solid_placed _ -> p

let default_brick = Scene.Brick { size = Vec.make 8. 3. 4.5; mortar = Precision.f32 (0.5 -. 2e-10) }

(* The block patterns: their keyword, pattern and number of listed colours, pigments or normals
   (§17.4, §17.6, §17.7; square, triangular and cubic as pattern.cpp). *)
let block_pattern st (current : Scene.pattern option) =
  match peek st with
  | Ident "checker" -> Some (Scene.Checker, 2)
  | Ident "hexagon" -> Some (Hexagon, 3)
  | Ident "brick" ->
      (* a brick keeps its size and mortar when written again *)
      Some ((match current with Some (Brick _ as b) -> b | _ -> default_brick), 2)
  | Ident "square" -> Some (Square, 4)
  | Ident "triangular" -> Some (Triangular, 6)
  | Ident "cubic" -> Some (Cubic, 6)
  | _ -> None

let is_block (p : Scene.pattern option) =
  match p with Some (Checker | Hexagon | Brick _ | Square | Triangular | Cubic | Object_pattern _ | Bitmap _) -> true | _ -> false

let is_pattern_start st =
  match peek st with
  | Ident s ->
      block_pattern st None <> None
      || List.mem s
           [ "agate"; "bozo"; "spotted"; "bumps"; "granite"; "leopard"; "marble"; "wood"; "onion"; "radial"; "cells"; "crackle";
             "wrinkles"; "dents"; "waves"; "ripples"; "quilted"; "facets"; "spiral1"; "spiral2"; "planar"; "boxed"; "spherical";
             "cylindrical"; "aoi"; "average"; "mandel"; "julia"; "magnet"; "pavement"; "tiling"; "slope"; "gradient"; "object";
             "image_map"; "bump_map"; "image_pattern"; "function"; "pigment_pattern"; "density_file"; "uv_mapping" ]
  | _ -> false

(* The pigment body read up to [close] ('}' of a pigment block, or ']' of a pigment_map entry),
   editing [base] (§17.9). *)
let rec parse_pigment_body st ~close (base : Scene.pigment) : Scene.pigment =
  let p =
    match ident_of_kind st (function V.Pigment p -> Some p | _ -> None) with
    | Some p -> p
    | None -> base
  in
  (* block patterns: up to [n] colours (commas optional) replacing the first entries of the
     default map, or [n] pigments { … } *)
  let listed (g : pig) pattern n =
    let g = { g with h = { g.h with pat = Some pattern; frequency = 0. (* §17.1: no value wrap *) } } in
    if is_ident st "pigment" then begin
      let rec go i acc =
        if i < n && (i = 0 || (ignore (accept st Comma); is_ident st "pigment")) then begin
          advance st;
          let pg = parse_pigment st st.default_texture.pigment in
          go (i + 1) ({ Scene.pvalue = float_of_int i; pigment = pg } :: acc)
        end
        else List.rev acc
      in
      let given = go 0 [] in
      (* missing pigments are the default texture's (Parse_Blend_List) *)
      let defaults = Pigment.default_map pattern in
      let pigments =
        Array.init (Array.length defaults) (fun i ->
            match List.nth_opt given i with
            | Some e -> e
            | None -> { Scene.pvalue = defaults.(i).value; pigment = st.default_texture.pigment })
      in
      { g with map = None; pigments }
    end
    else begin
      let map = Array.copy (Pigment.default_map pattern) in
      let rec go i =
        if i < n then begin
          if i > 0 then ignore (accept st Comma);
          if is_colour_start st then begin
            map.(i) <- Pigment.f32_entry (float_of_int i) (parse_colour st);
            go (i + 1)
          end
        end
      in
      go 0;
      { g with map = Some map; pigments = [||] }
    end
  in
  (* POV-Ray reads the colour or pattern first (after an identifier), then only modifiers: a
     colour or pattern keyword after anything else ends the pigment, an error (checked) *)
  if is_ident st "uv_mapping" then begin
    (* Parse_Pattern's UV_MAPPING_TOKEN: the rest of the block is a pigment of its own, read from
       the default one, which the wrapper evaluates at the hit's (u, v, 0) *)
    advance st;
    uv_mapped (parse_pigment_body st ~close st.default_texture.pigment)
  end
  else
  let first = ref true in
  let rec loop (g : pig) =
    let loc = peek_loc st in
    let item = peek st in
    let started = not !first in
    first := false;
    match item with
    | k when k == close -> advance st; pigment_of { g with h = Pattern_reader.finish st loc g.h }
    | Ident s when (is_colour_start st || is_pattern_start st) && started ->
        Error.raise_at loc "expected %s but found '%s': the colour or pattern comes first in a %s"
          (if close == RBrace then "'}' closing the pigment" else "']' closing the pigment_map entry")
          s
          (if close == RBrace then "pigment" else "pigment_map entry")
    | Ident _ when is_colour_start st -> loop { solid = parse_colour st; h = { g.h with pat = None }; map = None; pigments = [||]; uv = None }
    | Ident _ when block_pattern st g.h.pat <> None ->
        let pattern, n = Option.get (block_pattern st g.h.pat) in
        advance st;
        loop (listed g pattern n)
    | Ident "object" ->
        (* object { OBJECT [transforms] [two colours or pigments] }: the list inside the block *)
        advance st;
        open_block st "object";
        let g = listed g (Object_pattern (Pattern_object.parse st loc)) 2 in
        close_block st "object";
        loop g
    | Ident (("color_map" | "colour_map") as kw) ->
        advance st;
        if is_block g.h.pat then Error.raise_at loc "cannot use %s with this pattern type" kw;
        loop { g with map = Some (parse_colour_map st kw); pigments = [||] }
    | Ident "pigment_map" ->
        advance st;
        if is_block g.h.pat then Error.raise_at loc "cannot use pigment_map with this pattern type";
        loop { g with pigments = parse_pigment_map ~average:(g.h.pat = Some Average) st }
    | Ident ("quick_color" | "quick_colour") -> advance st; ignore (parse_colour st); loop g
    | Ident _ when started || not (is_pattern_start st) -> (
        match Pattern_reader.modifier st g.h with
        | Some h -> loop { g with h }
        | None -> (
            match item with
            | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a pigment" s)
            | _ ->
                unexpected st
                  (if close == RBrace then "a colour, a pattern or '}' in a pigment" else "a colour, a pattern or ']' in a pigment_map entry")))
    | Ident _ -> (
        match Pattern_reader.pattern_keyword st Pigment_pattern { g.h with pat = None } with
        | Some h ->
            (* a new pattern starts from the default map unless one was given for the old one *)
            loop { g with h; map = (if is_block g.h.pat then None else g.map); pigments = (if is_block g.h.pat then [||] else g.pigments) }
        | None -> unexpected st "a pattern")
    | _ -> unexpected st (if close == RBrace then "a colour, a pattern or '}' in a pigment" else "a colour, a pattern or ']' in a pigment_map entry")
  in
  loop (pig_of p)

(* pigment_map { [v PIGMENT_BODY] … } (§17.3): entries in the order written, values single precision. *)
and parse_pigment_map ?(average = false) st : Scene.pigment_entry array =
  let loc = peek_loc st in
  open_block st "pigment_map";
  match ident_of_kind st (function V.Pigment_map m -> Some m | _ -> None) with
  | Some m -> close_block st "pigment_map"; m
  | None ->
      (* an average's entries may omit the value (weight 1) *)
      let value () = if average && not (float_follows st || is_colour_start st) then 1. else parse_float st in
      map_entries st "pigment_map" ~loc ~value (fun v ->
          { Scene.pvalue = v; pigment = parse_pigment_body st ~close:RBracket st.default_texture.pigment })

and parse_pigment st (base : Scene.pigment) : Scene.pigment =
  open_block st "pigment";
  parse_pigment_body st ~close:RBrace base

(* A normal while it is read (normal.cpp's Tnormal: a pattern with an amount). *)
type nrm = {
  nh : Pattern_reader.header;
  amount : float;
  accuracy : float;
  no_bump_scale : bool;
  nmap : Scene.normal_map;
  nuv : Scene.warp list option;  (* a uv-mapped normal being edited: its warps, kept (as a pigment's) *)
}

let fresh_normal = { nh = Pattern_reader.plain; amount = 0.5; accuracy = Precision.f32 0.02; no_bump_scale = false; nmap = No_map; nuv = None }

let nrm_of (n : Scene.normal) =
  {
    nh = { pat = (match n.npattern with No_pattern -> None | p -> Some p); frequency = n.nfrequency; phase = n.nphase; wave = n.nwave; warps = n.nwarps; noise = n.nnoise_generator };
    amount = n.amount;
    accuracy = n.accuracy;
    no_bump_scale = n.no_bump_scale;
    nmap = n.nmap;
    nuv = (if n.nuv_mapping then Some n.nwarps else None);
  }

(* Post_Tnormal: no_bump_scale is passed down to the normals of a normal_map *)
let rec with_no_bump_scale (n : Scene.normal) =
  match n.nmap with
  | Normal_map es when n.no_bump_scale ->
      { n with nmap = Normal_map (Array.map (fun (e : Scene.normal_entry) -> { e with nnormal = with_no_bump_scale { e.nnormal with no_bump_scale = true } }) es) }
  | No_map | Slope_map _ | Normal_map _ -> n

let normal_of ?(template = false) loc (n : nrm) : Scene.normal =
  match n.nh.pat with
  | None when not template -> Error.raise_at loc "a normal needs a pattern"
  | None | Some _ ->
      let npattern = match n.nh.pat with Some p -> p | None -> Scene.No_pattern in
      (match (npattern, n.nmap) with
      | Average, (No_map | Slope_map _) -> Error.raise_at loc "an average normal needs a normal_map"
      | _ -> ());
      with_no_bump_scale
        {
          npattern;
          nfrequency = n.nh.frequency;
          nphase = n.nh.phase;
          nwave = n.nh.wave;
          nwarps = (match n.nuv with Some w -> w | None -> n.nh.warps);
          nnoise_generator = n.nh.noise;
          amount = n.amount;
          accuracy = n.accuracy;
          no_bump_scale = n.no_bump_scale;
          nmap = n.nmap;
          nuv_mapping = n.nuv <> None;
        }

let default_normal st = match st.default_texture.normal with Some n -> nrm_of n | None -> fresh_normal

(* The normal body read up to [close] ('}' of a normal block, or ']' of a normal_map entry), editing
   [base] (Parse_Tnormal, Parse_Pattern for NORMAL_TYPE). *)
let rec parse_normal_body ?(template = false) st ~close (base : Scene.normal option) : Scene.normal =
  let start = peek_loc st in
  let n =
    match ident_of_kind st (function V.Normal n -> Some n | _ -> None) with
    | Some n -> nrm_of n
    | None -> ( match base with Some n -> nrm_of n | None -> default_normal st)
  in
  if is_ident st "uv_mapping" then begin
    (* as in a pigment: the rest of the block is a normal of its own, read from the default one,
       perturbed at the hit's (u, v, 0) *)
    advance st;
    { (parse_normal_body st ~close st.default_texture.normal) with nuv_mapping = true }
  end
  else
  (* the pattern (once), then an optional amount, then modifiers *)
  let listed (n : nrm) pattern count =
    let h = { n.nh with pat = Some pattern; frequency = 0. } in
    let rec go i acc =
      if i < count && (i = 0 || (ignore (accept st Comma); is_ident st "normal")) && is_ident st "normal" then begin
        advance st;
        let nm = parse_normal st None in
        go (i + 1) ({ Scene.nvalue = float_of_int i; nnormal = nm } :: acc)
      end
      else List.rev acc
    in
    let given = go 0 [] in
    (* no normals listed: no map, the pattern's slope *)
    { n with nh = h; nmap = (if given = [] then No_map else Normal_map (Array.of_list given)) }
  in
  let n =
    match block_pattern st n.nh.pat with
    | Some (pattern, count) -> advance st; listed n pattern count
    | None when is_ident st "object" ->
        (* as in a pigment: the object, then up to two normals, inside the block *)
        let loc = peek_loc st in
        advance st;
        open_block st "object";
        let n = listed n (Object_pattern (Pattern_object.parse st loc)) 2 in
        close_block st "object";
        n
    | None -> (
        match Pattern_reader.pattern_keyword st Normal_pattern { n.nh with pat = None } with
        | Some ({ pat = Some (Bitmap { bump_size = Some amount; _ }); _ } as h) -> { n with nh = h; amount }
        | Some h -> { n with nh = h }
        | None -> n)
  in
  ignore (accept st Comma);
  let n = if float_follows st then { n with amount = Precision.f32 (parse_float st) } else n in
  let rec loop (n : nrm) =
    let loc = peek_loc st in
    match peek st with
    | k when k == close -> advance st; normal_of ~template start { n with nh = Pattern_reader.finish st loc n.nh }
    | Ident "bump_size" -> advance st; loop { n with amount = Precision.f32 (parse_float st) }
    | Ident "accuracy" -> advance st; loop { n with accuracy = Precision.f32 (parse_float st) }
    | Ident "no_bump_scale" -> advance st; loop { n with no_bump_scale = parse_bool_opt st }
    | Ident "slope_map" ->
        advance st;
        if is_block n.nh.pat then Error.raise_at loc "cannot use slope_map with this normal type";
        loop { n with nmap = Slope_map (parse_slope_map st) }
    | Ident "normal_map" ->
        advance st;
        (match n.nh.pat with
        | Some (Facets _) -> Error.raise_at loc "cannot use normal_map with this normal type"
        | _ -> if is_block n.nh.pat then Error.raise_at loc "cannot use normal_map with this normal type");
        loop { n with nmap = Normal_map (parse_normal_map st n.nh.pat) }
    | Ident ("color_map" | "colour_map" | "pigment_map" as kw) -> Error.raise_at loc "'%s' can only be used in a pigment" kw
    | Ident s when is_colour_start st || is_pattern_start st ->
        Error.raise_at loc "expected %s but found '%s': the pattern comes first in a normal"
          (if close == RBrace then "'}' closing the normal" else "']' closing the normal_map entry")
          s
    | Ident _ -> (
        match Pattern_reader.modifier st n.nh with
        | Some nh -> loop { n with nh }
        | None -> (
            match peek st with
            | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a normal" s)
            | _ -> unexpected st (if close == RBrace then "a normal modifier or '}'" else "a normal modifier or ']'")))
    | _ -> unexpected st (if close == RBrace then "a normal modifier or '}'" else "a normal modifier or ']'")
  in
  loop n

(* normal_map { [v NORMAL_BODY] … }: an average's entries may omit the value (weight 1) *)
and parse_normal_map st (pat : Scene.pattern option) : Scene.normal_entry array =
  let loc = peek_loc st in
  open_block st "normal_map";
  let value () = match pat with Some Average -> if float_follows st then parse_float st else 1. | _ -> parse_float st in
  map_entries st "normal_map" ~loc ~value (fun v -> { Scene.nvalue = v; nnormal = parse_normal_body st ~close:RBracket st.default_texture.normal })

(* slope_map { [v <height, slope>] … } *)
and parse_slope_map st : Scene.slope_entry array =
  let loc = peek_loc st in
  open_block st "slope_map";
  map_entries st "slope_map" ~loc ~value:(fun () -> parse_float st) (fun v ->
      let height, slope = Pattern_reader.uv st "a slope_map entry" in
      expect st RBracket "']' closing a slope_map entry";
      { Scene.svalue = v; height; slope })

and parse_normal st (base : Scene.normal option) : Scene.normal =
  open_block st "normal";
  parse_normal_body st ~close:RBrace base

(* #default's normal may have no pattern: it is only the base later normals edit *)
let parse_default_normal st (base : Scene.normal option) : Scene.normal =
  open_block st "normal";
  parse_normal_body ~template:true st ~close:RBrace base

let parse_reflection_block st (r : Scene.reflection) : Scene.reflection =
  (* reflection { MIN [, MAX] [fresnel [b]] [falloff F] [exponent E] [metallic [M]] } (§5.1) *)
  open_block st "reflection";
  let r, one_colour =
    if peek st == RBrace then (r, false)
    else
      let mn = parse_rgb st "reflection" in
      (* the comma between the two colours is optional: any expression starts the second *)
      ignore (accept st Comma);
      let vector_ident = match peek st with Ident s -> (match cur_value st s with Some (V.Vector _) -> true | _ -> false) | _ -> false in
      if float_follows st || is_colour_start st || vector_ident || peek st = Lt then ({ r with rmin = mn; rmax = parse_rgb st "reflection" }, false)
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
    | Ident "crand" -> advance st; loop { f with crand = parse_float st }
    | Ident "irid" ->
        (* irid { amount [thickness T] [turbulence V] } *)
        advance st;
        open_block st "irid";
        let irid = parse_float st in
        let rec fields (f : Scene.finish) =
          match peek st with
          | Ident "thickness" -> advance st; fields { f with irid_thickness = parse_float st }
          | Ident "turbulence" -> advance st; fields { f with irid_turb = (parse_vector st).x }
          | _ -> f
        in
        let f = fields { f with irid } in
        close_block st "irid";
        loop f
    | Ident "refraction" ->
        advance st;
        warn st loc "refraction value unnecessary to turn on refraction; to attenuate, the fade_power and fade_distance keywords should be specified in 'interior{...}'";
        loop { f with refraction = parse_float st }
    | Ident "caustics" ->
        advance st;
        warn st loc "caustics value should be specified in 'interior{...}' statement";
        loop { f with legacy_caustics = Some (Precision.f32 (parse_float st)) }
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

let parse_interior st (base : Scene.interior) : Scene.interior =
  open_block st "interior";
  let i = match ident_of_kind st (function V.Interior i -> Some i | _ -> None) with Some i -> i | None -> base in
  let rec loop (i : Scene.interior) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; i
    | Ident "ior" -> advance st; loop { i with ior = parse_float st }
    | Ident "caustics" -> advance st; loop { i with caustics = Precision.f32 (parse_float st *. 45.0) }
    | Ident "fade_distance" -> advance st; loop { i with fade_distance = parse_float st }
    | Ident "fade_power" -> advance st; loop { i with fade_power = parse_float st }
    | Ident ("fade_color" | "fade_colour") -> advance st; loop { i with fade_colour = parse_rgb st "fade_color" }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in an interior" s)
    | _ -> unexpected st "'ior', 'fade_distance', 'fade_power', 'fade_color' or '}' in an interior"
  in
  loop i

