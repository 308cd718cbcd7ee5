(* The text object: a TrueType font file found and read, the string decoded, one extruded glyph
   per character (docs/povray-rules.md §15.9). *)

open Token
open Reader
open Expr
open Object_value

(* §15.9: a string argument of text (the font file, the string), located when missing *)
let text_string st what =
  let l = peek_loc st in
  match peek st with
  | Comma | RBrace -> Error.raise_at l "text needs %s here" what
  | _ -> (
      match Expr.parse_expr st with
      | V.String s -> s
      | v -> Error.raise_at l "text needs %s (a string) here, not %s" what (V.kind_name v))

(* §15.9: the character codes of a text's string: UTF-8 decoded with charset utf8; with ascii, the
   default, a byte beyond 127 becomes a space (before 3.5, it is kept) *)
let text_codes st loc s =
  let n = String.length s in
  let b i = Char.code s.[i] in
  match st.charset with
  | Sys ->
      (* POV-Ray 3.7 on Unix cannot convert the system's text format *)
      Error.raise_at loc "charset sys: the string cannot be converted from the system's text format to Unicode (use charset utf8)"
  | Utf8 -> Utf8.decode s ~invalid:(fun c -> warn st loc "the text string is not valid UTF-8: a byte 0x%02X is left out" c)
  | Ascii ->
    let version = if st.version_set then st.version else 362 in
    let replaced = ref false in
    let codes = Array.init n (fun i -> let c = b i in if c > 127 && version >= 350 then (replaced := true; 32) else c) in
    if !replaced then warn st loc "a non-ASCII character of the text string has been replaced by a space (the charset is ascii; write global_settings { charset utf8 })";
    codes

(* §15.9: a font file is searched like an include file (the scene's directory, +L paths, the
   standard include directory), a name without an extension also with ".ttf" appended, and read
   through the access policy *)
let load_font st loc name =
  let found =
    match find_file ~inc:false st name with
    | Some p -> Some p
    | None -> if String.contains (Filename.basename name) '.' then None else find_file ~inc:false st (name ^ ".ttf")
  in
  match found with
  | None -> Error.raise_at loc "cannot find the font file \"%s\" (searched %s)" name (String.concat ", " (include_dirs st))
  | Some path -> (
      Access.check_read st.opts.access loc path;
      match Font.parse (read_file path) with
      | Ok f -> f
      | Error e -> Error.raise_at loc "the font file \"%s\" is not a usable TrueType font: %s" name e)

(* §15.9: text { ttf "font" "string", thickness, <offset> }: a union of one extruded glyph per
   character (POV-Ray makes it a CSG union, dissolved like any union) *)
let parse st loc =
  open_block st "text";
  if not (accept_ident st "ttf") then
    (match peek st with
     | Ident "internal" -> Error.raise_at (peek_loc st) "internal fonts are not supported yet: name a TrueType font file with ttf \"file.ttf\""
     | _ -> unexpected st "'ttf' and a font file name");
  let floc = peek_loc st in
  let file = text_string st "the font file name" in
  ignore (accept st Comma);
  let sloc = peek_loc st in
  let str = text_string st "the string to render" in
  skip_comma st;
  let depth = parse_float st in
  skip_comma st;
  let offset = parse_vector st in
  let font = load_font st floc file in
  let letters =
    match Font.layout ~utf8:(st.charset = Utf8) font (text_codes st sloc str) ~offset with
    | Error e -> Error.raise_at floc "the font file \"%s\" cannot be read: %s" file e
    | Ok l -> l
  in
  if letters = [] then warn st sloc "the text string is empty: the text object has no letters";
  let members =
    List.map
      (fun ((outline : Glyph.outline), place) ->
        let trans = Transform.compose Transform.identity (Transform.translate place) in
        V.Member_obj (new_obj (Scene.Glyph { outline; depth; trans }) loc))
      letters
  in
  (* POV-Ray then turns the whole text by <0.001, 0.001, 0.001> degrees (to avoid cracks
     where an edge lies along an axis), before the modifiers *)
  move_obj (Place.Rotate (Vec.make 0.001 0.001 0.001)) (new_csg Union members ~split:true loc)
