(* Declarations (docs/povray-rules.md §11.3): the value of a #declare or a macro argument, arrays, and where
   the value is stored. *)

open Token
open Reader
open Expr
open Materials
open Objects
open Settings


(* The value of a #declare or of a macro argument (the parser's "rvalue"), and whether a ';' should
   follow it (§11.3: after floats, vectors, colours and strings). *)
let rec parse_rvalue ?(store = ignore) ?(name = "") st : V.t * bool =
  let loc = peek_loc st in
  match peek st with
  | Ident "spline" -> advance st; (V.Spline (Spline_decl.read_block_with ~named:named_spline st), false)
  | Ident "function" -> advance st; (Fn_reader.declaration st ~name ~special:(special_function st), false)
  | Ident "light_source" -> ((match parse_light_source st with Lights.Lone l -> V.Light l | Shaped o -> V.Object o), false)
  | Ident s when Names.mem object_set s -> (V.Object (parse_object st), false)
  (* a declared pigment, finish or normal starts from the #default texture's (Copy_Pigment
     (Default_Texture->Pigment) and the like) *)
  | Ident "pigment" -> advance st; (V.Pigment (parse_pigment st st.default_texture.pigment), false)
  | Ident "finish" -> advance st; (V.Finish (parse_finish st st.default_texture.finish), false)
  | Ident "normal" -> advance st; (V.Normal (parse_normal st st.default_texture.normal), false)
  | Ident "sky_sphere" -> advance st; (V.Sky (Settings.parse_sky st), false)
  | Ident (("color_map" | "colour_map") as kw) -> advance st; (V.Colour_map (parse_colour_map st kw), false)
  | Ident "pigment_map" -> advance st; (V.Pigment_map (parse_pigment_map st), false)
  | Ident "texture" ->
      (* texture {…} texture {…} …: layers, the last written on top *)
      let l0 = peek_loc st in
      advance st;
      let t = Texture_reader.link st l0 None (Texture_reader.parse st) in
      let rec more t =
        if (match peek_follow st with Ident "texture" -> true | _ -> false) then begin
          let l = peek_loc st in
          advance st;
          more (Texture_reader.link st l (Some t) (Texture_reader.parse st))
        end
        else t
      in
      (V.Texture (more t), false)
  | Ident "texture_map" -> advance st; (V.Texture_map (Texture_reader.parse_texture_map st false), false)
  | Ident "material" -> advance st; (V.Material (Texture_reader.parse_material st Texture_reader.no_material), false)
  | Ident "interior" -> advance st; (V.Interior (parse_interior st Defaults.interior), false)
  | Ident "camera" -> advance st; (V.Camera (parse_camera st), false)
  | Ident "transform" -> advance st; (V.Transform (parse_transform st), false)
  | Ident "array" -> (parse_array ~store st, false)
  | Str _ | Ident ("str" | "vstr" | "concat" | "substr" | "chr" | "strupr" | "strlwr") ->
      (* a string is read without looking past it, and needs no ';': the token after it may call a
         macro that uses the identifier being declared (POV-Ray's portfolio scenes) *)
      (parse_string st, false)
  | Ident s when Names.mem unsupported_rvalue_set s -> not_supported loc (Printf.sprintf "'%s'" s)
  | Ident s -> (
      match cur_value st s with
      | Some (V.Object o) -> advance st; (V.Object { o with oloc = loc }, false)
      | Some ((V.Pigment _ | V.Normal _ | V.Sky _ | V.Finish _ | V.Texture _ | V.Interior _ | V.Light _ | V.Camera _ | V.Transform _ | V.Unsupported _ | V.Colour_map _ | V.Pigment_map _ | V.Texture_map _ | V.Material _) as v) ->
          advance st; (v, false)
      | Some (V.Array a) -> advance st; (V.Array { a with cells = Array.copy a.cells }, false)
      | Some (V.String _) -> (parse_string st, false)
      | _ -> (parse_expr st, true))
  | _ -> (parse_expr st, true)

and named_spline st s = match cur_value st s with Some (V.Spline sp) -> Some sp | _ -> None

(* The vector functions of a pigment, transform or spline, and pattern functions (function.cpp):
   the keyword is next. *)
and special_function st kw loc =
  match kw with
  | "spline" ->
      advance st;
      let sp = Spline_decl.read_block_with ~named:named_spline st in
      Some (Fn_special.spline sp loc)
  | "pattern" -> advance st; Some (Pattern_function.pattern st loc)
  | _ -> Fn_special.special st ~parse_transform kw loc

(* A string value, read without looking past it. An arithmetic operator right after it is the
   likely mistake of joining strings with '+': said so at the operator (POV-Ray only says it expected
   an object there). *)
and parse_string st =
  let v = parse_primary st in
  (match Lexer.next_char (top st).lx with
  | Some ('+' | '-' | '*' | '/') when not st.have ->
      Error.raise_at (peek_loc st) "cannot do arithmetic on a string (strings are joined with concat(…))"
  | Some _ | None -> ());
  v

(* array[d1][d2]… [{ initialisers }] (§11.2). The array is handed to [store] before the look for
   '{': that look runs the directives that follow, and POV-Ray lets them assign elements of the
   array being declared (#declare A = array[3] then #declare A[0] = … with no ';' between). *)
and parse_array ?(store = ignore) st =
  let loc = peek_loc st in
  advance st;
  (* the array of the dimensions read so far, handed to [store] before the next token is looked at *)
  let make dims =
    let total = Array.fold_left (fun t d -> t *. float_of_int d) 1. dims in
    let mib = total *. float_of_int (Sys.word_size / 8) /. 1048576. in
    if mib >= float_of_int st.opts.limits.memory_mb then
      Error.limit_at loc "this array of %.0f elements would need %.0f MiB, more than povml's memory limit of %s MiB (raise it with --max-memory MIB)"
        total mib (commas st.opts.limits.memory_mb);
    let cells = Array.make (int_of_float total) None in
    check_memory st loc;
    let value = V.Array { dims; cells } in
    store value;
    (value, cells)
  in
  let rec dims acc made =
    if peek st == LBracket then begin
      advance st;
      let l = peek_loc st in
      let n = parse_float st in
      (* the size is truncated, as POV-Ray does: array[2.5] has 2 elements *)
      if n < 1. then Error.raise_at l "an array dimension must be at least 1, not %g" n;
      if not (n < 2147483648.) then Error.raise_at l "an array dimension must be less than 2147483648, not %g" n;
      if List.length acc >= 5 then Error.raise_at l "an array has at most 5 dimensions";
      expect st RBracket "']' after an array dimension";
      let acc = int_of_float n :: acc in
      let dims_so_far = Array.of_list (List.rev acc) in
      let made = Some (dims_so_far, make dims_so_far) in
      (* array[3] is complete here: what the look for a '[' or '{' runs is not part of it *)
      ignore (peek_past st);
      dims acc made
    end
    else made
  in
  let dims, (value, cells) =
    match dims [] None with Some m -> m | None -> Error.raise_at loc "'array' needs a size: array[N]"
  in
  if peek st == LBrace then begin
    (* nested braces, one level per dimension; a comma may follow each element and each '}', the
       last ones included, and may be left out (POV-Ray's Parse_Initalizer, tokenize.cpp: an
       element, then Parse_Comma), so { 1, 2 3 } and { {1, 2} {3, 4} } are read as POV-Ray reads them *)
    let rec fill_level d offset =
      let bl = peek_loc st in
      expect st LBrace "'{' of an array initialiser";
      let stride = Array.fold_left ( * ) 1 (Array.sub dims (d + 1) (Array.length dims - d - 1)) in
      for i = 0 to dims.(d) - 1 do
        if peek st == RBrace then Error.raise_at bl "this initialiser has %d elements; the array dimension is %d" i dims.(d);
        if d = Array.length dims - 1 then begin
          cells.(offset + i) <- Some (fst (parse_rvalue st));
          ignore (accept st Comma)
        end
        else fill_level (d + 1) (offset + (i * stride))
      done;
      if peek st != RBrace then Error.raise_at (peek_loc st) "too many elements in an array initialiser: the dimension is %d" dims.(d);
      advance st;
      (* after the outermost '}' the array is complete (see [dims]) *)
      if (if d = 0 then peek_past st else peek st) == Comma then advance st
    in
    fill_level 0 0
  end;
  value

(* The subscripts [i][j]… of an element of [a], as a row-major index. *)
let parse_index st (a : V.array_v) =
  let n = Array.length a.dims in
  let rec go d acc =
    if d = n then acc
    else begin
      expect st LBracket "'[' of an array subscript";
      let l = peek_loc st in
      let f = parse_float st in
      (* truncated as C's (int) does; NaN and infinities are out of range, as in POV-Ray, where
         the cast makes them INT_MIN ("Negative subscript", Parse_Ident in parse.cpp) *)
      if not (f > -1. && f < float_of_int a.dims.(d)) then
        Error.raise_at l "array subscript %s is out of range 0 … %d"
          (if Float.is_nan f then "nan" else if Float.abs f < 2147483648. then string_of_int (int_of_float f) else Printf.sprintf "%g" f)
          (a.dims.(d) - 1);
      let i = int_of_float f in
      expect st RBracket "']' closing an array subscript";
      go (d + 1) ((acc * a.dims.(d)) + i)
    end
  in
  go 0 0

(* Where #declare and #local write (§11.3): an existing identifier is changed where it is found (the
   innermost table that has it), a new one goes to the global table for #declare and to the current
   table (file or macro) for #local: the table current when the declaration began, since a macro
   that gives the value ends only after it (#local V = M(); where M's body ends in #if … #end). *)
let assign ?(current = []) st ~local name value =
  let current = match current with t :: _ -> t | [] -> List.hd st.tables in
  match (local, lookup_cell st name) with
  | true, _ -> (
      match Names.find_opt current name with Some c -> c := value | None -> Names.replace current name (ref value))
  | false, Some c -> c := value
  | false, None -> Names.replace st.global name (ref value)

(* After an unsupported feature inside a declaration: skip the rest of the declared value, that is
   the blocks and parentheses it opened (a macro call's arguments: M(pigment { wood }, 2.2)), then
   what an operator joins to them, or at its own level up to a ';' or through its first block. *)
let skip_declaration st ~d0 ~p0 =
  let rec close () = if (st.depth > d0 || st.parens > p0) && peek st != Eof then (advance st; close ()) in
  let rec scan () =
    match peek st with
    | Semi | RBrace | Eof -> ()
    | LBrace -> advance st; close ()
    | _ -> advance st; scan ()
  in
  let in_parens = st.parens > p0 in
  if st.depth > d0 || in_parens then begin
    close ();
    (* F(max_extent(S).x) * 2; goes on after the call *)
    if in_parens then match peek_follow st with Plus | Minus | Star | Slash | Dot -> scan () | _ -> ()
  end
  else scan ();
  (* the further layers of a layered texture: texture {…} texture {…} *)
  while (match peek_follow st with Ident "texture" -> true | _ -> false) do advance st; scan () done

let parse_declare st ~local dloc =
  let nloc = peek_loc st in
  let k = peek_name st in
  let k =
    (* #declare deprecated [once] "message" Id = … (3.7): the message is for users of Id *)
    match k with
    | Ident "deprecated" ->
        advance st;
        ignore (accept_ident st "once");
        (match peek st with Str _ -> advance st | _ -> unexpected st "the deprecation message");
        peek_name st
    | k -> k
  in
  let target =
    match k with
    | Ident s when is_keyword s -> Error.raise_at nloc "'%s' is a keyword and cannot be declared" s
    | Ident s -> (
        match st.cur_elem with
        | Some (a, i) -> advance st; `Element (s, a, i)
        | None -> advance st; `Name s)
    | _ -> unexpected st (Printf.sprintf "an identifier after '#%s'" (if local then "local" else "declare"))
  in
  let name = match target with `Name s | `Element (s, _, _) -> s in
  expect st Eq (Printf.sprintf "'=' after '%s'" name);
  let d0 = st.depth and p0 = st.parens in
  let in_main = List.length st.frames = 1 in
  let tables = st.tables in
  let store value = match target with `Name s -> assign ~current:tables st ~local s value | `Element (_, a, i) -> a.cells.(i) <- Some value in
  let outer = st.in_rvalue in
  st.in_rvalue <- true;
  let value, needs_semi =
    Fun.protect ~finally:(fun () -> st.in_rvalue <- outer) @@ fun () ->
    try parse_rvalue ~store ~name st
    with Unsupported (l, what, _) ->
      (* a declaration povml cannot make yet is no error until it is used (issue: include files
         declare much more than a scene uses) *)
      skip_declaration st ~d0 ~p0;
      if in_main then warn st dloc "'%s' uses %s, which povml does not support yet; using it will be an error" name what;
      (V.Unsupported { what; at = l }, false)
  in
  (* the value is stored before anything after it is read: the next token may be a directive *)
  store value;
  (* the ';' is looked for as past any value: a directive or macro call after the value waits *)
  if peek_follow st = Semi then advance st
  else if needs_semi then begin
    if st.version >= 350 then
      Error.raise_at st.cur.loc
        "all #declares of float, vector, and color require ';' at the end when the language version is 3.5 or higher (add the ';' or set #version 3.1)"
    else if st.version >= 310 then
      warn st st.cur.loc "all #version and #declares of float, vector, and color require ';' at the end"
  end

