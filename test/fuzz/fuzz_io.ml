(* What the deterministic fuzz runs (test_fuzz, test_fuzz_images) share: writing an input, keeping
   the current one in a file rewritten in place, and the per-input CPU timer. *)

let write path text =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out oc) (fun () -> output_string oc text)

let keep fd text =
  ignore (Unix.lseek fd 0 SEEK_SET);
  ignore (Unix.write_substring fd text 0 (String.length text));
  Unix.ftruncate fd (String.length text)

let set_timer which seconds = ignore (Unix.setitimer which { Unix.it_interval = 0.; it_value = seconds })

exception Out_of_time

let within budget f =
  let timed_out = ref false in
  let before = Sys.signal Sys.sigvtalrm (Sys.Signal_handle (fun _ -> timed_out := true; raise Out_of_time)) in
  set_timer Unix.ITIMER_VIRTUAL budget;
  set_timer Unix.ITIMER_REAL (10. *. budget);
  (* the timer may also go off after the run, before it is stopped *)
  let outcome =
    try
      let o = f () in
      set_timer Unix.ITIMER_VIRTUAL 0.;
      Some o
    with Out_of_time -> None
  in
  set_timer Unix.ITIMER_VIRTUAL 0.;
  set_timer Unix.ITIMER_REAL 0.;
  Sys.set_signal Sys.sigvtalrm before;
  if !timed_out then None else outcome
