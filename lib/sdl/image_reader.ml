(* Parse_Image and the modifiers of image_map, bump_map and image_pattern (parstxtr.cpp). *)

open Token
open Reader
open Expr

type block = Image_map | Bump_map | Image_pattern | Material_map

(* Parse_UV_Vect: a float stands for both terms, a longer vector gives its first two *)
let uv st what =
  let loc = peek_loc st in
  match parse_expr st with
  | V.Float x -> (x, x)
  | V.Vector a when Array.length a >= 2 -> (a.(0), a.(1))
  | v -> Error.raise_at loc "expected a 2-term vector for %s but found %s" what (V.kind_name v)

let parse_name st =
  let loc = peek_loc st in
  match parse_expr st with
  | V.String s -> s
  | v -> Error.raise_at loc "expected the image file's name (a string) but found %s" (V.kind_name v)

(* The file type keyword or a name whose extension gives it; a name without one is the output
   type's, PNG in povml. A POT file is legal only for a height field [hf]. *)
let parse_file ~hf st =
  let loc = peek_loc st in
  let typed fmt =
    advance st;
    (fmt, parse_name st)
  in
  match peek st with
  | Ident ("png" | "sys") -> typed Image_file.Png
  | Ident "jpeg" -> typed Image_file.Jpeg
  | Ident "gif" -> typed Image_file.Gif
  | Ident "pot" when hf -> typed Image_file.Pot
  | Ident "pot" -> Error.raise_at loc "file type not supported here: 'pot' images are read only by height fields"
  | Ident "ppm" -> typed Image_file.Ppm
  | Ident "pgm" -> typed Image_file.Pgm
  | Ident "tga" -> typed Image_file.Tga
  | Ident (("iff" | "tiff" | "bmp" | "exr" | "hdr" | "function") as kw) -> not_supported loc (Printf.sprintf "'%s' images" kw)
  | _ -> (
      let name = parse_name st in
      match Image_file.format_of_extension name with
      | Some ((Iff | Tiff | Bmp | Exr | Hdr) as fmt) -> not_supported loc (Printf.sprintf "'%s' images" (Image_file.format_name fmt))
      | Some fmt -> (fmt, name)
      | None when not (String.contains name '.') -> (Image_file.Png, name)
      | None -> Error.raise_at loc "could not determine valid image file type from extension")

(* The scene's gamma mode when the image is read (sceneData->gammaMode, which #version and
   assumed_gamma set as they are read): below an effective version 3.7 (3.62 without #version)
   and without assumed_gamma, image files are not decoded (their raw values are used); with
   assumed_gamma, such a scene assumes its working gamma for files that say nothing; from 3.7 on,
   files are decoded to the working gamma (neutral until assumed_gamma is read). *)
let read_options st block ~gamma ~premultiply : Image_file.options =
  let correct = block = Image_map in
  let version = if st.version_set then st.version else 362 in
  let working = match st.assumed_gamma with Some g -> Gamma_curve.by_decoding_gamma g | None -> Gamma_curve.Neutral in
  let off : Image_file.options = { gamma_correct = false; default_gamma = None; working_gamma = Neutral; gamma_override = false; premultiply;
      max_pixels = st.opts.limits.pixels; max_memory_mb = st.opts.limits.memory_mb } in
  let base : Image_file.options =
    match st.assumed_gamma with
    | _ when not correct -> off
    | None when version < 370 -> off
    | Some _ when version < 370 -> { off with gamma_correct = true; default_gamma = Some working; working_gamma = working }
    | Some _ | None -> { off with gamma_correct = true; working_gamma = working }
  in
  match gamma with
  | None -> base
  | Some g ->
      { base with gamma_correct = true; gamma_override = true; default_gamma = Some g; working_gamma = (if correct then working else Neutral) }

(* Parse_Gamma: srgb or a positive decoding gamma *)
let parse_gamma st =
  if accept_ident st "srgb" then Gamma_curve.Srgb
  else
    let loc = peek_loc st in
    let v = parse_float st in
    if v <= 0. then Error.raise_at loc "gamma value must be positive";
    if v < 1. && st.assumed_gamma <> None then warn st loc "Suspicious value %g specified for gamma. Did you mean %g?" v (1. /. v);
    Gamma_curve.by_decoding_gamma v

(* the file searched like an include file, the format's extensions tried where the name has none *)
let locate st loc fmt name =
  let exts =
    match fmt with
    | Image_file.Jpeg -> [ ".jpg"; ".JPG"; ".jpeg"; ".JPEG" ]
    | Pot -> [ ".gif"; ".GIF" ]
    | f -> let e = "." ^ Image_file.format_name f in [ e; String.uppercase_ascii e ] in
  let names = if String.contains name '.' then [ name ] else name :: List.map (fun e -> name ^ e) exts in
  match List.find_map (fun n -> find_file ~inc:false st n) names with
  | Some path ->
      Access.check_read st.opts.access loc path;
      path
  | None -> Error.raise_at loc "cannot find the image file \"%s\" (searched %s)" name (String.concat ", " (include_dirs st))

let not_with loc what = Error.raise_at loc "'%s' cannot be used with a non color-mapped image" what

(* load_file: the file name, its gamma and premultiplied options (after the name, in any order),
   and the image decoded at once with the options [block] reads images with; the image and its
   name as written *)
let rec load_file ?(hf = false) st block =
  if is_ident st "function" then (function_image st, "function") else
  let file_loc = peek_loc st in
  let fmt, name = parse_file ~hf st in
  let rec file_options gamma premultiply =
    match peek st with
    | Ident "gamma" -> advance st; file_options (Some (parse_gamma st)) premultiply
    | Ident "premultiplied" -> advance st; file_options gamma (Some (Expr.c_int (parse_float st) <> 0.))
    | _ -> (gamma, premultiply)
  in
  let gamma, premultiply = file_options None None in
  let options = read_options st block ~gamma ~premultiply in
  if options.gamma_correct && (not options.gamma_override) && fmt = Png && ((not st.version_set) || st.version < 370) then
    warn st file_loc "PNG input image default gamma handling has changed for pre POV-Ray 3.7 scenes; results may differ from original intention";
  let path = locate st file_loc fmt name in
  match Image_read.read fmt options path with
  | Ok img -> (img, name)
  | Error (Unreadable msg) -> Error.raise_at file_loc "cannot read the image file \"%s\": %s" name msg
  | Error (Over_limit { msg; option }) -> Error.limit_at file_loc "cannot read the image file \"%s\": %s (raise it with %s)" name msg option

(* function W, H { … } (Make_Pattern_Image): an image of W × H pixels made by a float function (a
   16-bit grey image) or a pigment function (a 16-bit RGBA image, not premultiplied) over the unit
   square, pixel (j, i) at x = j / (W − 1), y = i / (H − 1), z = 0; each value stored as the
   integer part of value × 65535 in single precision, wrapped to 16 bits as the C cast does *)
and function_image st : Image_file.t =
  let loc = peek_loc st in
  advance st;
  let size () = int_of_float (Expr.c_int (parse_float st +. 0.5)) in
  let width = size () in
  skip_comma st;
  let height = size () in
  if width < 1 || height < 1 then Error.raise_at loc "a function image needs a width and a height of at least 1";
  if peek st != LBrace then unexpected st "'{' after the size of the function image";
  let f =
    match Fn_reader.declaration st ~name:"" ~special:(st.read_special_function st) with
    | V.Function f -> f
    | _ -> Error.raise_at loc "a function image needs a function"
  in
  let sample v = int_of_float (Expr.c_int (Precision.f32 (Precision.f32 v *. 65535.))) land 0xffff in
  let fr = Fn.frame f in
  let at i j =
    fr.(0) <- float_of_int j /. float_of_int (width - 1);
    fr.(1) <- float_of_int i /. float_of_int (height - 1);
    fr.(2) <- 0.
  in
  let n = width * height in
  (* an int a sample, four for a colour: the memory limit bounds them before they are made *)
  let mib = float_of_int width *. float_of_int height *. float_of_int (if f.size = 0 then 1 else 4) *. float_of_int (Sys.word_size / 8) /. 1048576. in
  if mib >= float_of_int st.opts.limits.memory_mb then
    Error.limit_at loc "a %d×%d function image would need %.0f MiB, more than povml's memory limit of %s MiB (raise it with --max-memory MIB)"
      width height mib (commas st.opts.limits.memory_mb);
  if f.size = 0 then begin
    let grey = Array.make n 0 in
    let eval = Lazy.force f.counted in
    with_function_steps st loc (fun () ->
        for i = 0 to height - 1 do
          for j = 0 to width - 1 do
            at i j;
            grey.((i * width) + j) <- sample (eval fr)
          done
        done);
    { width; height; pixels = Grey { max = 65535; grey; alpha = None; lut = None }; premultiplied = false }
  end
  else if f.size = 5 then begin
    let rgb = Array.make (3 * n) 0 and alpha = Array.make n 0 in
    for i = 0 to height - 1 do
      for j = 0 to width - 1 do
        at i j;
        let c = f.veval fr and k = (i * width) + j in
        rgb.(3 * k) <- sample c.(0);
        rgb.((3 * k) + 1) <- sample c.(1);
        rgb.((3 * k) + 2) <- sample c.(2);
        alpha.(k) <- sample (Precision.f32 (1. -. Precision.f32 c.(4)))
      done
    done;
    { width; height; pixels = Colour { max = 65535; rgb; alpha = Some alpha; lut = None }; premultiplied = false }
  end
  else Error.raise_at loc "unsupported function type in a function image (a float function or a pigment function is needed)"

(* the block after [keyword], up to its '}' (a material_map: up to its first texture) *)
let read st keyword =
  let block = match keyword with "image_map" -> Image_map | "bump_map" -> Bump_map | "material_map" -> Material_map | _ -> Image_pattern in
  open_block st keyword;
  let image, name = load_file st block in
  let iw = float_of_int image.width and ih = float_of_int image.height in
  let b =
    {
      Scene.image;
      file = name;
      map_type = 0;
      interpolate = 0;
      once = false;
      use = Use_colour;
      width = Precision.f32 iw;
      height = Precision.f32 ih;
      offset_u = 0.;
      offset_v = 0.;
      all_filter = 0.;
      all_transmit = 0.;
      has_filter = false;
      bump_size = None;
    }
  in
  (* filter/transmit all F, or filter/transmit N, F on one palette entry (image_map only) *)
  let filter_transmit (b : Scene.bitmap) l ~is_filter =
    let edit ?entry v =
      let filter, transmit = if is_filter then (Some v, None) else (None, Some v) in
      Image_file.with_filter_transmit b.image ?entry ~filter ~transmit ()
    in
    let b =
      if accept_ident st "all" then begin
        let v = parse_float st in
        let b = if is_filter then { b with all_filter = v } else { b with all_transmit = v } in
        if Image_file.is_indexed b.image then { b with image = edit v } else b
      end
      else begin
        let rl = peek_loc st in
        let reg = int_of_float (parse_float st +. 0.01) in
        let what = if is_filter then "filter" else "transmit" in
        if not (Image_file.is_indexed b.image) then not_with l what;
        if reg < 0 || reg >= Image_file.colour_map_size b.image then
          Error.raise_at rl "%s color register value out of range" (String.uppercase_ascii what);
        ignore (accept st Comma);
        let v = parse_float st in
        { b with image = edit ~entry:reg v }
      end
    in
    { b with has_filter = true }
  in
  let rec modifiers (b : Scene.bitmap) =
    let l = peek_loc st in
    match peek st with
    | RBrace when block <> Material_map -> advance st; b
    | Ident "texture" when block = Material_map -> b
    | Ident "once" -> advance st; modifiers { b with once = true }
    | Ident "interpolate" ->
        advance st;
        let v = int_of_float (parse_float st) in
        if block = Image_map && v <> 2 && v <> 3 && v <> 4 then Error.raise_at l "invalid interpolate value";
        modifiers { b with interpolate = v }
    | Ident "map_type" ->
        advance st;
        let v = int_of_float (parse_float st) in
        if block = Image_map && v <> 0 && v <> 1 && v <> 2 && v <> 5 then Error.raise_at l "invalid map_type value";
        modifiers { b with map_type = v }
    | Ident ("use_colour" | "use_color") -> advance st; modifiers { b with use = Use_colour }
    | Ident "use_index" -> advance st; modifiers { b with use = (if block = Image_pattern then Use_index else Use_none) }
    | Ident "use_alpha" when block = Image_pattern -> advance st; modifiers { b with use = Use_alpha }
    | Ident "bump_size" when block = Bump_map -> advance st; modifiers { b with bump_size = Some (Precision.f32 (parse_float st)) }
    | Ident "repeat" ->
        advance st;
        let ru, rv = uv st "repeat" in
        if ru <= 0. || rv <= 0. then Error.raise_at l "zero or negative image repeat vector";
        modifiers { b with width = Precision.f32 (iw *. ru); height = Precision.f32 (ih *. rv) }
    | Ident "offset" ->
        advance st;
        let ou, ov = uv st "offset" in
        modifiers { b with offset_u = ou *. -.iw; offset_v = ov *. -.ih }
    | Ident ("filter" | "transmit" as kw) when block = Image_map ->
        advance st;
        modifiers (filter_transmit b l ~is_filter:(kw = "filter"))
    | _ -> unexpected st (if block = Material_map then "a material_map modifier or 'texture'" else Printf.sprintf "an %s modifier or '}'" keyword)
  in
  (block, modifiers b)

let parse st keyword =
  match read st keyword with
  | (Image_map | Bump_map | Material_map), b -> Scene.Bitmap b
  | Image_pattern, b -> Image_pattern b

let parse_material_map st = snd (read st "material_map")

(* A height field's file: Parse_Image (HF_FILE) as for a bump_map, without gamma correction unless
   [gamma] is given; the image is decoded at once *)
let height_field_image st = load_file ~hf:true st Bump_map
