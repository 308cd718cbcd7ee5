(* The AFL++ target of the decoders: afl_image.exe FORMAT FILE reads FILE (AFL's @@) as FORMAT
   ("png", "gif", "pot", "jpeg", "ppm", "pgm", "tga", "ttf") through [Image_target.run] and aborts
   on a bug, as afl_main.exe does for scenes (SIGABRT is what AFL++ counts as a crash). The PNG
   target puts every chunk's CRC right first, so that mutations reach past the CRC check.
   Persistent mode as in afl_main.ml: up to [persistent_runs] inputs per process. *)

external reset_instrumentation : bool -> unit = "caml_reset_afl_instrumentation"

let persistent_signature = "##SIG_AFL_PERSISTENT##"
let persistent_runs = 1000

let read path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

let one kind path =
  match Povml_fuzz.Image_target.run ~fix_png_crcs:true kind (read path) with
  | Decoded | Refused _ -> ()
  | Bug msg ->
      prerr_endline ("povml decoder fuzz target: an exception escaped: " ^ msg);
      Unix.kill (Unix.getpid ()) Sys.sigabrt

let () =
  Printexc.record_backtrace true;
  ignore (Sys.getenv_opt persistent_signature);
  match Sys.argv with
  | [| _; name; path |] -> (
      match List.assoc_opt name Povml_fuzz.Image_target.kinds with
      | None ->
          prerr_endline ("afl_image: unknown format " ^ name);
          exit 2
      | Some kind ->
          if Sys.getenv_opt "__AFL_PERSISTENT" = None then one kind path
          else begin
            let pid = Unix.getpid () in
            reset_instrumentation true;
            for _ = 2 to persistent_runs do
              one kind path;
              Unix.kill pid Sys.sigstop;
              reset_instrumentation false
            done;
            one kind path
          end)
  | _ ->
      prerr_endline "usage: afl_image FORMAT FILE (FORMAT: png, gif, pot, jpeg, ppm, pgm, tga, ttf)";
      exit 2
