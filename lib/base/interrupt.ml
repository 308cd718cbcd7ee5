(* SIGINT and SIGTERM during a render: a handler that records the signal and raises [Interrupted],
   and the holds that keep it back where the work must not stop half-way. *)

(* In OCaml 4.13 a signal handler runs at the next allocation or blocking system call of the
   program (a blocked waitpid or read returns EINTR, as the runtime installs handlers without
   SA_RESTART), so a handler may raise: parsing and tracing allocate all the time. Signal
   dispositions and the signal mask are state of the whole process; the three references below
   are their OCaml side and live as long as it does. *)

exception Interrupted

let signals = [ Sys.sigint; Sys.sigterm ]

(* the signals [install] took over, the first one that arrived, and how many [hold]s are running
   (while one is, or after [commit], the handler records and does not raise) *)
let installed = ref []
let first = ref None
let holding = ref 0

let record s = if !first = None && List.mem s !installed then first := Some s

let handler s =
  record s;
  if !holding = 0 then raise Interrupted

let install () =
  List.iter
    (fun s ->
      match Sys.signal s (Sys.Signal_handle handler) with
      | Sys.Signal_ignore -> Sys.set_signal s Sys.Signal_ignore
      | Sys.Signal_default | Sys.Signal_handle _ -> if not (List.mem s !installed) then installed := s :: !installed)
    signals

(* A blocked signal waits in the kernel, where the handler has not seen it yet. *)
let record_blocked () = if !holding > 0 then List.iter record (Unix.sigpending ())

let received () =
  record_blocked ();
  !first

let check () = if received () <> None then raise Interrupted

let hold f =
  (* counted first: a signal already on its way when the mask changes must not raise either *)
  incr holding;
  let old = Unix.sigprocmask Unix.SIG_BLOCK signals in
  let release () =
    let blocked = Unix.sigpending () in
    List.iter
      (fun s ->
        if List.mem s blocked && List.mem s !installed then begin
          record s;
          (* POSIX drops a pending signal whose action becomes "ignore": recorded, it is not
             delivered again when the mask is restored *)
          let h = Sys.signal s Sys.Signal_ignore in
          Sys.set_signal s h
        end)
      signals;
    ignore (Unix.sigprocmask Unix.SIG_SETMASK old);
    decr holding
  in
  match f () with
  | v -> release (); v
  | exception e -> release (); raise e

(* a hold that never ends *)
let disarm () = incr holding

let commit f =
  hold (fun () ->
      match f () with
      | Ok _ as r -> disarm (); r
      | Error _ as r -> r)

let exit_status s = if s = Sys.sigterm then 143 else 130
let name s = if s = Sys.sigterm then "SIGTERM" else "SIGINT"
