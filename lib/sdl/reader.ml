(* The reader of the scene language: the parser state, the token stream with its frames (scene
   file, included files, macro bodies) and their open conditionals, the symbol tables, and the
   helpers every part of the interpreter uses to look at tokens and report errors. *)

open Token
module V = Value

(* Tables keyed by names: the symbol tables and the keyword sets, searched for every identifier. *)
module Names = Hashtbl.Make (struct
  type t = string

  let equal = String.equal
  let hash = Hashtbl.hash
end)

type options = {
  width : int;
  height : int;
  clock : float;  (** +K *)
  animation : Animation.values;  (** clock_on, frame_number and the other animation identifiers *)
  declares : (string * V.t) list;  (** Declare=NAME=VALUE: identifiers declared before the scene is read *)
  library_paths : string list;  (** +L, searched in order after the scene's directory and the working directory *)
  debug : string -> unit;  (** where #debug text goes *)
  included : string -> depth:int -> float -> unit;  (** an include file was read: path, nesting, seconds *)
  limits : Scene_limits.t;
  access : Access.t;  (** the files the scene may read and write *)
}

type camera_spec = V.camera_spec = {
  c_location : Vec.t option;
  c_direction : Vec.t option;
  c_up : Vec.t option;
  c_right : Vec.t option;
  c_sky : Vec.t option;
  c_look_at : (Vec.t * Loc.t) option;
  c_angle : (float * Loc.t) option;
  c_trans : Transform.t option;  (* the camera's transforms, applied last (§1.3) *)
  c_ortho : bool;
}

(* A feature povml does not render yet. Inside a declaration it makes the declared value
   [V.Unsupported] (an error only where it is used); anywhere else it is a located error. *)
exception Unsupported of Loc.t * string * (Loc.t * string) list

(* Where tokens come from: the scene file, an included file, or a macro body (§11.3). Each frame
   has its own stack of open conditionals and loops. *)
type frame = { lx : Lexer.t; kind : frame_kind; mutable conds : cond list }

and frame_kind =
  | Main
  | Included of Loc.t * float  (* where the #include was, and when reading it began *)
  | Macro_body of string * Loc.t  (* the macro and where it was called *)

and cond =
  | If_branch of Loc.t  (* inside the branch of an #if/#ifdef that is taken *)
  | While_loop of Lexer.mark * Loc.t  (* the mark is just before the condition *)
  | For_loop of { var : V.t ref; stop : float; step : float; body : Lexer.mark; floc : Loc.t }
  | Switch_case of { value : float; mutable running : bool; sloc : Loc.t }

(* global_settings { charset … } (§15.9) *)
type charset = Ascii | Utf8 | Sys

type st = {
  mutable frames : frame list;  (* innermost first; never empty *)
  mutable cur : Token.t;  (* the current token, valid when [have] *)
  mutable have : bool;
  mutable cur_elem : (V.array_v * int) option;  (* the current token is this array element *)
  mutable no_expand : bool;  (* reading the argument of defined(): a macro name is not called *)
  mutable defer : bool;  (* reading past a complete value: a directive is kept, not run *)
  mutable in_rvalue : bool;  (* reading a declaration's value: a macro called past it is kept too *)
  mutable pending_macro : (V.macro * Loc.t) option;  (* the macro call so kept, the current token *)
  mutable streams : V.stream array;  (* the random streams made by seed() *)
  mutable depth : int;  (* '{' minus '}' consumed: how a declaration that fails is skipped *)
  mutable parens : int;  (* '(' minus ')' consumed: the same for a macro call's arguments *)
  opts : options;
  global : V.t ref Names.t;
  mutable tables : V.t ref Names.t list;  (* innermost first; the global table is last *)
  mutable includes : int;  (* open include files *)
  mutable macro_depth : int;
  mutable macro_calls : int;  (* in the whole scene, against [opts.limits] *)
  mutable iterations : int;  (* loop iterations in the whole scene *)
  mutable string_bytes : int;  (* the bytes of the strings string functions built in the whole scene *)
  mutable nesting : int;  (* open parentheses, vectors, unary operators and unions being read *)
  mutable braces : int;  (* POV-Ray's count of nested blocks, for its warning past 200 *)
  mutable object_count : int;  (* objects and lights that entered the scene *)
  mutable isosurfaces : int;  (* isosurfaces read: the next one's number *)
  mutable split_unions : int;  (* unions split so far, each its members' shared interior's number *)
  probe_work : Scratch.t Lazy.t;  (* the scratch of trace() calls, renewed for each: POV-Ray's parser thread's data; made by the first *)
  mutable probed : (V.obj * Compiled.t) option;  (* the object trace(), inside() or an extent function compiled last, and its compiled scene *)
  mutable version : int;  (* languageVersion × 100 *)
  mutable version_set : bool;
  mutable charset : charset;  (* how a text's string is read *)
  mutable warnings : Error.t list;  (* newest first *)
  mutable objects : Scene.obj list;  (* newest first *)
  mutable lights : Scene.light list;  (* newest first *)
  mutable camera : camera_spec option;
  mutable background : Colour.t option;
  mutable sky : Scene.sky option;
  mutable assumed_gamma : float option;
  mutable max_trace_level : int;
  mutable adc_bailout : float;
  mutable noise_generator : int;
  mutable irid_wavelength : Rgb.t;
  mutable number_of_waves : int;
  mutable ambient_light : Rgb.t;
  mutable default_texture : Scene.layer;
  mutable directive : st -> string -> Loc.t -> unit;  (* the directive reader, tied below *)
  mutable invoke : st -> V.macro -> Loc.t -> unit;  (* the macro caller, tied below *)
  mutable index : st -> V.array_v -> int;  (* reads the subscripts of an array element, tied below *)
  mutable files : V.user_file list;  (* the files #fopen opened, closed when the scene ends *)
  mutable read_object : st -> V.obj option;
  mutable read_pigment : st -> Scene.pigment;  (* Materials' pigment block reader, for pigment patterns *)  (* Objects' parser, for object patterns (Materials) *)
  mutable read_special_function : st -> string -> Loc.t -> Fn.t option;  (* Declare's pigment, transform, spline and pattern functions, for function images *)
}

(* ---------------------------------------------------------------------------------------------- *)
(* Keywords *)

(* The reserved words by what povml does with them ([Keywords]). *)
let keywords = Keywords.words (function Read | Object -> true | Not_supported | Object_not_supported | Reserved -> false)
let unsupported = Keywords.words (function Not_supported | Object_not_supported -> true | Read | Object | Reserved -> false)
let reserved = Keywords.words (function Reserved -> true | Read | Object | Not_supported | Object_not_supported -> false)

let set_of l =
  let h = Names.create 64 in
  List.iter (fun s -> Names.replace h s ()) l;
  h

let keyword_set = set_of (keywords @ unsupported @ reserved)
let unsupported_set = set_of unsupported
let is_keyword s = Names.mem keyword_set s
let is_unsupported s = Names.mem unsupported_set s

(* An [Unsupported] that no declaration may absorb: the located error the scene ends with. *)
let unsupported_error loc what notes = Error.Scene_error { loc; msg = "not supported yet: " ^ what; notes; kind = Scene }

(* ---------------------------------------------------------------------------------------------- *)
(* Token access

   The parser sees one token at a time, as POV-Ray's does: [peek] reads the next token only when it is
   asked for, and reading is where directives run and macros are called (§11.3). So a directive is
   executed when the parser first looks past it, and [advance] never reads ahead. *)

let top st = List.hd st.frames

(* ---------------------------------------------------------------------------------------------- *)
(* Limits: every scene ends in bounded time and memory, with a located error of kind Limit. *)

let commas n =
  let s = string_of_int n in
  let len = String.length s in
  String.concat "" (List.init len (fun i -> (if i > 0 && (len - i) mod 3 = 0 then "," else "") ^ String.make 1 s.[i]))

let check_memory st loc =
  let limit = st.opts.limits.memory_mb in
  if (Gc.quick_stat ()).heap_words / (1 lsl 20) * (Sys.word_size / 8) >= limit then
    Error.limit_at loc "the scene needs more than %s MiB of memory, povml's limit (raise it with --max-memory MIB)" (commas limit)

let count_iteration st loc =
  st.iterations <- st.iterations + 1;
  if st.iterations > st.opts.limits.iterations then
    Error.limit_at loc "the scene's loops have run %s times, povml's limit (does this loop never end? raise the limit with --max-iterations N)"
      (commas st.opts.limits.iterations);
  check_memory st loc

(* Evaluating [f ()], a call of user functions while the scene is read, with the limit on their
   steps reported at [loc]. *)
let with_function_steps st loc f =
  try f () with
  | Fn_budget.Exhausted ->
      Error.limit_at loc "the scene's functions need more than %s steps, povml's limit (does a sum, a chain of calls or an octave count run too long? raise the limit with --max-function-steps N)"
        (commas st.opts.limits.function_steps)

(* A string of [len] bytes built by a string function: all of them together are bounded, so that
   a string grown a little at a time (quadratic work) ends. *)
let count_string st loc len =
  st.string_bytes <- st.string_bytes + len;
  if st.string_bytes / 1048576 >= st.opts.limits.string_mb then
    Error.limit_at loc "the scene's string functions have built %s MiB of strings, povml's limit (is a string grown in a long loop? raise the limit with --max-strings MIB)"
      (commas st.opts.limits.string_mb)

let count_object st loc =
  st.object_count <- st.object_count + 1;
  if st.object_count > st.opts.limits.objects then
    Error.limit_at loc "the scene has more than %s objects and lights, povml's limit (raise it with --max-objects N)"
      (commas st.opts.limits.objects);
  if st.object_count land 1023 = 0 then check_memory st loc

(* [nest st loc f] reads a nested construct with [f], refusing to nest deeper than the limit: the
   reader recurses on nesting, so this is what keeps deep input from overflowing the stack. *)
let nest st loc f =
  if st.nesting >= st.opts.limits.nesting then
    Error.limit_at loc "this is nested more than %s levels deep (parentheses, vectors, signs and unions together), povml's limit (raise it with --max-nesting N)"
      (commas st.opts.limits.nesting);
  st.nesting <- st.nesting + 1;
  match f () with
  | v -> st.nesting <- st.nesting - 1; v
  | exception e -> st.nesting <- st.nesting - 1; raise e

let lookup_cell st name =
  let rec go = function
    | [] -> None
    | t :: rest -> ( match Names.find_opt t name with Some c -> Some c | None -> go rest)
  in
  go st.tables

let lookup st name = match lookup_cell st name with Some c -> Some !c | None -> None

(* While looking past a value, directives wait (see [peek_follow]), except those that only end a
   branch or a macro body: they change no value, and a macro's value is often followed by its #end. *)
let closes_branch f d =
  match d with
  | "else" | "elseif" -> true
  | "end" -> ( match f.conds with [] -> (match f.kind with Macro_body _ -> true | Main | Included _ -> false) | (If_branch _ | Switch_case _) :: _ -> true | (While_loop _ | For_loop _) :: _ -> false)
  | _ -> false

(* A directive runs where it stands: what it cannot do is an error there, never part of a value
   being declared around it (a declaration that is looking for its next token runs the directives
   after it, and its recovery could not skip the rest of a half-run #if). *)
let run_directive st d loc =
  try st.directive st d loc with Unsupported (l, what, notes) -> raise (unsupported_error l what notes)

(* POV-Ray's float functions and constants (the FLOAT_FUNCT tokens of reswords.h other than
   version): after a '#' one of them, a number or a float identifier is an error, where any other
   token is read as if the '#' were not there (Parse_Directive in tokenize.cpp). *)
let float_tokens =
  [ "abs"; "acos"; "acosh"; "asc"; "asin"; "asinh"; "atan"; "atan2"; "atanh"; "bitwise_and"; "bitwise_or";
    "bitwise_xor"; "ceil"; "clock"; "clock_on"; "cos"; "cosh"; "defined"; "degrees"; "dimension_size"; "dimensions";
    "div"; "exp"; "false"; "file_exists"; "floor"; "inside"; "int"; "ln"; "log"; "max"; "min"; "mod"; "no"; "now";
    "off"; "on"; "pi"; "pow"; "prod"; "radians"; "rand"; "seed"; "select"; "sin"; "sinh"; "sqrt"; "strcmp";
    "strlen"; "sum"; "tan"; "tanh"; "true"; "val"; "vdot"; "vlength"; "yes" ]

let float_token_set =
  let h = Names.create 64 in
  List.iter (fun s -> Names.replace h s ()) float_tokens;
  h

let rec fill st =
  let f = top st in
  take st f (Lexer.next f.lx)

(* The token [t] just read from frame [f]: a directive runs, a macro is called, anything else
   becomes the current token. *)
and take st f t =
  match t.kind with
  | Eof -> end_of_frame st f t
  | Hash -> after_hash st f t.loc (Lexer.next f.lx)
  | Directive d ->
      if st.defer && not (closes_branch f d) then begin st.cur <- t; st.have <- true; st.cur_elem <- None end
      else begin
        run_directive st d t.loc;
        if not st.have then fill st
      end
  | Ident s -> (
      match lookup st s with
      | Some (V.Macro m) when st.defer && st.in_rvalue && not st.no_expand ->
          (* past a declaration's value a macro is called once the value is stored, as POV-Ray
             calls none while it looks for the value's end *)
          st.cur <- t; st.have <- true; st.cur_elem <- None; st.pending_macro <- Some (m, t.loc)
      | Some (V.Macro m) when not st.no_expand ->
          st.invoke st m t.loc;
          if not st.have then fill st
      | Some (V.Array a) when Lexer.next_char f.lx = Some '[' ->
          (* an array element is resolved as it is read, so every context sees its value (§11.2) *)
          let i = st.index st a in
          st.cur <- t; st.have <- true; st.cur_elem <- Some (a, i)
      | _ -> st.cur <- t; st.have <- true; st.cur_elem <- None)
  | _ -> st.cur <- t; st.have <- true; st.cur_elem <- None

(* A '#' not followed by a directive name: POV-Ray reads the token after it as usual, so a '#'
   before a keyword, an identifier, a macro call or punctuation is ignored, silently as POV-Ray
   does (language/image_size.pov:25 ends "look_at <0,2,0>#"), except before a float (checked with
   POV-Ray: "Expected 'object or directive.', float function 'clock' found instead"). A name that
   is neither a keyword nor declared is a misspelt directive. *)
and after_hash st f hash t =
  let not_a_directive what = Error.raise_at t.loc "expected a directive or an object after '#' but found %s" what in
  (match t.kind with
  | Num _ -> not_a_directive (describe t.kind)
  | Ident s when Names.mem float_token_set s -> not_a_directive (describe t.kind)
  | Ident s -> (
      match lookup st s with
      | Some (V.Float _) -> not_a_directive (Printf.sprintf "'%s', which is a float" s)
      | Some _ -> ()
      | None when is_keyword s -> ()
      | None -> (
          match Suggest.nearest s Lexer.directive_names with
          | [] -> Error.raise_at hash "unknown directive '#%s'" s
          | sug -> Error.raise_at hash "unknown directive '#%s'; did you mean %s?" s (String.concat " or " (List.map (Printf.sprintf "'#%s'") sug))))
  | Str _ | Directive _ | LBrace | RBrace | LParen | RParen | Lt | Gt | LBracket | RBracket | Comma | Semi | Plus
  | Minus | Star | Slash | Dot | Eq | Ne | Le | Ge | Bang | Amp | Bar | Quest | Colon | Hash | Eof -> ());
  take st f t

and end_of_frame st f t =
  (match f.conds with
  | [] -> ()
  | c :: _ ->
      let loc, what =
        match c with
        | If_branch l -> (l, "#if")
        | While_loop (_, l) -> (l, "#while")
        | For_loop { floc; _ } -> (floc, "#for")
        | Switch_case { sloc; _ } -> (sloc, "#switch")
      in
      Error.raise_at loc "%s has no matching #end before the end of the file" what);
  match f.kind with
  | Main -> st.cur <- t; st.have <- true; st.cur_elem <- None
  | Included (_, t0) ->
      st.opts.included (Lexer.file f.lx) ~depth:st.includes (Unix.gettimeofday () -. t0);
      st.frames <- List.tl st.frames;
      st.tables <- List.tl st.tables;
      st.includes <- st.includes - 1;
      fill st
  | Macro_body (name, _) -> Error.raise_at t.loc "the body of macro '%s' ends without #end" name

(* A directive read while looking past a complete value was kept for later (see [peek_follow]);
   it runs as soon as the parser asks for the next token. *)
let rec run_pending st =
  match st.pending_macro with
  | Some (m, loc) when st.have ->
      st.pending_macro <- None;
      st.have <- false;
      st.invoke st m loc;
      if not st.have then fill st;
      run_pending st
  | _ ->
  match st.cur.kind with
  | Directive d when st.have ->
      st.have <- false;
      run_directive st d st.cur.loc;
      if not st.have then fill st;
      run_pending st
  | _ -> ()

let peek st = if not st.have then fill st else run_pending st; st.cur.kind

(* The token after a complete value, read to see whether the value goes on ('+', '.x', another
   texture layer …). A directive found there is not run yet: it runs after the value has been
   used, so "#declare A = 1 #declare B = A;" and a #declare just before #end see the new A. *)
let peek_follow st =
  if not st.have then begin
    st.defer <- true;
    (try fill st with e -> st.defer <- false; raise e);
    st.defer <- false
  end;
  st.cur.kind

(* The token after a complete value that may still go on (an array's '[' or '{', the comma after an
   initialiser), read as [peek] reads, running directives and calling macros. What those cannot do
   belongs to what follows the value, so it is an error there, not a declaration povml cannot make. *)
let peek_past st = try peek st with Unsupported (l, what, notes) -> raise (unsupported_error l what notes)

(* The value of the identifier [name] that is the current token (an array element if subscripted). *)
let cur_value st name =
  match st.cur_elem with
  | Some (a, i) -> (
      match a.cells.(i) with
      | Some v -> Some v
      | None -> Error.raise_at st.cur.loc "element %d of the array '%s' has not been assigned a value" i name)
  | None -> lookup st name
let peek_loc st = if not st.have then fill st else run_pending st; st.cur.loc

let advance st =
  if not st.have then fill st else run_pending st;
  (match st.cur.kind with
  | LBrace ->
      st.depth <- st.depth + 1;
      (* POV-Ray warns at a block nested 200 deep, and then counts that block as not opened *)
      if st.braces + 1 >= 200 then st.warnings <- Error.warning st.cur.loc "too many nested '{' braces" :: st.warnings
      else st.braces <- st.braces + 1
  | RBrace -> st.depth <- st.depth - 1; st.braces <- st.braces - 1
  | LParen -> st.parens <- st.parens + 1
  | RParen -> st.parens <- st.parens - 1
  | _ -> ());
  if st.cur.kind != Eof then st.have <- false

let warn st loc fmt = Printf.ksprintf (fun msg -> st.warnings <- Error.warning loc msg :: st.warnings) fmt

let not_supported loc what = raise (Unsupported (loc, what, []))

(* Using a declared value that needed an unsupported feature. *)
let unsupported_use loc name what at = raise (Unsupported (loc, Printf.sprintf "%s (used through '%s')" what name, [ (at, Printf.sprintf "'%s' was declared here" name) ]))

let all_names st = List.concat_map (fun t -> Names.fold (fun k _ acc -> k :: acc) t []) st.tables

let unknown_identifier st loc name =
  let candidates = all_names st @ keywords in
  match Suggest.nearest name candidates with
  | [] -> Error.raise_at loc "unknown identifier '%s'" name
  | s -> Error.raise_at loc "unknown identifier '%s'; did you mean %s?" name (String.concat " or " (List.map (Printf.sprintf "'%s'") s))

let unexpected st what =
  let k = peek st in
  match k with
  | Ident s when is_unsupported s -> not_supported (peek_loc st) (Printf.sprintf "'%s'" s)
  | Ident s when (not (is_keyword s)) && cur_value st s = None -> (
      let candidates = all_names st @ keywords in
      match Suggest.nearest s candidates with
      | [] -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k)
      | sug ->
          Error.raise_at (peek_loc st) "expected %s but found %s; did you mean %s?" what (describe k)
            (String.concat " or " (List.map (Printf.sprintf "'%s'") sug)))
  | Ident s -> (
      match cur_value st s with
      | Some (V.Unsupported u) -> unsupported_use (peek_loc st) s u.what u.at
      | Some v -> Error.raise_at (peek_loc st) "expected %s but found '%s', which is %s" what s (V.kind_name v)
      | None -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k))
  | _ -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k)

(* [k] is always a constant constructor here, so physical equality is the cheap, exact test *)
let expect st k what = if peek st == k then advance st else unexpected st what
let open_block st what = expect st LBrace (Printf.sprintf "'{' after '%s'" what)

(* the items of a list whose length the scene announced, read one by one (a huge count is then an
   error at the first item missing, never an allocation of that size) *)
let read_items n item =
  let rec go i acc = if i >= n then Array.of_list (List.rev acc) else go (i + 1) (item i :: acc) in
  go 0 []

exception Object_copy of V.obj * string

let open_shape st kw =
  open_block st kw;
  match peek st with
  | Ident s when not (is_keyword s) -> (
      match cur_value st s with
      | Some (V.Object o) ->
          advance st;
          raise (Object_copy (o, kw))
      | Some _ | None -> ())
  | _ -> ()

let close_block st what = expect st RBrace (Printf.sprintf "'}' closing '%s' or one of its keywords" what)

let accept st k = if peek st == k then (advance st; true) else false
let skip_comma st = ignore (accept st Comma)
let is_ident st s = match peek st with Ident i -> String.equal i s | _ -> false

let accept_ident st s =
  if is_ident st s then (advance st; true) else false

(* The next token where a name is expected (#declare, #undef, #macro, #for, defined()): a macro
   name there is a name, not a call. *)
let peek_name st =
  st.no_expand <- true;
  Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st)

(* The scene file: the outermost frame. *)
let main_file st = Lexer.file (List.nth st.frames (List.length st.frames - 1)).lx

let include_dirs st =
  let main = Filename.dirname (main_file st) in
  let debian = Access.standard_include_dir in
  (* the scene's directory (POV-Ray searches the working directory, usually the scene's), then +L *)
  let dirs = [ main; Filename.current_dir_name ] @ st.opts.library_paths @ (if Sys.file_exists debian then [ debian ] else []) in
  List.fold_left (fun acc d -> if List.mem d acc then acc else acc @ [ d ]) [] dirs

(* An include file: the name as written, then with ".inc" ([~inc:false] for file_exists, which
   does not append it). *)
let find_file ?(inc = true) st name =
  let candidates =
    let join d n = if d = Filename.current_dir_name then n else Filename.concat d n in
    let names = if inc then [ name; name ^ ".inc" ] else [ name ] in
    if Filename.is_relative name then List.concat_map (fun d -> List.map (join d) names) (include_dirs st) else names
  in
  List.find_opt (fun p -> Sys.file_exists p && not (Sys.is_directory p)) candidates


let read_file path =
  let at = { Loc.none with file = path } in
  let reason msg =
    (* Sys_error reads "path: reason"; the path is already in the location *)
    let p = path ^ ": " in
    if String.length msg > String.length p && String.sub msg 0 (String.length p) = p then
      String.sub msg (String.length p) (String.length msg - String.length p)
    else msg
  in
  if Sys.file_exists path && Sys.is_directory path then Error.raise_at at "this is a directory, not a scene file";
  match open_in_bin path with
  | exception Sys_error msg -> Error.raise_at at "cannot open the scene file: %s" (reason msg)
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          match really_input_string ic (in_channel_length ic) with
          | s -> s
          | exception Sys_error msg -> Error.raise_at at "cannot read the scene file: %s" (reason msg))

