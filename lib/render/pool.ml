(* Worker processes by fork. Task numbers go down one pipe that every worker reads (4-byte records:
   a pipe moves up to PIPE_BUF bytes atomically, so each read takes one whole task), results go
   back marshalled into one unlinked temporary file per worker. The parent keeps its heap as it is:
   nothing is compacted or copied before the fork, and pages the workers only read stay shared. *)

exception Worker_failed of string

let read_task fd buf =
  let rec go () =
    match Unix.read fd buf 0 4 with
    | 4 -> Some (Bytes.get_int32_le buf 0 |> Int32.to_int)
    | 0 -> None
    | _ -> raise (Worker_failed "short read on the task pipe")
    | exception Unix.Unix_error (Unix.EINTR, _, _) -> go ()
  in
  go ()

let rec write_all fd buf off len =
  if len > 0 then
    match Unix.write fd buf off len with
    | k -> write_all fd buf (off + k) (len - k)
    | exception Unix.Unix_error (Unix.EINTR, _, _) -> write_all fd buf off len

let worker f items task_r out =
  let oc = Unix.out_channel_of_descr out in
  let buf = Bytes.create 4 in
  let rec loop () =
    match read_task task_r buf with
    | None -> ()
    | Some i ->
        Marshal.to_channel oc (i, f items.(i)) [ Marshal.No_sharing ];
        loop ()
  in
  let code =
    match loop () with
    | () -> flush oc; 0
    | exception e -> prerr_endline ("povml: render worker: " ^ Printexc.to_string e); 3
  in
  flush stderr;
  (* leave without the parent's at_exit handlers and buffered output *)
  Unix._exit code

let rec waitpid pid =
  match Unix.waitpid [] pid with
  | _, st -> st
  | exception Unix.Unix_error (Unix.EINTR, _, _) -> waitpid pid

let map ~workers f items =
  let items = Array.of_list items in
  let n = Array.length items in
  let workers = min workers n in
  if workers <= 1 then Array.to_list (Array.map f items)
  else begin
    flush_all ();
    let task_r, task_w = Unix.pipe ~cloexec:true () in
    let outs =
      Array.init workers (fun _ ->
          let name = Filename.temp_file "povml-worker" ".bin" in
          let fd = Unix.openfile name [ Unix.O_RDWR; Unix.O_TRUNC; Unix.O_CLOEXEC ] 0o600 in
          Unix.unlink name;
          fd)
    in
    let pids =
      Array.map
        (fun out ->
          match Unix.fork () with
          | 0 -> Unix.close task_w; worker f items task_r out
          | pid -> pid)
        outs
    in
    Unix.close task_r;
    (* if every worker died, writing tasks must fail with EPIPE, not kill this process *)
    let pipe_handler = Sys.signal Sys.sigpipe Sys.Signal_ignore in
    let buf = Bytes.create 4 in
    Fun.protect
      ~finally:(fun () -> Unix.close task_w; Sys.set_signal Sys.sigpipe pipe_handler)
      (fun () ->
        try
          for i = 0 to n - 1 do
            Bytes.set_int32_le buf 0 (Int32.of_int i);
            write_all task_w buf 0 4
          done
        with Unix.Unix_error (Unix.EPIPE, _, _) -> ());
    let failed = ref None in
    Array.iter
      (fun pid ->
        match waitpid pid with
        | Unix.WEXITED 0 -> ()
        | Unix.WEXITED c -> failed := Some (Printf.sprintf "a render worker failed (status %d)" c)
        | Unix.WSIGNALED s | Unix.WSTOPPED s -> failed := Some (Printf.sprintf "a render worker was killed (signal %d)" s))
      pids;
    let results = Array.make n None in
    Array.iter
      (fun fd ->
        ignore (Unix.lseek fd 0 Unix.SEEK_SET);
        let ic = Unix.in_channel_of_descr fd in
        (try
           while true do
             let (i : int), r = Marshal.from_channel ic in
             results.(i) <- Some r
           done
         with End_of_file -> ());
        close_in ic)
      outs;
    (match !failed with Some m -> raise (Worker_failed m) | None -> ());
    Array.to_list (Array.map (function Some r -> r | None -> raise (Worker_failed "a task was not done")) results)
  end
