(* povml's exit statuses, and the last word on a run that ends by a signal or an exception. *)

let scene_error (k : Error.kind) = match k with Scene -> 1 | Limit -> 3 | Access -> 4
let cannot_write = 5

(* EX_SOFTWARE of sysexits.h; cmdliner's own 123 … 125 are not used *)
let internal_error = 70

let man =
  [
    `S Cmdliner.Manpage.s_exit_status;
    `I ("0", "The image was written.");
    `I ("1", "The scene has an error (printed as file:line:column: error: … with the source line).");
    `I ("2", "Usage error: an unknown switch or a wrong value on the command line.");
    `I ("3", "The scene reached one of povml's limits (loop iterations, nesting, memory …).");
    `I ("4", "The scene asked for a file it may not read or write.");
    `I ("5", "The image could not be written: a full disk, a device that refuses it, a missing directory or \
               permission (the reason is printed; the previous file at the output path is unchanged).");
    `I ("70", "Internal error: a bug in povml (please report it).");
    `I ("130", "Interrupted by SIGINT (Ctrl-C): the render stopped, its worker processes were killed and no \
                image was written.");
    `I ("143", "Interrupted by SIGTERM, the same way.");
    `P "Whatever the status, an existing file at the output path is replaced only by a whole new image.";
  ]

let interrupted s =
  (* the progress line on a terminal is left open *)
  if Unix.isatty Unix.stderr then prerr_string "\r\027[K";
  Printf.eprintf "povml: interrupted by %s; no image was written\n%!" (Interrupt.name s);
  Interrupt.exit_status s

(* [Interrupt.disarm] comes first in each case, so that a second Ctrl-C cannot cut the report short *)
let guard run =
  match run () with
  | 0 -> Interrupt.disarm (); 0
  | code -> (
      Interrupt.disarm ();
      match Interrupt.received () with Some s -> interrupted s | None -> code)
  | exception e -> (
      Interrupt.disarm ();
      match Interrupt.received () with
      | Some s -> interrupted s
      | None -> (
          match e with
          | Out_of_memory ->
              (* what the interpreter's memory limit does not see: the render, the image *)
              Printf.eprintf
                "povml: error: the render needs more memory than the system gives this process (ulimit -v); \
                 no image was written (a smaller image, +W and +H, needs less)\n%!";
              scene_error Limit
          | e ->
              Printf.eprintf "povml: internal error: %s (please report it)\n%!" (Printexc.to_string e);
              internal_error))
