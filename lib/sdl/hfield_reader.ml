(* Parse_HField (parse.cpp): the image, then water_level and smooth in any order; the object's
   modifiers follow in [Objects], and the field is built as POV-Ray's Compute_HField builds it. *)

open Token
open Reader

(* image_height_at (support/imageutil.cpp) of every pixel *)
let heights_of_image (img : Image_file.t) =
  let w = img.width and h = img.height in
  let value lut max p = match lut with Some (l : float array) -> l.(p) | None -> Image_file.linear max p in
  Array.init (w * h) (fun k ->
      let z = k / w and x = k mod w in
      (* Map[z][x] is the image's row height − z − 1 *)
      let i = x + ((h - z - 1) * w) in
      match img.pixels with
      | Indexed _ -> Image_file.index img i * 256
      | Grey { max; grey; lut; _ } -> int_of_float (Precision.f32 (value lut max grey.(i) *. 65535.))
      | Colour { max; rgb; lut; _ } ->
          let r = value lut max rgb.(3 * i) and g = value lut max rgb.((3 * i) + 1) and b = value lut max rgb.((3 * i) + 2) in
          if max > 255 then int_of_float (((0.297 *. r) +. (0.589 *. g) +. (0.114 *. b)) *. 65535.)
          else int_of_float (((r *. 256.) +. g) *. 255.))

let parse st =
  open_shape st "height_field";
  let image_loc = peek_loc st in
  let image, name = Image_reader.height_field_image st in
  let rec options water smooth =
    match peek st with
    | Ident "water_level" ->
        advance st;
        let level = Expr.parse_float st in
        (* before #version 2.0 the level was given in 1/256ths *)
        let level = if st.version < 200 then level /. 256. else level in
        options (65536.0 *. level) smooth
    | Ident "smooth" -> advance st; options water true
    | _ -> (water, smooth)
  in
  let water, smooth = options 0. false in
  (* smooth_height_field (hfield.cpp) finds no triangle round a vertex of a field one pixel wide
     or deep, and stops the parse with this message *)
  if smooth && (image.width < 2 || image.height < 2) then
    Error.raise_at image_loc "Failed to find any normals at. (a smooth height_field needs an image at least 2×2 pixels; \"%s\" is %d×%d)" name
      image.width image.height;
  let field =
    Hfield.make ~width:image.width ~height:image.height ~heights:(heights_of_image image) ~water ~smooth
  in
  Scene.Height_field { field; trans = Hfield.scaling field }
