(* The AFL++ target: reads the scene named on the command line (AFL's @@), or stdin, runs it
   through [Target.run], and aborts on a bug. AFL++ counts only a signal as a crash, so a bug ends
   with SIGABRT rather than an exit status. Outside afl-fuzz this is an ordinary program, for
   reproducing a crash: afl_main.exe FILE.

   The OCaml runtime has its own fork server (runtime/afl.c), started when afl-fuzz has set
   __AFL_SHM_ID. It also has a persistent mode: a child that stops itself with SIGSTOP is sent
   SIGCONT for the next input instead of being replaced by a new fork. An input takes well under a
   millisecond and a fork several, so the target runs up to [persistent_runs] inputs per process
   when afl-fuzz asks for it (it sets __AFL_PERSISTENT when the binary holds the string below).
   The interpreter keeps no state between scenes, so one input cannot change the next. *)

external reset_instrumentation : bool -> unit = "caml_reset_afl_instrumentation"

let persistent_signature = "##SIG_AFL_PERSISTENT##"
let persistent_runs = 1000

let read_all ic =
  let buf = Buffer.create 4096 in
  let chunk = Bytes.create 4096 in
  let rec go () =
    let n = input ic chunk 0 4096 in
    if n > 0 then (Buffer.add_subbytes buf chunk 0 n; go ())
  in
  go ();
  Buffer.contents buf

let one () =
  let file, text =
    match Sys.argv with
    | [| _; path |] ->
        let ic = open_in_bin path in
        let text = Fun.protect ~finally:(fun () -> close_in ic) (fun () -> read_all ic) in
        (path, text)
    | _ -> ("stdin.pov", read_all stdin)
  in
  match Povml_fuzz.Target.run ~file text with
  | Scene _ | Refused _ -> ()
  | Bug msg ->
      prerr_endline ("povml fuzz target: not a scene and not a scene error: " ^ msg);
      Unix.kill (Unix.getpid ()) Sys.sigabrt

let () =
  Printexc.record_backtrace true;
  (* the signature must be in the binary; reading it as a variable keeps it there *)
  ignore (Sys.getenv_opt persistent_signature);
  if Sys.getenv_opt "__AFL_PERSISTENT" = None || Sys.argv = [| Sys.argv.(0) |] then one ()
  else begin
    let pid = Unix.getpid () in
    reset_instrumentation true;
    for _ = 2 to persistent_runs do
      one ();
      Unix.kill pid Sys.sigstop;
      reset_instrumentation false
    done;
    one ()
  end
