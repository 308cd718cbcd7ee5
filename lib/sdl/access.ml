(* The file-access policy. Directories are kept as given and resolved when a file is checked, so
   the working directory and directories created during the run are seen as they are then. *)

type t = { read : string list; write : string list }

let standard_include_dir = "/usr/share/povray-3.7/include"
(* Debian installs the include directory's fonts (cyrvetic.ttf, timrom.ttf, …) as symbolic links
   into this directory; POV-Ray reads them through the include directory (§15.9) *)
let standard_font_dir = "/usr/share/fonts/truetype/povray"
let default = { read = [ Filename.current_dir_name; standard_include_dir; standard_font_dir ]; write = [] }
let allow_read t dir = { t with read = t.read @ [ dir ] }
let allow_write t dir = { t with write = t.write @ [ dir ] }

let realpath p = try Some (Unix.realpath p) with Unix.Unix_error _ -> None

(* [path] (resolved) is [root] (resolved) or inside it. *)
let under path root =
  root = "/"
  || path = root
  || String.length path > String.length root
     && String.sub path 0 (String.length root) = root
     && path.[String.length root] = '/'

let inside roots path = List.exists (fun r -> match realpath r with Some r -> under path r | None -> false) roots

(* POV-Ray's rule too: a directory a scene may write to, it may also read. *)
let readable t path = match realpath path with Some p -> inside (t.read @ t.write) p | None -> false

(* A file to be written may not exist yet, nor its directories: the nearest one that exists is
   resolved and the names after it are appended (opening fails later if a directory is missing).
   A symbolic link that leads nowhere does not resolve and is refused, since opening it would
   create its target wherever it points; so is a missing name followed by "..". *)
let rec resolved_for_writing path =
  match Unix.lstat path with
  | _ -> realpath path
  | exception Unix.Unix_error _ ->
      let dir = Filename.dirname path and base = Filename.basename path in
      if base = Filename.current_dir_name || base = Filename.parent_dir_name || dir = path then None
      else Option.map (fun d -> Filename.concat d base) (resolved_for_writing dir)

let writable t path = match resolved_for_writing path with Some p -> inside t.write p | None -> false

let check_read t loc path =
  if not (readable t path) then
    Error.access_at loc
      "reading \"%s\" is not allowed: it is outside the scene's directory, the working directory and the library paths (allow it with --allow-read DIR)"
      path

let check_write t loc path =
  if not (writable t path) then
    if t.write = [] then
      Error.access_at loc "writing \"%s\" is not allowed: scenes may write files only under a directory given with --allow-write DIR" path
    else
      Error.access_at loc "writing \"%s\" is not allowed: it is outside the directories given with --allow-write (allow it with --allow-write DIR)" path
