(* Textures as POV-Ray 3.7's parser reads them (parstxtr.cpp Parse_Texture, Parse_Tiles,
   Parse_Material, parse.cpp Link_Textures): plain textures, layers, patterned textures
   (texture_map, listed textures, tiles, average) and materials. *)

open Token
open Reader
open Expr

(* Convert_Filter_To_Transmit, for scenes of version 3.1 and older: a layer's filter becomes
   transmit, in its colour or in every colour of its map *)
let rec filter_to_transmit (p : Scene.pigment) : Scene.pigment =
  let convert (c : Colour.t) = { c with transmit = Precision.f32 (c.transmit +. c.filter); filter = 0. } in
  match p with
  | Solid c -> Solid (convert c)
  | Solid_placed r -> Solid_placed { r with colour = convert r.colour }
  | Pattern pp when Array.length pp.pigments > 0 ->
      Pattern { pp with pigments = Array.map (fun (e : Scene.pigment_entry) -> { e with pigment = filter_to_transmit e.pigment }) pp.pigments }
  | Pattern pp -> Pattern { pp with map = Array.map (fun (e : Scene.map_entry) -> { e with colour = convert e.colour }) pp.map }

let convert_layer (l : Scene.layer) = { l with pigment = filter_to_transmit l.pigment }

(* Link_Textures: [nw] laid over [old] (the last written on top). Neither may be patterned when
   there are two. *)
let link st loc (old : Scene.texture option) (nw : Scene.texture) : Scene.texture =
  let legacy = st.version <= 310 in
  match (old, nw) with
  | Some (Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway), _ -> Error.raise_at loc "cannot layer over a patterned texture"
  | None, Layers ls when legacy ->
      (* every layer with one below it *)
      let n = List.length ls in
      Layers (List.mapi (fun i l -> if i < n - 1 then convert_layer l else l) ls)
  | None, _ -> nw
  | Some (Layers below), Layers ls -> Layers ((if legacy then List.map convert_layer ls else ls) @ below)
  | Some (Layers _), (Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway) -> Error.raise_at loc "cannot layer a patterned texture over another"

let default_texture st : Scene.texture = Layers [ st.default_texture ]
let transform_keyword = function Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") -> true | _ -> false

(* Parse_Texture_Transform: only transforms may follow, up to [close] *)
let rec transforms st ~close (t : Scene.texture) =
  match peek st with
  | k when k == close -> advance st; t
  | k when transform_keyword k -> transforms st ~close (Place.texture t (parse_op st))
  | _ -> unexpected st (if close == RBrace then "a transform or '}' in a texture" else "a transform or ']' in a texture_map entry")

(* Parse_Texture up to [close] ('}' of a texture block, or ']' of a texture_map entry): a texture
   identifier or the default texture, modified by pigment, normal and finish (identifiers or
   blocks, the top layer's) and transforms (every layer's); or, when nothing modified it, tiles
   or a patterned texture. *)
let rec parse_body st ~close : Scene.texture =
  match Materials.ident_of_kind st (function V.Texture t -> Some t | _ -> None) with
  | Some ((Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway) as t) -> transforms st ~close t
  | Some (Layers ls) -> plain st ~close ls true
  | None -> plain st ~close [ st.default_texture ] false

and plain st ~close (ls : Scene.layer list) modified =
  let top, below = match ls with top :: below -> (top, below) | [] -> (st.default_texture, []) in
  (* pigment, normal and finish identifiers may stand for their blocks, a concession POV-Ray makes
     to old scenes ("texture { Jade }") *)
  let rec ids (top : Scene.layer) modified =
    match
      Materials.ident_of_kind st (function V.Pigment p -> Some (`P p) | V.Normal n -> Some (`N n) | V.Finish f -> Some (`F f) | _ -> None)
    with
    | Some (`P p) -> ids { top with pigment = p } true
    | Some (`N n) -> ids { top with normal = Some n } true
    | Some (`F f) -> ids { top with finish = f } true
    | None -> (top, modified)
  in
  let top, modified = ids top modified in
  let rec mods (top : Scene.layer) below modified =
    match peek st with
    | Ident "pigment" -> advance st; mods { top with pigment = Materials.parse_pigment st top.pigment } below true
    | Ident "normal" -> advance st; mods { top with normal = Some (Materials.parse_normal st top.normal) } below true
    | Ident "finish" -> advance st; mods { top with finish = Materials.parse_finish st top.finish } below true
    | k when transform_keyword k ->
        let op = parse_op st in
        mods (Place.layer top op) (List.map (fun l -> Place.layer l op) below) true
    | Ident "no_bump_scale" ->
        (* it only changes how the normals of the entries of a patterned texture are bent *)
        advance st;
        mods top below modified
    | _ -> (top, below, modified)
  in
  let top, below, modified = mods top below modified in
  let t : Scene.texture = Layers (top :: below) in
  let loc = peek_loc st in
  match peek st with
  | k when k == close -> advance st; t
  | Ident "tiles" when not modified -> advance st; transforms st ~close (parse_tiles st loc)
  | Ident "material_map" when not modified ->
      (* Parse_Material_Map: the image, its modifiers, then the materials, each a texture block *)
      advance st;
      let mimage = Image_reader.parse_material_map st in
      let rec materials acc = if is_ident st "texture" then (advance st; materials (parse st :: acc)) else List.rev acc in
      let materials = Array.of_list (materials []) in
      close_block st "material_map";
      if Array.length materials = 0 then Error.raise_at loc "a material_map needs a texture";
      transforms st ~close (Material_map { mimage; mwarps = []; materials })
  | Ident "uv_mapping" when not modified ->
      (* UV_MAP_PATTERN: the rest of the block is a texture of its own, evaluated at the hit's
         (u, v, 0) *)
      advance st;
      Uv_mapped { uwarps = []; inner = parse_body st ~close }
  | Ident _ when (not modified) && Materials.is_pattern_start st -> patterned st ~close
  | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a texture" s)
  | _ ->
      unexpected st
        (if close == RBrace then "'pigment', 'normal', 'finish', a transform or '}' in a texture"
         else "'pigment', 'normal', 'finish', a transform or ']' in a texture_map entry")

(* texture { … } after the keyword *)
and parse st : Scene.texture =
  open_block st "texture";
  parse_body st ~close:RBrace

(* [texture {…}] blocks one after the other, layered *)
and layers st : Scene.texture option =
  let rec go acc =
    if is_ident st "texture" then begin
      let loc = peek_loc st in
      advance st;
      go (Some (link st loc acc (parse st)))
    end
    else acc
  in
  go None

(* tiles { texture {…} … tile2 texture {…} … }: a checker of the two (the first tile where the
   checker's value is 1) *)
and parse_tiles st loc : Scene.texture =
  open_block st "tiles";
  let first = layers st in
  if not (accept_ident st "tile2") then unexpected st "'texture' or 'tile2' in tiles";
  let second = layers st in
  close_block st "tiles";
  let first = match first with Some t -> t | None -> Error.raise_at loc "first texture missing from tiles" in
  let second = match second with Some t -> t | None -> default_texture st in
  Texture_pattern { tpat = block_header Scene.Checker; tmap = [| { tvalue = 0.; ttexture = second }; { tvalue = 1.; ttexture = first } |] }

and block_header pattern : Scene.patterned =
  {
    pattern;
    frequency = 0.;
    phase = 0.;
    wave = Ramp;
    map = [||];
    warps = [];
    noise_generator = 0;
    pigments = [||];
    uv_mapping = false;
  }

(* Parse_Pattern for a texture: the pattern (a block pattern with up to its number of listed
   texture {…}), its modifiers and texture_map, up to [close]. A patterned texture needs its
   textures. *)
and patterned st ~close : Scene.texture =
  let loc = peek_loc st in
  (* a block pattern's listed textures: missing ones are the default texture *)
  let listed n =
    let rec go i acc =
      if i < n && (i = 0 || (ignore (accept st Comma); is_ident st "texture")) && is_ident st "texture" then begin
        advance st;
        go (i + 1) (parse st :: acc)
      end
      else List.rev acc
    in
    let given = Array.of_list (go 0 []) in
    Some (Array.init n (fun i -> { Scene.tvalue = float_of_int i; ttexture = (if i < Array.length given then given.(i) else default_texture st) }))
  in
  let h = Pattern_reader.plain in
  let h, tmap =
    match Materials.block_pattern st None with
    | Some (pattern, n) ->
        advance st;
        ({ h with pat = Some pattern; frequency = 0. }, listed n)
    | None -> (
        match peek st with
        | Ident "object" ->
            advance st;
            open_block st "object";
            let pattern = Scene.Object_pattern (Pattern_object.parse st loc) in
            let tmap = listed 2 in
            close_block st "object";
            ({ h with pat = Some pattern; frequency = 0. }, tmap)
        | _ -> (
            match Pattern_reader.pattern_keyword st Pigment_pattern h with
            | Some h -> (h, None)
            | None -> unexpected st "a pattern"))
  in
  let block = match tmap with Some _ -> true | None -> false in
  let rec loop (h : Pattern_reader.header) tmap =
    let l = peek_loc st in
    match peek st with
    | k when k == close ->
        advance st;
        let h = Pattern_reader.finish st l h in
        let pattern = Option.get h.pat in
        let tmap =
          match (tmap, pattern) with
          | Some m, _ -> m
          | None, Scene.Average -> Error.raise_at l "average must have a map"
          | None, _ -> Error.raise_at l "a patterned texture must have a texture_map"
        in
        Scene.Texture_pattern
          {
            tpat = { (block_header pattern) with frequency = h.frequency; phase = h.phase; wave = h.wave; warps = h.warps; noise_generator = h.noise };
            tmap;
          }
    | Ident "texture_map" ->
        advance st;
        if block then Error.raise_at l "cannot use texture_map with this pattern type";
        loop h (Some (parse_texture_map st (match h.pat with Some Average -> true | _ -> false)))
    | Ident ("color_map" | "colour_map" | "pigment_map" | "normal_map" | "slope_map") ->
        Error.raise_at l "'%s' is not allowed in a texture: a patterned texture takes a texture_map" (match peek st with Ident s -> s | _ -> "")
    | Ident "no_bump_scale" -> advance st; loop h tmap
    | _ -> (
        match Pattern_reader.modifier st h with
        | Some h -> loop h tmap
        | None -> (
            match peek st with
            | Ident s when is_unsupported s -> not_supported l (Printf.sprintf "'%s' in a texture" s)
            | _ -> unexpected st (if close == RBrace then "a pattern modifier, 'texture_map' or '}' in a texture" else "a pattern modifier, 'texture_map' or ']'")))
  in
  loop h tmap

(* texture_map { [v TEXTURE_BODY] … } or texture_map { Id }; an average's values may be left out
   (1 then) *)
and parse_texture_map st average : Scene.texture_entry array =
  let loc = peek_loc st in
  open_block st "texture_map";
  match Materials.ident_of_kind st (function V.Texture_map m -> Some m | _ -> None) with
  | Some m -> close_block st "texture_map"; m
  | None ->
      let value () = if average && not (float_follows st) then 1. else parse_float st in
      Materials.map_entries st "texture_map" ~loc ~value (fun v -> { Scene.tvalue = v; ttexture = parse_body st ~close:RBracket })

(* Parse_Material: a material identifier's textures laid over [m]'s and its interior, then
   texture, interior_texture, interior and transforms (of the textures and the interior) *)
let parse_material st (m : V.material) : V.material =
  open_block st "material";
  let loc = peek_loc st in
  let m =
    match Materials.ident_of_kind st (function V.Material m -> Some m | _ -> None) with
    | Some id ->
        let over base t = match t with Some t -> Some (link st loc base t) | None -> base in
        { V.mtexture = over m.mtexture id.mtexture; minterior_texture = over m.minterior_texture id.minterior_texture; minterior = id.minterior }
    | None -> m
  in
  let rec loop (m : V.material) =
    let l = peek_loc st in
    match peek st with
    | RBrace -> advance st; m
    | Ident "texture" -> advance st; loop { m with mtexture = Some (link st l m.mtexture (parse st)) }
    | Ident "interior_texture" ->
        advance st;
        open_block st "interior_texture";
        loop { m with minterior_texture = Some (link st l m.minterior_texture (parse_body st ~close:RBrace)) }
    | Ident "interior" ->
        advance st;
        let base = match m.minterior with Some i -> i | None -> Defaults.interior in
        loop { m with minterior = Some (Materials.parse_interior st base) }
    | k when transform_keyword k ->
        let op = parse_op st in
        loop { m with mtexture = Option.map (fun t -> Place.texture t op) m.mtexture }
    | Ident s when is_unsupported s -> not_supported l (Printf.sprintf "'%s' in a material" s)
    | _ -> unexpected st "'texture', 'interior_texture', 'interior', a transform or '}' in a material"
  in
  loop m

let no_material : V.material = { mtexture = None; minterior_texture = None; minterior = None }
