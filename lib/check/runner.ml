(* Running povml and POV-Ray as separate processes: finding POV-Ray, private directories, timing,
   and what a failed render said. *)

type renderer = Povml of string | Povray of string

let name = function Povml _ -> "povml" | Povray _ -> "POV-Ray"

let executable p = try Unix.access p [ Unix.X_OK ]; not (Sys.is_directory p) with Unix.Unix_error _ | Sys_error _ -> false

let in_path prog =
  let path = try Sys.getenv "PATH" with Not_found -> "" in
  List.find_map
    (fun d -> if d = "" then None else let p = Filename.concat d prog in if executable p then Some p else None)
    (String.split_on_char ':' path)

let install_hint = "install POV-Ray 3.7 (Debian/Ubuntu: apt-get install povray) or name its executable with --povray PATH or the POVRAY environment variable"

let find_povray path =
  let given = match path with Some p -> Some (p, "--povray") | None -> Option.map (fun p -> (p, "POVRAY")) (Sys.getenv_opt "POVRAY") in
  match given with
  | Some (p, from) ->
      let p = if Filename.is_implicit p && not (String.contains p '/') then Option.value (in_path p) ~default:p else p in
      let p = if Filename.is_relative p then Filename.concat (Sys.getcwd ()) p else p in
      if executable p then Ok p else Error (Printf.sprintf "POV-Ray was not found: '%s' (from %s) is not an executable file; %s" p from install_hint)
  | None -> (
      match in_path "povray" with
      | Some p -> Ok p
      | None -> Error (Printf.sprintf "POV-Ray was not found: no 'povray' in PATH; %s" install_hint))

let rec remove_tree p =
  match Unix.lstat p with
  | exception Unix.Unix_error _ -> ()
  | { st_kind = S_DIR; _ } ->
      (try Array.iter (fun f -> remove_tree (Filename.concat p f)) (Sys.readdir p) with Sys_error _ -> ());
      (try Unix.rmdir p with Unix.Unix_error _ -> ())
  | _ -> ( try Unix.unlink p with Unix.Unix_error _ -> ())

let temp_dir prefix =
  let base = if Sys.file_exists "/tmp" then "/tmp" else Filename.get_temp_dir_name () in
  let rec attempt n =
    let d = Filename.concat base (Printf.sprintf "%s.%d.%06x" prefix (Unix.getpid ()) (Random.bits () land 0xffffff)) in
    match Unix.mkdir d 0o700 with
    | () -> d
    | exception Unix.Unix_error (Unix.EEXIST, _, _) when n > 0 -> attempt (n - 1)
  in
  Random.self_init ();
  attempt 100

(* POV-Ray complains on every run when the user's configuration file is missing. *)
let ensure_user_conf () =
  match Sys.getenv_opt "HOME" with
  | None -> ()
  | Some home -> (
      let dir = Filename.concat (Filename.concat home ".povray") "3.7" in
      let conf = Filename.concat dir "povray.conf" in
      if not (Sys.file_exists conf) then
        try
          List.iter (fun d -> if not (Sys.file_exists d) then Unix.mkdir d 0o755) [ Filename.concat home ".povray"; dir ];
          close_out (open_out conf)
        with Unix.Unix_error _ | Sys_error _ -> ())

type failure = { code : int; message : string; unsupported : bool }
type outcome = { seconds : float; image : (Encode.t, failure) result }

let read_lines path =
  match open_in_bin path with
  | exception Sys_error _ -> []
  | ic ->
      let rec go acc = match input_line ic with l -> go (l :: acc) | exception End_of_file -> close_in ic; List.rev acc in
      go []

let lower_contains ~sub s =
  let s = String.lowercase_ascii s in
  let ls = String.length s and lsub = String.length sub in
  let rec go i = i + lsub <= ls && (String.sub s i lsub = sub || go (i + 1)) in
  go 0

(* The first line that speaks of an error, with (when [join]) the continuation lines POV-Ray wraps
   it into (they start with a space); else the last line of output. *)
let failure_message ~join lines =
  let rec find = function
    | [] -> None
    | l :: rest when lower_contains ~sub:"error" l ->
        let rec cont acc = function
          | c :: more when join && String.length c > 0 && c.[0] = ' ' -> cont (acc ^ " " ^ String.trim c) more
          | _ -> acc
        in
        Some (cont (String.trim l) rest)
    | _ :: rest -> find rest
  in
  let m =
    match find lines with
    | Some m -> m
    | None -> ( match List.rev (List.filter (fun l -> String.trim l <> "") lines) with l :: _ -> String.trim l | [] -> "no output")
  in
  if String.length m > 240 then String.sub m 0 237 ^ "..." else m

(* Both renderers read the same empty ini file ([ini]) before the switches: what Debian's
   povray.ini or the user's would add (a size, a bounding threshold) stays out of the comparison. *)
let environment ~ini =
  let others = List.filter (fun v -> not (String.length v >= 7 && String.sub v 0 7 = "POVINI=")) (Array.to_list (Unix.environment ())) in
  Array.of_list (others @ [ "POVINI=" ^ ini ])

(* libpng warns on stderr about the PNGs POV-Ray writes ("Interlace handling should be turned on")
   when camlimages reads them; the warning says nothing about the image. *)
let quietly f =
  flush stderr;
  match Unix.dup Unix.stderr with
  | exception Unix.Unix_error _ -> f ()
  | saved ->
      (try
         let null = Unix.openfile "/dev/null" [ O_WRONLY ] 0 in
         Unix.dup2 null Unix.stderr;
         Unix.close null
       with Unix.Unix_error _ -> ());
      Fun.protect ~finally:(fun () -> Unix.dup2 saved Unix.stderr; Unix.close saved) f

let replace_all ~sub ~by s =
  let ls = String.length s and lsub = String.length sub in
  if lsub = 0 then s
  else
    let b = Buffer.create ls in
    let rec go i =
      if i > ls - lsub then Buffer.add_string b (String.sub s i (ls - i))
      else if String.sub s i lsub = sub then (Buffer.add_string b by; go (i + lsub))
      else (Buffer.add_char b s.[i]; go (i + 1))
    in
    go 0;
    Buffer.contents b

let render ?shown r ~dir ~scene ~out switches =
  let exe = match r with Povml exe -> exe | Povray exe -> ensure_user_conf (); exe in
  let ini = Filename.concat dir "clean.ini" in
  if not (Sys.file_exists ini) then close_out (open_out ini);
  let env = environment ~ini in
  let log = Filename.concat dir "render.log" in
  (try Sys.remove out with Sys_error _ -> ());
  let args = Array.of_list (exe :: ("+I" ^ scene) :: ("+O" ^ out) :: switches) in
  flush stdout;
  flush stderr;
  let t0 = Unix.gettimeofday () in
  let status =
    match Unix.fork () with
    | 0 -> (
        try
          Unix.chdir dir;
          let fd = Unix.openfile log [ O_WRONLY; O_CREAT; O_TRUNC ] 0o644 in
          let null = Unix.openfile "/dev/null" [ O_RDONLY ] 0 in
          Unix.dup2 null Unix.stdin;
          Unix.dup2 fd Unix.stdout;
          Unix.dup2 fd Unix.stderr;
          Unix.execve exe args env
        with e ->
          prerr_endline (Printf.sprintf "cannot run %s: %s" exe (match e with Unix.Unix_error (e, _, _) -> Unix.error_message e | e -> Printexc.to_string e));
          Unix._exit 127)
    | pid ->
        let rec wait () = match Unix.waitpid [] pid with _, st -> st | exception Unix.Unix_error (EINTR, _, _) -> wait () in
        wait ()
  in
  let seconds = Unix.gettimeofday () -. t0 in
  let code = match status with WEXITED c -> c | WSIGNALED s | WSTOPPED s -> 128 + abs s in
  let failed message = { seconds; image = Error { code; message; unsupported = (match r with Povml _ -> code = 2 | Povray _ -> false) || lower_contains ~sub:"not supported" message } } in
  let shown m = match shown with Some name -> replace_all ~sub:scene ~by:name m | None -> m in
  if code <> 0 then failed (shown (failure_message ~join:(match r with Povray _ -> true | Povml _ -> false) (read_lines log)))
  else if not (Sys.file_exists out) then failed "exited 0 but wrote no image"
  else
    match quietly (fun () -> Output.read_png out) with
    | Ok img -> { seconds; image = Ok img }
    | Error m -> failed ("cannot read its image: " ^ m)

let median xs =
  match List.sort compare xs with
  | [] -> nan
  | s ->
      let n = List.length s in
      if n mod 2 = 1 then List.nth s (n / 2) else (List.nth s ((n / 2) - 1) +. List.nth s (n / 2)) /. 2.
