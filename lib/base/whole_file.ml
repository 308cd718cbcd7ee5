(* Files written whole or not at all: a checked, synced temporary file renamed onto the name. *)

(* Where the bytes go: beside a file that the rename replaces, or into a file that stays (a
   device, a pipe, a socket, povml's own output stream: a rename would put a regular file where
   /dev/null or a terminal was). *)
type target = Replace of string | Into

let same_file (a : Unix.stats) (b : Unix.stats) = a.st_dev = b.st_dev && a.st_ino = b.st_ino

(* /dev/stdout redirected to a file: written into, so that the shell's redirection gets the bytes *)
let own_stream st =
  List.exists (fun fd -> match Unix.fstat fd with s -> same_file s st | exception Unix.Unix_error _ -> false) [ Unix.stdout; Unix.stderr ]

let target path =
  match Unix.lstat path with
  | exception Unix.Unix_error _ -> Replace path
  | { st_kind = S_REG | S_DIR; _ } -> Replace path
  | { st_kind = S_LNK; _ } -> (
      match Unix.stat path with
      | { st_kind = S_REG; _ } as st when not (own_stream st) -> (
          match Unix.realpath path with p -> Replace p | exception Unix.Unix_error _ -> Into)
      | _ | (exception Unix.Unix_error _) -> Into)
  | { st_kind = S_CHR | S_BLK | S_FIFO | S_SOCK; _ } -> Into

let rec write_one fd data off =
  if off < String.length data then
    match Unix.write_substring fd data off (String.length data - off) with
    | n -> write_one fd data (off + n)
    | exception Unix.Unix_error (EINTR, _, _) -> write_one fd data off

let write_all fd parts = List.iter (fun data -> write_one fd data 0) parts

(* [data] (its parts one after the other) into the open file [fd], synced when it is a regular file (a device or a pipe has
   nothing to sync), and [fd] closed: every step checked, the first failure raised. *)
let fill fd data =
  match
    write_all fd data;
    if (Unix.fstat fd).st_kind = S_REG then Unix.fsync fd
  with
  | () -> Unix.close fd
  | exception e -> (try Unix.close fd with Unix.Unix_error _ -> ()); raise e

(* The directory entry made by the rename reaches the disk too; a directory that cannot be synced
   (some file systems refuse) has still been renamed into. *)
let sync_dir dir =
  match Unix.openfile dir [ O_RDONLY; O_CLOEXEC ] 0 with
  | exception Unix.Unix_error _ -> ()
  | fd -> (try Unix.fsync fd with Unix.Unix_error _ -> ()); (try Unix.close fd with Unix.Unix_error _ -> ())

let temp_file dir =
  match Filename.temp_file ~temp_dir:dir ".povml-" ".part" with
  | tmp -> Ok tmp
  | exception Sys_error msg ->
      (* the message names the file, which was never made: the directory and the reason *)
      let reason = match String.rindex_opt msg ':' with Some i -> String.trim (String.sub msg (i + 1) (String.length msg - i - 1)) | None -> msg in
      Error (dir ^ ": " ^ reason)

let replace path data =
  if Sys.file_exists path && Sys.is_directory path then Error "it is a directory; nothing was written" else
  let dir = Filename.dirname path in
  let outcome = if Sys.file_exists path then "the old file is kept" else "nothing was written" in
  match temp_file dir with
  | Error reason -> Error (reason ^ "; " ^ outcome)
  | Ok tmp -> (
      let discard () = try Sys.remove tmp with Sys_error _ -> () in
      match
        fill (Unix.openfile tmp [ O_WRONLY; O_TRUNC; O_CLOEXEC ] 0) data;
        Interrupt.check ();
        (* the temporary file is private; the file gets ordinary permissions *)
        (try Unix.chmod tmp 0o644 with Unix.Unix_error _ -> ());
        Unix.rename tmp path
      with
      | () -> sync_dir dir; Ok ()
      | exception Interrupt.Interrupted -> discard (); raise Interrupt.Interrupted
      | exception Unix.Unix_error (e, _, _) -> discard (); Error (Unix.error_message e ^ "; " ^ outcome))

let write_into path data =
  match fill (Unix.openfile path [ O_WRONLY; O_CLOEXEC ] 0) data with
  | () -> Ok ()
  | exception Unix.Unix_error (e, _, _) -> Error (Unix.error_message e)

let write_parts path data =
  Interrupt.hold (fun () ->
      Interrupt.check ();
      match target path with Replace p -> replace p data | Into -> write_into path data)

let write path data = write_parts path [ data ]
