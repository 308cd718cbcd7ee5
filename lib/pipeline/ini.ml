(* POV-Ray's .ini files (processoptions.cpp ParseFile) read into the switches they stand for. *)

(* What an ini option becomes: a switch povml reads; nothing, for the values povml follows
   in any case, for the values it follows (POV-Ray's defaults: Bounding_Method=1, Split_Unions=off
   …), other values a warning naming them. *)
type meaning = Switch of (string -> string option) | Include | Followed of (string -> bool)

let bool_of s =
  match String.lowercase_ascii s with
  | "on" | "true" | "yes" | "1" -> Some true
  | "off" | "false" | "no" | "0" -> Some false
  | _ -> None

let valued sw v = Some (sw ^ v)
let int_v sw v = Option.map (fun _ -> sw ^ v) (int_of_string_opt (String.trim v))
let float_v sw v = Option.map (fun _ -> sw ^ v) (float_of_string_opt (String.trim v))
let flag sw v = Option.map (fun b -> (if b then "+" else "-") ^ sw) (bool_of v)
let is_on v = bool_of v = Some true
let is_off v = bool_of v = Some false
let is x v = String.lowercase_ascii (String.trim v) = x
let any _ = true

(* The ini keys of POV-Ray 3.7 (RenderOptions_INI_Table), lowercased, with what povml makes of
   each; a key not listed is not one of POV-Ray's *)
let table =
  [ ("input_file_name", Switch (valued "+I")); ("output_file_name", Switch (valued "+O"));
    ("width", Switch (int_v "+W")); ("height", Switch (int_v "+H"));
    ("antialias", Switch (flag "A")); ("antialias_threshold", Switch (float_v "--antialias-threshold="));
    ("sampling_method", Switch (int_v "+AM")); ("antialias_depth", Switch (int_v "+R"));
    ("antialias_gamma", Switch (float_v "+AG")); ("jitter", Switch (flag "J"));
    ("jitter_amount", Switch (float_v "--jitter-amount=")); ("library_path", Switch (valued "+L"));
    ("clock", Switch (float_v "+K")); ("start_row", Switch (float_v "+SR")); ("end_row", Switch (float_v "+ER"));
    ("start_column", Switch (float_v "+SC")); ("end_column", Switch (float_v "+EC"));
    ("work_threads", Switch (int_v "+WT")); ("render_block_size", Switch (int_v "+BS"));
    ("display", Switch (flag "D")); ("verbose", Switch (flag "V"));
    ("output_file_type", Switch (fun v -> match String.uppercase_ascii v with "N" | "N8" -> Some "--format=png" | "P" -> Some "--format=ppm" | _ -> None));
    ("output_to_file", Switch (flag "F")); ("bounding", Switch (flag "MB"));
    ("bounding_threshold", Switch (int_v "--bounding-threshold="));
    ("initial_frame", Switch (int_v "+KFI")); ("final_frame", Switch (int_v "+KFF"));
    ("initial_clock", Switch (float_v "+KI")); ("final_clock", Switch (float_v "+KF"));
    ("cyclic_animation", Switch (flag "KC")); ("subset_start_frame", Switch (float_v "+SF"));
    ("subset_end_frame", Switch (float_v "+EF")); ("frame_step", Switch (int_v "--frame-step="));
    ("declare", Switch (fun v -> if String.contains v '=' then Some ("--declare=" ^ v) else None));
    ("include_ini", Include) ]
  (* what povml does in any case: POV-Ray's defaults, the options of features povml has not (a
     BSP tree, file outputs povml does not write), and what shows only on a display or console *)
  @ List.map
      (fun (k, follows) -> (String.lowercase_ascii k, Followed follows))
      [ ("Bounding_Method", is "1"); ("Remove_Bounds", is_on); ("Split_Unions", is_off); ("Continue_Trace", is_off);
        ("Pause_When_Done", is_off); ("Output_Alpha", is_off); ("Bits_Per_Color", is "8"); ("Bits_Per_Colour", is "8");
        ("File_Gamma", is "srgb"); ("Dither", is_off); ("Field_Render", is_off); ("Grayscale_Output", is_off);
        ("Clockless_Animation", is_off); ("Real_Time_Raytracing", is_off); ("High_Reproducibility", is_off);
        ("Quality", fun v -> match int_of_string_opt (String.trim v) with Some q -> q >= 9 | None -> false);
        ("Radiosity_From_File", is_off); ("Radiosity_To_File", is_off); ("Radiosity_Vain_Pretrace", is_on);
        ("Render_Block_Step", is "0"); ("Render_Pattern", is "0"); ("Create_Histogram", is_off); ("Version", is "3.7");
        ("Include_Header", is "") ]
  @ List.map
      (fun k -> (String.lowercase_ascii k, Followed (fun v -> is "" v || is_off v)))
      [ "All_File"; "Create_Ini"; "Debug_File"; "Fatal_File"; "Render_File"; "Statistic_File"; "Warning_File";
        "Pre_Scene_Command"; "Pre_Frame_Command"; "Post_Frame_Command"; "Post_Scene_Command"; "Fatal_Error_Command";
        "User_Abort_Command" ]
  @ List.map
      (fun k -> (String.lowercase_ascii k, Followed any))
      [ "All_Console"; "Debug_Console"; "Fatal_Console"; "Render_Console"; "Statistic_Console"; "Warning_Console";
        "Warning_Level"; "Append_File"; "Test_Abort"; "Test_Abort_Count"; "Display_Gamma"; "Palette"; "Video_Mode";
        "Preview_Start_Size"; "Preview_End_Size"; "Draw_Vistas"; "Light_Buffer"; "Vista_Buffer"; "Buffer_Output";
        "Buffer_Size"; "Max_Image_Buffer_Memory"; "Dither_Method"; "Odd_Field"; "Compression"; "Histogram_Name";
        "Histogram_Grid_Size"; "Histogram_Type"; "Pre_Scene_Return"; "Pre_Frame_Return"; "Post_Frame_Return";
        "Post_Scene_Return"; "Fatal_Error_Return"; "User_Abort_Return"; "Radiosity_File_Name"; "BSP_BaseAccessCost";
        "BSP_ChildAccessCost"; "BSP_ISectCost"; "BSP_MaxDepth"; "BSP_MissChance" ]

let is_ini name =
  let base = match String.index_opt name '[' with Some i -> String.sub name 0 i | None -> name in
  Filename.check_suffix (String.lowercase_ascii base) ".ini"

(* "file.ini[Section]": the file and the section (Parse_INI_Specification) *)
let specification loc spec =
  match String.index_opt spec '[' with
  | None -> (spec, None)
  | Some i -> (
      match String.index_from_opt spec i ']' with
      | None -> Error.raise_at loc "'%s': a section name opened with '[' needs its ']'" spec
      | Some j -> (String.sub spec 0 i, Some (String.sub spec (i + 1) (j - i - 1))))

(* A cursor over one file's text, with the line and column it has reached. *)
type cursor = { file : string; text : string; mutable pos : int; mutable line : int; mutable bol : int }

let peek c = if c.pos < String.length c.text then Some c.text.[c.pos] else None
let here c = { Loc.file = c.file; line = c.line; col = c.pos - c.bol + 1 }

let advance c =
  (match peek c with
  | Some '\n' -> c.line <- c.line + 1; c.bol <- c.pos + 1
  | Some '\r' when not (c.pos + 1 < String.length c.text && c.text.[c.pos + 1] = '\n') -> c.line <- c.line + 1; c.bol <- c.pos + 1
  | Some _ | None -> ());
  c.pos <- c.pos + 1

let rec skip_blanks c = match peek c with Some (' ' | '\t') -> advance c; skip_blanks c | _ -> ()
let rec skip_space c = match peek c with Some (' ' | '\t' | '\n' | '\r') -> advance c; skip_space c | _ -> ()
let rec skip_line c = match peek c with None -> () | Some '\n' -> advance c | Some _ -> advance c; skip_line c

(* Parse_INI_String: up to a space, ',', ';', '#', a quote (and for a key '[', ']', '='), or up to
   [stop]; a value with spaces in it reads on to the end of the line or a comment when it is
   followed by more than one word and no '=' (POV-Ray's "smart mode", for unquoted paths) *)
let word ?stop ?(key = false) c =
  let b = Buffer.create 16 in
  let rec go () =
    match (peek c, stop) with
    | None, _ -> ()
    | Some ch, Some s -> advance c; if ch <> s then (Buffer.add_char b ch; go ())
    | Some (' ' | '\t' | '\n' | '\r' | ',' | ';' | '#' | '"' | '\''), None -> ()
    | Some ('[' | ']' | '='), None when key -> ()
    | Some ch, None -> Buffer.add_char b ch; advance c; go ()
  in
  go ();
  Buffer.contents b

let value c =
  match peek c with
  | Some (('"' | '\'') as q) -> advance c; word ~stop:q c
  | _ ->
      let first = word c in
      (* an unquoted path with spaces: the rest of the line up to a comment, when no '=' follows *)
      let save = (c.pos, c.line, c.bol) in
      skip_blanks c;
      let rest_start = c.pos in
      let rec to_end () = match peek c with None | Some ('\n' | '\r' | ';' | '#') -> () | Some _ -> advance c; to_end () in
      to_end ();
      let rest = String.trim (String.sub c.text rest_start (c.pos - rest_start)) in
      if rest <> "" && first <> "" && (not (String.contains rest '=')) && rest.[0] <> ',' then first ^ " " ^ rest
      else begin
        let p, l, bl = save in
        c.pos <- p; c.line <- l; c.bol <- bl;
        first
      end

let read_file loc file =
  if Sys.file_exists file && Sys.is_directory file then Error.raise_at loc "cannot read the ini file \"%s\": it is a directory" file;
  match open_in_bin file with
  | exception Sys_error _ -> Error.raise_at loc "cannot open the ini file \"%s\"" file
  | ic -> (
      (* read to its end, so that a pipe (bash's <(…)) reads as a file does; an ini file is a few
         lines, and one past [max_bytes] is refused rather than held in memory *)
      let max_bytes = 1 lsl 24 in
      let read () =
        let b = Buffer.create 4096 and chunk = Bytes.create 65536 in
        let rec go () =
          let n = input ic chunk 0 (Bytes.length chunk) in
          if n > 0 then begin
            if Buffer.length b + n > max_bytes then Error.limit_at loc "the ini file \"%s\" is longer than %d bytes" file max_bytes;
            Buffer.add_subbytes b chunk 0 n;
            go ()
          end
        in
        go ();
        Buffer.contents b
      in
      match Fun.protect ~finally:(fun () -> close_in_noerr ic) read with
      | text -> text
      | exception Sys_error m -> Error.raise_at loc "cannot read the ini file \"%s\": %s" file m)

let rec expand ~warn ~depth loc spec =
  if depth > 16 then Error.raise_at loc "ini files include each other more than 16 deep";
  let file, section = specification loc spec in
  lines_of ~warn ~depth ~section file (read_file loc file)

(* the switches of an ini file's text *)
and lines_of ~warn ~depth ~section file text =
  let c = { file; text; pos = 0; line = 1; bol = 0 } in
  let out = ref [] in
  let emit s = out := s :: !out in
  (* the lines before the first section always count; a named section only when it was asked for *)
  let active = ref true in
  let rec lines () =
    skip_space c;
    match peek c with
    | None -> ()
    | Some '[' ->
        advance c;
        let name = word ~stop:']' c in
        active := (match section with Some s -> String.lowercase_ascii s = String.lowercase_ascii name | None -> false);
        lines ()
    | Some _ when not !active -> skip_line c; lines ()
    | Some (';' | '#') -> skip_line c; lines ()
    | Some ('+' | '-') ->
        let sw = word c in
        let sw = match peek c with Some (('"' | '\'') as q) -> advance c; sw ^ word ~stop:q c | _ -> sw in
        emit sw;
        lines ()
    | Some ch when ch = '_' || (Char.code ch < 128 && (match ch with 'a' .. 'z' | 'A' .. 'Z' | '0' .. '9' -> true | _ -> false)) ->
        let l = here c in
        let k = word ~key:true c in
        skip_blanks c;
        if peek c <> Some '=' then begin
          (* a plain word: another ini file, or the scene (ProcessUnknownString) *)
          let plain = k ^ word c in
          if is_ini plain then List.iter emit (List.rev (expand ~warn ~depth:(depth + 1) l (relative file plain)))
          else emit ("+I" ^ plain);
          lines ()
        end
        else begin
          advance c;
          skip_blanks c;
          let values = ref [ value c ] in
          skip_blanks c;
          while peek c = Some ',' do
            advance c;
            skip_blanks c;
            values := value c :: !values;
            skip_blanks c
          done;
          (match List.assoc_opt (String.lowercase_ascii k) table with
          | None -> Error.raise_at l "unknown ini option '%s' (POV-Ray 3.7 has no such key)" k
          | Some (Followed follows) ->
              List.iter
                (fun v -> if not (follows v) then warn (Error.warning l (Printf.sprintf "the ini option '%s=%s' is not supported yet; ignored" k v)))
                (List.rev !values)
          | Some Include -> List.iter (fun v -> List.iter emit (List.rev (expand ~warn ~depth:(depth + 1) l (relative file v)))) (List.rev !values)
          | Some (Switch make) ->
              List.iter
                (fun v ->
                  match make v with
                  | Some s -> emit s
                  | None -> Error.raise_at l "'%s' is not a value of the ini option '%s'" v k)
                (List.rev !values));
          skip_line c;
          lines ()
        end
    | Some ch -> Error.raise_at (here c) "unexpected '%c' in an ini file: expected an option (Key=Value), a switch or a section" ch
  in
  lines ();
  List.rev !out

(* POV-Ray opens an ini file named by another as given, from the current directory; povml also
   looks beside the naming file when the name is relative and not found *)
and relative from name =
  let base = match String.index_opt name '[' with Some i -> String.sub name 0 i | None -> name in
  if Filename.is_relative base && (not (Sys.file_exists base)) && Sys.file_exists (Filename.concat (Filename.dirname from) base) then
    Filename.concat (Filename.dirname from) name
  else name

let switches ~warn spec = expand ~warn ~depth:0 Loc.none spec

let is_option arg =
  match String.index_opt arg '=' with
  | Some i when i > 0 && arg.[0] <> '+' && arg.[0] <> '-' -> List.mem_assoc (String.lowercase_ascii (String.trim (String.sub arg 0 i))) table
  | Some _ | None -> false

let option ~warn arg = lines_of ~warn ~depth:0 ~section:None "<command line>" arg

(* Declare=NAME=VALUE as POV-Ray's front end passes it on: a quoted value is a string, anything
   else C's atof of it in single precision, declared as the front end declares its values *)
let declaration d =
  match String.index_opt d '=' with
  | None -> None
  | Some i ->
      let name = String.trim (String.sub d 0 i) and v = String.sub d (i + 1) (String.length d - i - 1) in
      let value =
        match String.index_opt v '"' with
        | Some q ->
            let rest = String.sub v (q + 1) (String.length v - q - 1) in
            Value.String (match String.index_opt rest '"' with Some e -> String.sub rest 0 e | None -> rest)
        | None ->
            (* atof: the longest prefix that is a number, 0 without one *)
            let v = String.trim v in
            let rec longest n = if n = 0 then 0. else match float_of_string_opt (String.sub v 0 n) with Some f -> f | None -> longest (n - 1) in
            Value.Float (Animation.declared (Precision.f32 (longest (String.length v))))
      in
      if name = "" then None else Some (name, value)

(* Process_povray_ini of POV-Ray's Unix front end: the file POVINI names, else the first of
   these that can be read *)
let default_file ~getenv ~readable =
  let home = match getenv "HOME" with Some h when h <> "" -> [ h ] | Some _ | None -> [] in
  let in_home sub = List.map (fun h -> Filename.concat h sub) home in
  let search =
    ("./povray.ini" :: in_home ".povray/3.7/povray.ini") @ ("/etc/povray/3.7/povray.ini" :: in_home ".povrayrc") @ [ "/etc/povray.ini" ]
  in
  match getenv "POVINI" with
  | Some f when readable f -> (Some f, [])
  | named ->
      let warnings =
        match named with
        | Some f -> [ Error.warning Loc.none (Printf.sprintf "the POVINI environment variable names \"%s\", which cannot be read; looking for povray.ini" f) ]
        | None -> []
      in
      (List.find_opt readable search, warnings)
