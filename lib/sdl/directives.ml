(* Directives (docs/povray-rules.md §11.3), run as the token stream is read: conditionals, loops, macros and
   their calls, includes, messages, #version, #undef and #default; #declare and the file directives
   are handed to Declare and User_files. *)

open Token
open Reader
open Expr
open Materials
open Declare

(* Skip raw tokens of the current frame (a branch not taken, a loop that ends, a macro definition)
   up to the #end at this level, or up to one of [stops] at this level; returns what it stopped at. *)
let skip st ~stops open_loc what =
  let f = top st in
  let rec go depth =
    let t = Lexer.next f.lx in
    match t.kind with
    | Eof -> Error.raise_at open_loc "%s has no matching #end" what
    (* the directives that open a block, matched directly rather than searched in a list: skipping
       is the hot path of a guarded include read again in a loop *)
    | Directive ("if" | "ifdef" | "ifndef" | "while" | "for" | "switch" | "macro") -> go (depth + 1)
    | Directive "end" -> if depth = 0 then `End else go (depth - 1)
    | Directive d when depth = 0 && List.mem d stops -> `Stop (d, t.loc)
    | _ -> go depth
  in
  go 0

let skip_to_end st open_loc what = ignore (skip st ~stops:[] open_loc what)

(* (expression): the condition of #if, #while, #switch, #case. Read without looking past the ')',
   so nothing after it runs before the directive has decided. *)
let cond_value st what =
  if peek st != LParen then unexpected st (Printf.sprintf "'(' after '#%s'" what);
  advance st;
  let l = peek_loc st in
  let v = parse_full st in
  expect st RParen (Printf.sprintf "')' closing the condition of '#%s'" what);
  match v with V.Float f -> f | v -> Error.raise_at l "the condition of '#%s' must be a float, not %s" what (V.kind_name v)

(* A string argument (#include, #debug …), also read without looking past it. *)
let string_arg st what =
  let l = peek_loc st in
  match parse_primary st with
  | V.String s -> s
  | v -> Error.raise_at l "'#%s' needs a string, not %s" what (V.kind_name v)

let push_cond st c = let f = top st in f.conds <- c :: f.conds

let pop_cond st = let f = top st in f.conds <- List.tl f.conds

(* #if (c) / #elseif chain, from a condition already evaluated to [c]. *)
let rec run_if st c loc =
  if c then push_cond st (If_branch loc)
  else
    match skip st ~stops:[ "else"; "elseif" ] loc "#if" with
    | `End -> ()
    | `Stop ("else", _) -> push_cond st (If_branch loc)
    | `Stop (_, l) -> run_if st (truth (cond_value st "elseif")) l

(* Look for the #case, #range or #else of a #switch that matches. *)
let rec find_case st (sw : cond) =
  match sw with
  | Switch_case r -> (
      match skip st ~stops:[ "case"; "range"; "else" ] r.sloc "#switch" with
      | `End -> pop_cond st
      | `Stop ("else", _) -> r.running <- true
      | `Stop ("case", _) -> if Float.abs (cond_value st "case" -. r.value) < 1e-10 then r.running <- true else find_case st sw
      | `Stop (_, _) ->
          let lo, hi = range_args st in
          if lo <= r.value && r.value <= hi then r.running <- true else find_case st sw)
  | If_branch _ | While_loop _ | For_loop _ -> ()

and range_args st =
  expect st LParen "'(' after '#range'";
  let lo = parse_float st in
  expect st Comma "',' between the bounds of '#range'";
  let hi = parse_float st in
  expect st RParen "')' closing '#range'";
  (lo, hi)

(* The end of a macro body: back to the caller's frame and tables. *)
let return_from_macro st =
  st.frames <- List.tl st.frames;
  st.tables <- List.tl st.tables;
  st.macro_depth <- st.macro_depth - 1


let directive_names = Lexer.directive_names

let directive st d loc =
  let f = top st in
  match d with
  | "declare" | "local" -> parse_declare st ~local:(d = "local") loc
  | "undef" -> (
      let k = peek_name st in
      match k with
      | Ident _ when st.cur_elem <> None ->
          (* #undef A[i] clears that element *)
          (match st.cur_elem with Some (a, i) -> a.cells.(i) <- None | None -> ());
          advance st
      | Ident s ->
          advance st;
          (match List.find_opt (fun t -> Names.mem t s) st.tables with
          | Some t -> Names.remove t s
          | None -> warn st loc "attempt to #undef the unknown identifier '%s'" s)
      | _ -> unexpected st "an identifier after '#undef'")
  | "version" ->
      let l = peek_loc st in
      let v = parse_float st in
      if v > 3.71 then Error.raise_at l "this scene requires POV-Ray version %g or later; povml reads the language of POV-Ray 3.7" v;
      ignore (accept st Semi);
      st.version <- int_of_float ((v *. 100.) +. 0.5);
      st.version_set <- true
  | "include" -> (
      let name = string_arg st "include" in
      if st.includes >= st.opts.limits.include_depth then
        Error.limit_at loc "include files are nested more than %s deep, povml's limit (does a file include itself? raise the limit with --max-include-depth N)"
          (commas st.opts.limits.include_depth);
      match find_file st name with
      | None ->
          Error.raise_at loc "cannot find the include file \"%s\" (searched %s)" name (String.concat ", " (include_dirs st))
      | Some path ->
          Access.check_read st.opts.access loc path;
          let text = read_file path in
          st.frames <- { lx = Lexer.create ~file:path text; kind = Included (loc, Unix.gettimeofday ()); conds = [] } :: st.frames;
          st.tables <- Names.create 16 :: st.tables;
          st.includes <- st.includes + 1)
  | "if" -> run_if st (truth (cond_value st "if")) loc
  | "ifdef" | "ifndef" ->
      expect st LParen (Printf.sprintf "'(' after '#%s'" d);
      let def = parse_defined_arg st in
      expect st RParen (Printf.sprintf "')' closing '#%s'" d);
      run_if st (if d = "ifdef" then def else not def) loc
  | "else" | "elseif" -> (
      match f.conds with
      | If_branch l :: _ -> pop_cond st; skip_to_end st l "#if"
      | Switch_case { running = true; _ } :: _ when d = "else" -> () (* falls through, as #case does *)
      | _ -> Error.raise_at loc "'#%s' without a matching #if" d)
  | "end" -> (
      match f.conds with
      | If_branch _ :: _ | Switch_case _ :: _ -> pop_cond st
      | While_loop (m, l) :: _ ->
          count_iteration st l;
          Lexer.reset f.lx m;
          if not (truth (cond_value st "while")) then begin pop_cond st; skip_to_end st l "#while" end
      | For_loop r :: _ -> (
          match !(r.var) with
          | V.Float i ->
              let i = i +. r.step in
              r.var := V.Float i;
              if (r.step > 0. && i <= r.stop +. 1e-10) || (r.step < 0. && i >= r.stop -. 1e-10) then begin
                count_iteration st r.floc;
                Lexer.reset f.lx r.body
              end
              else pop_cond st
          | v -> Error.raise_at r.floc "the #for variable was changed to %s inside the loop" (V.kind_name v))
      | [] -> (
          match f.kind with
          | Macro_body _ -> return_from_macro st
          | Main | Included _ -> Error.raise_at loc "'#end' without a matching #if, #while, #for, #switch or #macro"))
  | "while" ->
      let m = Lexer.mark f.lx in
      if truth (cond_value st "while") then push_cond st (While_loop (m, loc)) else skip_to_end st loc "#while"
  | "for" ->
      expect st LParen "'(' after '#for'";
      let k = peek_name st in
      let name = match k with Ident s when not (is_keyword s) -> s | _ -> unexpected st "the loop variable of '#for'" in
      if st.cur_elem <> None then Error.raise_at (peek_loc st) "the #for loop variable must not be an array element";
      advance st;
      expect st Comma "',' after the #for variable";
      let start = parse_float st in
      expect st Comma "',' after the start value of '#for'";
      let stop = parse_float st in
      let sl = peek_loc st in
      let step = if accept st Comma then parse_float st else 1. in
      expect st RParen "')' closing '#for'";
      assign st ~local:true name (V.Float start);
      let var = Option.get (lookup_cell st name) in
      if Float.abs step < 1e-10 then Error.raise_at sl "the step of '#for' must not be 0";
      if (step > 0. && start < stop +. 1e-10) || (step < 0. && start > stop -. 1e-10) then
        push_cond st (For_loop { var; stop; step; body = Lexer.mark f.lx; floc = loc })
      else skip_to_end st loc "#for"
  | "switch" ->
      let v = cond_value st "switch" in
      let sw = Switch_case { value = v; running = false; sloc = loc } in
      push_cond st sw;
      find_case st sw
  | "case" | "range" -> (
      match f.conds with
      | Switch_case { running = true; _ } :: _ ->
          (* no #break before it: execution falls through *)
          if d = "case" then ignore (cond_value st "case") else ignore (range_args st)
      | _ -> Error.raise_at loc "'#%s' outside a #switch" d)
  | "break" -> (
      (* leave the innermost #switch, #while or #for, closing the branches opened inside it *)
      let rec out conds skipped =
        match conds with
        | (If_branch _) :: rest -> out rest (skipped + 1)
        | (Switch_case _ | While_loop _ | For_loop _) :: rest ->
            f.conds <- rest;
            for _ = 0 to skipped do skip_to_end st loc "#break" done
        | [] -> (
            match f.kind with
            | Macro_body _ ->
                (* #break in a macro returns from it *)
                return_from_macro st
            | Main | Included _ -> Error.raise_at loc "'#break' outside a #switch, #while, #for or macro")
      in
      out f.conds 0)
  | "macro" ->
      let k = peek_name st in
      let name = match k with Ident s when not (is_keyword s) -> advance st; s | _ -> unexpected st "a macro name after '#macro'" in
      expect st LParen (Printf.sprintf "'(' after the macro name '%s'" name);
      let rec params acc =
        let k = peek_name st in
        match k with
        | RParen -> advance st; List.rev acc
        | Ident p when not (is_keyword p) ->
            advance st;
            ignore (accept st Comma);
            params (p :: acc)
        | _ -> unexpected st "a parameter name or ')'"
      in
      let params = params [] in
      let m = { V.mname = name; params; source = f.lx; body = Lexer.mark f.lx; mloc = loc } in
      skip_to_end st loc (Printf.sprintf "#macro %s" name);
      Names.replace st.global name (ref (V.Macro m))
  | "debug" -> st.opts.debug (string_arg st "debug")
  | "warning" -> let s = string_arg st "warning" in warn st loc "%s" s
  | "error" -> let s = string_arg st "error" in Error.raise_at loc "#error: %s" s
  | "default" ->
      open_block st "#default";
      let rec loop () =
        let l = peek_loc st in
        match peek st with
        | RBrace -> advance st
        | Ident "texture" ->
            advance st;
            (* Parse_Default: the default texture is one plain layer *)
            (match Texture_reader.parse st with
            | Layers [ l ] -> st.default_texture <- l
            | Layers _ -> Error.raise_at l "the default texture cannot be layered"
            | Texture_pattern _ | Uv_mapped _ | Material_map _ | Cutaway -> Error.raise_at l "the default texture cannot be a patterned texture, a material map or tiles");
            loop ()
        | Ident "pigment" -> advance st; st.default_texture <- { st.default_texture with pigment = parse_pigment st st.default_texture.pigment }; loop ()
        | Ident "finish" -> advance st; st.default_texture <- { st.default_texture with finish = parse_finish st st.default_texture.finish }; loop ()
        | Ident "normal" -> advance st; st.default_texture <- { st.default_texture with normal = Some (parse_default_normal st st.default_texture.normal) }; loop ()
        | Ident "radiosity" ->
            (* the default radiosity importance, which only radiosity reads (Parse_Default) *)
            advance st;
            Settings.parse_radiosity_importance st;
            loop ()
        | Ident s when List.mem s [ "camera"; "media" ] -> not_supported l (Printf.sprintf "'%s' in #default" s)
        | _ -> unexpected st "'texture', 'pigment', 'normal', 'finish' or '}' in #default"
      in
      loop ()
  | "fopen" -> User_files.fopen st
  | "fclose" -> User_files.fclose st loc
  | "read" -> User_files.read st loc
  | "write" -> User_files.write st loc
  | "render" | "statistics" -> st.opts.debug (string_arg st d)
  | _ -> (
      match Suggest.nearest d directive_names with
      | [] -> Error.raise_at loc "unknown directive '#%s'" d
      | s -> Error.raise_at loc "unknown directive '#%s'; did you mean %s?" d (String.concat " or " (List.map (Printf.sprintf "'#%s'") s)))

(* A macro call (§11.3): the arguments are read in the caller, an identifier standing alone is
   passed by reference, then the body is read in a table of its own. *)
let invoke st (m : V.macro) loc =
  if st.macro_depth >= st.opts.limits.macro_depth then
    Error.limit_at loc "macro calls are nested more than %s deep, povml's limit (a macro that calls itself without end? raise the limit with --max-macro-depth N)"
      (commas st.opts.limits.macro_depth);
  st.macro_calls <- st.macro_calls + 1;
  if st.macro_calls > st.opts.limits.macro_calls then
    Error.limit_at loc "the scene has called macros %s times, povml's limit (raise it with --max-macro-calls N)" (commas st.opts.limits.macro_calls);
  if st.macro_calls land 255 = 0 then check_memory st loc;
  expect st LParen (Printf.sprintf "'(' after the macro name '%s'" m.mname);
  let table = Names.create 8 in
  let nparams = List.length m.params in
  let wrong_count msg = raise (Error.Scene_error { loc = peek_loc st; msg; notes = [ (m.mloc, "the macro is defined here") ]; kind = Scene }) in
  List.iteri
    (fun i p ->
      (* the commas between arguments are optional, and one may follow the last *)
      if i > 0 then ignore (accept st Comma);
      if peek st == RParen then
        wrong_count (Printf.sprintf "macro '%s' takes %d argument%s, this call gives %d" m.mname nparams (if nparams = 1 then "" else "s") i);
      let by_ref =
        match peek st with
        | Ident s when st.cur_elem = None -> (
            match lookup_cell st s with
            | Some c when (match Lexer.next_char (top st).lx with Some (',' | ')') -> true | _ -> false) -> advance st; Some c
            | _ -> None)
        | _ -> None
      in
      let cell = match by_ref with Some c -> c | None -> ref (fst (parse_rvalue st)) in
      Names.replace table p cell)
    m.params;
  ignore (accept st Comma);
  if peek st != RParen then wrong_count (Printf.sprintf "too many arguments for macro '%s', which takes %d" m.mname nparams);
  advance st;
  st.tables <- table :: st.tables;
  st.frames <- { lx = Lexer.at m.source m.body; kind = Macro_body (m.mname, loc); conds = [] } :: st.frames;
  st.macro_depth <- st.macro_depth + 1

