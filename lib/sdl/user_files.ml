(* The scene's own files: #fopen, #read, #write and #fclose. What each directive accepts, writes
   and reads was checked against POV-Ray 3.7.0.10 (the cases are in test/cram/file_io.t). *)

open Token
open Reader

(* ---------------------------------------------------------------------------------------------- *)
(* Opening and closing *)

(* Sys_error reads "path: reason"; the messages name the path themselves. *)
let reason path msg =
  let p = path ^ ": " in
  let n = String.length p in
  if String.length msg > n && String.sub msg 0 n = p then String.sub msg n (String.length msg - n) else msg

let read_text at path =
  match open_in_bin path with
  | exception Sys_error msg -> Error.raise_at at "cannot open \"%s\" for reading: %s" path (reason path msg)
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          try really_input_string ic (in_channel_length ic)
          with Sys_error msg -> Error.raise_at at "cannot read \"%s\": %s" path (reason path msg))

(* A file to read is searched as include files are (the scene's directory, the working directory,
   +L, the standard directory); one to write is named from the working directory, as POV-Ray
   does. *)
let open_read st at name =
  match find_file ~inc:false st name with
  | None -> Error.raise_at at "cannot find the file \"%s\" to read (searched %s)" name (String.concat ", " (include_dirs st))
  | Some path ->
      Access.check_read st.opts.access at path;
      V.Reading (Lexer.create ~file:path (read_text at path))

let open_write st at path ~append =
  Access.check_write st.opts.access at path;
  let mode = if append then Open_append else Open_trunc in
  match open_out_gen [ Open_wronly; Open_creat; mode; Open_binary ] 0o666 path with
  | oc -> V.Writing oc
  | exception Sys_error msg -> Error.raise_at at "cannot open \"%s\" for writing: %s" path (reason path msg)

let fopen st =
  let name =
    match peek_name st with
    | Ident s when not (is_keyword s) -> (
        match lookup st s with
        | None -> advance st; s
        | Some v -> Error.raise_at (peek_loc st) "'#fopen' needs a new identifier for the file, but '%s' is %s" s (V.kind_name v))
    | _ -> unexpected st "an identifier for the file after '#fopen'"
  in
  let at = peek_loc st in
  let path = match Expr.parse_primary st with V.String s -> s | v -> Error.raise_at at "'#fopen' needs a file name (a string), not %s" (V.kind_name v) in
  let io =
    match peek st with
    | Ident "read" -> advance st; open_read st at path
    | Ident "write" -> advance st; open_write st at path ~append:false
    | Ident "append" -> advance st; open_write st at path ~append:true
    | k -> Error.raise_at (peek_loc st) "expected 'read', 'write' or 'append' after the file name of '#fopen' but found %s" (describe k)
  in
  let f = { V.path; io } in
  st.files <- f :: st.files;
  (* POV-Ray puts a file identifier in the global table, even when a macro opens it *)
  Names.replace st.global name (ref (V.File f))

(* A failed write, flush or close of the file [f] (a full disk, a device): an error at [at], the
   directive that wrote. *)
let write_failed at (f : V.user_file) msg = Error.raise_at at "cannot write \"%s\": %s" f.path (reason f.path msg)

(* Closes [f] and undefines every identifier that names it. A file closed by [#fclose] at [at] is
   closed with its last bytes checked; one the scene left open, as well as it can. *)
let close ?at st (f : V.user_file) =
  let failure =
    match (f.io, at) with
    | V.Writing oc, Some _ -> ( try close_out oc; None with Sys_error m -> close_out_noerr oc; Some m)
    | V.Writing oc, None -> close_out_noerr oc; None
    | (V.Reading _ | V.Closed), _ -> None
  in
  f.io <- V.Closed;
  st.files <- List.filter (fun g -> g != f) st.files;
  List.iter (Names.filter_map_inplace (fun _ c -> match !c with V.File g when g == f -> None | _ -> Some c)) st.tables;
  match (failure, at) with Some m, Some at -> write_failed at f m | _ -> ()

let close_all st = List.iter (close st) st.files

(* #fclose of an identifier that is not an open file does nothing, as in POV-Ray: a file read to
   its end has already been closed and undefined. *)
let fclose st at =
  match peek_name st with
  | Ident s ->
      let file = match lookup st s with Some (V.File f) -> Some f | Some _ | None -> None in
      advance st;
      Option.iter (close ~at st) file
  | _ -> unexpected st "a file identifier after '#fclose'"

(* The file named first in #read and #write. *)
let file_arg st what =
  let at = peek_loc st in
  match peek_name st with
  | Ident s -> (
      match cur_value st s with
      | Some (V.File f) -> advance st; (f, at)
      | Some v -> Error.raise_at at "'#%s' needs a file opened by #fopen, but '%s' is %s" what s (V.kind_name v)
      | None ->
          Error.raise_at at "'#%s' needs a file opened by #fopen, but '%s' is not defined (a file read to its end is closed and undefined)" what s)
  | _ -> unexpected st (Printf.sprintf "a file identifier after '#%s ('" what)

(* ---------------------------------------------------------------------------------------------- *)
(* Reading: a data file is read with the scene's tokens. Its values are floats (a number with '+'
   and '-' signs before it, no expressions), vectors of 2 to 5 such numbers, and strings, each
   followed by a comma. *)

let data_error (t : Token.t) what = Error.raise_at t.loc "expected %s in the data file but found %s" what (describe t.kind)

let rec signed_float lx =
  let t = Lexer.next lx in
  match t.kind with
  | Plus -> signed_float lx
  | Minus -> ( let t = Lexer.next lx in match t.kind with Num f -> -.f | _ -> data_error t "a number after '-'")
  | Num f -> f
  | _ -> data_error t "a number"

(* The comma after a value: true when the data ends instead. POV-Ray 3.7 reads one token there and
   drops it when it is not a comma, so in "1 2 3" the 2 is never read: data must be separated by
   commas, and the value after a missing comma is lost as it is in POV-Ray. *)
let comma lx =
  match (Lexer.next lx).kind with
  | Comma -> false
  | Eof -> true
  | _ -> false

(* Between the terms of a vector the comma is optional. *)
let term_comma lx =
  let m = Lexer.mark lx in
  match (Lexer.next lx).kind with Comma -> () | _ -> Lexer.reset lx m

let vector lx =
  let x = signed_float lx in
  term_comma lx;
  let y = signed_float lx in
  term_comma lx;
  let rec rest acc =
    let m = Lexer.mark lx in
    let t = Lexer.next lx in
    match t.kind with
    | Gt -> List.rev acc
    | Plus | Minus | Num _ ->
        if List.length acc = 5 then Error.raise_at t.loc "a vector in a data file has at most 5 terms";
        Lexer.reset lx m;
        let v = signed_float lx in
        term_comma lx;
        rest (v :: acc)
    | _ -> data_error t "a number or '>' in a vector"
  in
  match rest [ y; x ] with
  | [ _; _; _; _; _ ] as l -> V.Colour (Array.of_list l)
  | l -> V.Vector (Array.of_list l)

let data_value lx =
  let m = Lexer.mark lx in
  let t = Lexer.next lx in
  match t.kind with
  | Eof -> (None, true)
  | Plus | Minus | Num _ ->
      Lexer.reset lx m;
      let v = signed_float lx in
      (Some (V.Float v), comma lx)
  | Lt -> let v = vector lx in (Some v, comma lx)
  | Str s -> (Some (V.String s), comma lx)
  | _ -> data_error t "a float, a vector or a string"

(* Where #read stores a value: a new identifier (made global, as POV-Ray does), or an identifier
   or array element that holds a float, a 3-term vector or a string; POV-Ray refuses the others.
   A new identifier the data ends before stays undefined (POV-Ray declares it without a value,
   so that its defined() is true though it cannot be used). *)
let target st name at =
  let refuse v =
    Error.raise_at at "'#read' stores into a new identifier or one that holds a float, a 3-term vector or a string; '%s' is %s" name
      (V.kind_name v)
  in
  let storable = function V.Float _ | V.String _ -> true | V.Vector a -> Array.length a = 3 | _ -> false in
  match st.cur_elem with
  | Some (a, i) -> (
      match a.cells.(i) with
      | Some v when not (storable v) -> refuse v
      | Some _ | None -> fun v -> a.cells.(i) <- Some v)
  | None -> (
      if is_keyword name then Error.raise_at at "'%s' is a keyword; '#read' needs an identifier to store into" name;
      match lookup_cell st name with
      | None -> fun v -> Names.replace st.global name (ref v)
      | Some c when storable !c -> fun v -> c := v
      | Some c -> refuse !c)

let read st loc =
  expect st LParen "'(' after '#read'";
  let f, at = file_arg st "read" in
  let lx =
    match f.io with
    | V.Reading lx -> lx
    | V.Writing _ -> Error.raise_at at "cannot read from \"%s\": it is open for writing" f.path
    | V.Closed -> Error.raise_at at "the file \"%s\" is closed" f.path
  in
  ignore (accept st Comma);
  let next_value () =
    try data_value lx
    with Error.Scene_error e -> raise (Error.Scene_error { e with notes = e.notes @ [ (loc, "read by this #read") ] })
  in
  (* after the end of the data, the remaining identifiers are passed over *)
  let rec targets ended =
    let at = peek_loc st in
    match peek_name st with
    | RParen -> advance st; ended
    | Comma when ended -> advance st; targets ended
    | Ident _ when ended -> advance st; targets ended
    | Ident s ->
        let store = target st s at in
        advance st;
        let v, ended = next_value () in
        Option.iter store v;
        ignore (accept st Comma);
        targets ended
    | _ -> unexpected st "an identifier to read into, or ')'"
  in
  if targets false then close st f

(* ---------------------------------------------------------------------------------------------- *)
(* Writing *)

let text = function
  | V.String s -> Some s
  | V.Float x -> Some (Printf.sprintf "%g" x)
  | V.Vector a -> Some ("<" ^ String.concat "," (Array.to_list (Array.map (Printf.sprintf "%g") a)) ^ "> ")
  | _ -> None

(* The binary formats: the range a value is clamped to, its bytes, and whether big-endian. *)
let binary = function
  | "uint8" -> Some (0, 255, 1, false)
  | "sint8" -> Some (-128, 127, 1, false)
  | "uint16be" -> Some (0, 65535, 2, true)
  | "uint16le" -> Some (0, 65535, 2, false)
  | "sint16be" -> Some (-32768, 32767, 2, true)
  | "sint16le" -> Some (-32768, 32767, 2, false)
  | "sint32be" -> Some (-2147483648, 2147483647, 4, true)
  | "sint32le" -> Some (-2147483648, 2147483647, 4, false)
  | _ -> None

let write_binary oc (lo, hi, bytes, big) x =
  let v = if x <= float_of_int lo then lo else if x >= float_of_int hi then hi else int_of_float (Float.floor (x +. 0.5)) in
  for j = 0 to bytes - 1 do
    let shift = 8 * if big then bytes - 1 - j else j in
    output_byte oc ((v asr shift) land 0xFF)
  done

let write st loc =
  expect st LParen "'(' after '#write'";
  let f, at = file_arg st "write" in
  let oc =
    match f.io with
    | V.Writing oc -> oc
    | V.Reading _ -> Error.raise_at at "cannot write to \"%s\": it is open for reading" f.path
    | V.Closed -> Error.raise_at at "the file \"%s\" is closed" f.path
  in
  ignore (accept st Comma);
  let put out = try out () with Sys_error m -> write_failed loc f m in
  (* a binary format applies to the numbers after it up to the next comma *)
  let rec numbers fmt =
    match peek st with
    | Comma | RParen -> ()
    | _ -> (
        let l = peek_loc st in
        match Expr.parse_full st with
        | V.Float x -> put (fun () -> write_binary oc fmt x); numbers fmt
        | V.Vector a -> put (fun () -> Array.iter (write_binary oc fmt) a); numbers fmt
        | v -> Error.raise_at l "'#write' writes floats and vectors in binary, not %s" (V.kind_name v))
  in
  let rec items () =
    match peek st with
    | RParen -> advance st
    | Comma -> advance st; items ()
    | Ident k when binary k <> None -> advance st; numbers (Option.get (binary k)); items ()
    | _ -> (
        let l = peek_loc st in
        let v = Expr.parse_full st in
        match text v with
        | Some s -> put (fun () -> output_string oc s); items ()
        | None -> Error.raise_at l "'#write' writes strings, floats and vectors, not %s" (V.kind_name v))
  in
  items ();
  (* written at once, so that the file reads the same whatever else opens it *)
  put (fun () -> flush oc)
