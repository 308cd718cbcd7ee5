(* Parse_HField (parse.cpp): the image, then water_level and smooth in any order; the object's
   modifiers follow in [Objects], and the field is built as POV-Ray's Compute_HField builds it. *)

open Token
open Reader

let parse st =
  open_block st "height_field";
  let loc = peek_loc st in
  (match peek st with Ident "function" -> not_supported loc "'function'" | _ -> ());
  let image, _name = Image_reader.height_field_image st in
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
  let field =
    Hfield.make ~width:image.width ~height:image.height ~heights:(Hfield.heights_of_image image) ~water ~smooth
  in
  Scene.Height_field { field; trans = Hfield.scaling field }
