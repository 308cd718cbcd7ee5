(* Worker processes by fork. Task numbers go down one pipe that every worker reads (4-byte records:
   a pipe moves up to PIPE_BUF bytes atomically, so each read takes one whole task), results go
   back marshalled into one unlinked temporary file per worker. The parent keeps its heap as it is:
   nothing is compacted or copied before the fork, and pages the workers only read stay shared.

   No worker outlives the map for long: when the parent leaves [map] by an exception (an
   interrupt among them) it kills and reaps the workers, and a worker whose parent died (SIGKILL,
   where nothing can run) notices within half a second and exits. A worker never writes anywhere
   but its own result file, stderr, and the error pipe when its result file cannot be written (a
   full disk): the parent then says why, once. *)

exception Worker_failed of string
exception Cannot_write of string

(* a worker's status when its results could not be written; the reason goes down the error pipe *)
let status_cannot_write = 4

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

(* What a forked process does first, while the parent's [Interrupt.hold] still blocks SIGINT and
   SIGTERM (the mask is inherited, pending signals are not). *)
let become_worker parent =
  (* Ctrl-C reaches the whole process group: the parent alone decides, and kills its workers *)
  Sys.set_signal Sys.sigint Sys.Signal_ignore;
  Sys.set_signal Sys.sigterm Sys.Signal_default;
  (* a worker whose stderr was closed dies quietly on its progress line *)
  Sys.set_signal Sys.sigpipe Sys.Signal_default;
  (* the parent can die by SIGKILL: an orphan leaves within half a second, even inside a block *)
  let orphaned _ = if Unix.getppid () <> parent then Unix._exit 1 in
  Sys.set_signal Sys.sigalrm (Sys.Signal_handle orphaned);
  ignore (Unix.setitimer Unix.ITIMER_REAL { Unix.it_interval = 0.5; it_value = 0.5 });
  ignore (Unix.sigprocmask Unix.SIG_UNBLOCK [ Sys.sigint; Sys.sigterm ])

(* A result file that cannot be written (a full disk): the parent is told why, in one line. *)
exception Write_failed of string

let worker parent f items task_r out err_w =
  let oc = Unix.out_channel_of_descr out in
  let put write = try write () with Sys_error m -> raise (Write_failed m) in
  let buf = Bytes.create 4 in
  let rec loop () =
    if Unix.getppid () <> parent then Unix._exit 1;
    match read_task task_r buf with
    | None -> ()
    | Some i ->
        let r = f items.(i) in
        put (fun () -> Marshal.to_channel oc (i, r) [ Marshal.No_sharing ]);
        loop ()
  in
  let code =
    match loop (); put (fun () -> flush oc) with
    | () -> 0
    | exception Write_failed m ->
        let line = Bytes.of_string (m ^ "\n") in
        (try write_all err_w line 0 (Bytes.length line) with Unix.Unix_error _ -> ());
        status_cannot_write
    | exception e -> prerr_endline ("povml: render worker: " ^ Printexc.to_string e); 3
  in
  flush stderr;
  (* leave without the parent's at_exit handlers and buffered output *)
  Unix._exit code

let rec waitpid pid =
  match Unix.waitpid [] pid with
  | _, st -> st
  | exception Unix.Unix_error (Unix.EINTR, _, _) -> waitpid pid

(* OCaml numbers signals its own way (Sys.sigkill is -7): the name a user knows. *)
let signal_name s =
  let names =
    [ (Sys.sigkill, "SIGKILL"); (Sys.sigsegv, "SIGSEGV"); (Sys.sigterm, "SIGTERM"); (Sys.sigint, "SIGINT");
      (Sys.sigabrt, "SIGABRT"); (Sys.sigbus, "SIGBUS"); (Sys.sigpipe, "SIGPIPE"); (Sys.sigstop, "SIGSTOP") ]
  in
  match List.assoc_opt s names with Some n -> n | None -> Printf.sprintf "signal %d" s

(* The first reason a worker sent down the error pipe, once every worker has exited. *)
let reason err_r =
  let buf = Bytes.create 4096 in
  Unix.set_nonblock err_r;
  match Unix.read err_r buf 0 (Bytes.length buf) with
  | n when n > 0 -> List.hd (String.split_on_char '\n' (Bytes.sub_string buf 0 n))
  | _ | (exception Unix.Unix_error _) -> "a write failed"

(* The parent's side once the workers run: hand out the tasks, wait for every worker (removing it
   from [running]), then read the results. *)
let collect items n ~close task_w err_r outs running consume =
  let buf = Bytes.create 4 in
  (try
     for i = 0 to n - 1 do
       Bytes.set_int32_le buf 0 (Int32.of_int i);
       write_all task_w buf 0 4
     done
   with Unix.Unix_error (Unix.EPIPE, _, _) -> ());
  close task_w;
  let failed = ref None and cannot_write = ref false in
  List.iter
    (fun pid ->
      let st = waitpid pid in
      running := List.filter (fun p -> p <> pid) !running;
      match st with
      | Unix.WEXITED 0 -> ()
      | Unix.WEXITED c when c = status_cannot_write -> cannot_write := true
      | Unix.WEXITED c -> failed := Some (Printf.sprintf "a render worker failed (status %d)" c)
      | Unix.WSIGNALED s | Unix.WSTOPPED s -> failed := Some (Printf.sprintf "a render worker was killed (%s)" (signal_name s)))
    !running;
  (* a worker that died with the interrupt did not fail; one that died otherwise may have left its
     results cut short, so they are read only when every worker finished *)
  Interrupt.check ();
  if !cannot_write then raise (Cannot_write (Filename.get_temp_dir_name () ^ ": " ^ reason err_r));
  (match !failed with Some m -> raise (Worker_failed m) | None -> ());
  let finished = Array.make (Array.length items) false in
  Array.iter
    (fun fd ->
      ignore (Unix.lseek fd 0 Unix.SEEK_SET);
      let ic = Unix.in_channel_of_descr fd in
      try
        while true do
          let (i : int), r = Marshal.from_channel ic in
          finished.(i) <- true;
          consume i r
        done
      with End_of_file -> ())
    outs;
  if not (Array.for_all Fun.id finished) then raise (Worker_failed "a task was not done")

let iter ~workers f items consume =
  let items = Array.of_list items in
  let n = Array.length items in
  let workers = min workers n in
  if workers <= 1 then Array.iteri (fun i x -> consume i (f x)) items
  else begin
    flush_all ();
    let task_r, task_w = Unix.pipe ~cloexec:true () in
    let err_r, err_w = Unix.pipe ~cloexec:true () in
    let result_file _ =
      match Whole_file.temp_file (Filename.get_temp_dir_name ()) with
      | Error reason -> raise (Cannot_write reason)
      | Ok name ->
          let fd = Unix.openfile name [ Unix.O_RDWR; Unix.O_TRUNC; Unix.O_CLOEXEC ] 0o600 in
          Unix.unlink name;
          fd
    in
    let made = ref [] in
    let outs =
      match for i = 1 to workers do made := result_file i :: !made done with
      | () -> Array.of_list !made
      | exception e -> List.iter Unix.close (task_r :: task_w :: err_r :: err_w :: !made); raise e
    in
    let parent = Unix.getpid () in
    let running = ref [] in
    (* if every worker died, writing tasks must fail with EPIPE, not kill this process *)
    let pipe_handler = Sys.signal Sys.sigpipe Sys.Signal_ignore in
    let open_fds = ref (task_r :: task_w :: err_r :: err_w :: Array.to_list outs) in
    let close fd =
      if List.mem fd !open_fds then begin
        open_fds := List.filter (fun d -> d <> fd) !open_fds;
        try Unix.close fd with Unix.Unix_error _ -> ()
      end
    in
    let close_all () = List.iter close !open_fds; Sys.set_signal Sys.sigpipe pipe_handler in
    let start () =
      Interrupt.hold (fun () ->
          Array.iter
            (fun out ->
              match Unix.fork () with
              | 0 ->
                  (* the child never returns into the parent's code *)
                  (try Unix.close task_w; become_worker parent; worker parent f items task_r out err_w with _ -> ());
                  Unix._exit 3
              | pid -> running := pid :: !running)
            outs);
      running := List.rev !running;
      (* the workers hold the read end; once they are gone, writing a task fails with EPIPE *)
      close task_r;
      close err_w;
      Interrupt.check ()
    in
    match start (); collect items n ~close task_w err_r outs running consume with
    | () -> close_all ()
    | exception e ->
        (* kill and reap the workers still running, with signals held back so that this finishes *)
        Interrupt.hold (fun () ->
            List.iter (fun pid -> try Unix.kill pid Sys.sigkill with Unix.Unix_error _ -> ()) !running;
            List.iter (fun pid -> ignore (waitpid pid)) !running;
            close_all ());
        raise e
  end

let map ~workers f items =
  let results = Array.make (List.length items) None in
  iter ~workers f items (fun i r -> results.(i) <- Some r);
  Array.to_list (Array.map Option.get results)
