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
