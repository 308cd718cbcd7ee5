(* Interrupt, and what Output and Pool do with it. Signal handlers belong to the whole process, so
   each case runs in a forked process of its own, which reports by its exit status. *)

let in_own_process name f () =
  flush_all ();
  match Unix.fork () with
  | 0 ->
      let code = match f () with () -> 0 | exception e -> prerr_endline (name ^ ": " ^ Printexc.to_string e); 1 in
      Unix._exit code
  | pid -> (
      match snd (Unix.waitpid [] pid) with
      | Unix.WEXITED 0 -> ()
      | Unix.WEXITED c -> Alcotest.failf "%s: status %d" name c
      | Unix.WSIGNALED s | Unix.WSTOPPED s -> Alcotest.failf "%s: signal %d" name s)

let self s = Unix.kill (Unix.getpid ()) s

(* Unix.kill runs the handler of a signal sent to this process before it returns *)
let raises f = match f () with _ -> false | exception Interrupt.Interrupted -> true

let check_received what expected = Alcotest.(check (option int)) what expected (Interrupt.received ())

let test_raises () =
  Interrupt.install ();
  check_received "nothing yet" None;
  Alcotest.(check bool) "SIGTERM raises" true (raises (fun () -> self Sys.sigterm));
  check_received "SIGTERM" (Some Sys.sigterm);
  Alcotest.(check bool) "a second signal raises too" true (raises (fun () -> self Sys.sigint));
  check_received "the first one counts" (Some Sys.sigterm);
  Alcotest.(check int) "status" 143 (Interrupt.exit_status Sys.sigterm)

let test_ignored () =
  Sys.set_signal Sys.sigint Sys.Signal_ignore;
  Interrupt.install ();
  Alcotest.(check bool) "SIGINT ignored at start stays ignored" false (raises (fun () -> self Sys.sigint));
  check_received "nothing" None

let test_hold () =
  Interrupt.install ();
  let r = Interrupt.hold (fun () -> self Sys.sigint; check_received "seen while held" (Some Sys.sigint); List.init 100_000 Fun.id) in
  Alcotest.(check int) "hold returns" 100_000 (List.length r);
  check_received "recorded" (Some Sys.sigint);
  Alcotest.(check bool) "not delivered again" false (raises (fun () -> ignore (List.init 100_000 Fun.id)));
  Alcotest.(check bool) "check raises" true (raises Interrupt.check);
  Alcotest.(check bool) "a later signal raises" true (raises (fun () -> self Sys.sigint))

let test_commit () =
  Interrupt.install ();
  Alcotest.(check bool) "Ok" true (Interrupt.commit (fun () -> Ok ()) = Ok ());
  Alcotest.(check bool) "after the commit a signal raises nothing" false (raises (fun () -> self Sys.sigint));
  check_received "but is recorded" (Some Sys.sigint)

let image = { Encode.width = 2; height = 1; pixels = Bytes.of_string "\001\002\003\250\251\252" }

let entries dir = List.sort compare (Array.to_list (Sys.readdir dir))

let with_dir f =
  let dir = Filename.temp_file "povml-interrupt" "" in
  Sys.remove dir;
  Unix.mkdir dir 0o700;
  Fun.protect ~finally:(fun () -> Array.iter (fun e -> Sys.remove (Filename.concat dir e)) (Sys.readdir dir); Unix.rmdir dir) (fun () -> f dir)

let test_output () =
  Interrupt.install ();
  with_dir (fun dir ->
      let path = Filename.concat dir "a.ppm" in
      let oc = open_out_bin path in
      output_string oc "previous";
      close_out oc;
      (* a signal that came during the render, or during the write (held back by an outer hold) *)
      Interrupt.hold (fun () -> self Sys.sigint);
      Alcotest.(check bool) "write raises Interrupted" true (raises (fun () -> Output.write Output.Ppm path image));
      Alcotest.(check string) "the previous file is unchanged" "previous" (let ic = open_in_bin path in
         let s = really_input_string ic (in_channel_length ic) in
         close_in ic;
         s);
      Alcotest.(check (list string)) "no temporary file" [ "a.ppm" ] (entries dir))

let test_output_during_write () =
  Interrupt.install ();
  with_dir (fun dir ->
      let path = Filename.concat dir "a.png" in
      let oc = open_out_bin path in
      output_string oc "previous";
      close_out oc;
      (* SIGINT once the temporary file exists: a timer looks for it every millisecond, and
         writing and syncing the 3 MB PNG of a million random pixels takes longer *)
      let writing () = Array.exists (fun e -> Filename.check_suffix e ".part") (Sys.readdir dir) in
      let sent = ref false in
      Sys.set_signal Sys.sigalrm (Sys.Signal_handle (fun _ -> if (not !sent) && writing () then (sent := true; self Sys.sigint)));
      ignore (Unix.setitimer Unix.ITIMER_REAL { Unix.it_interval = 0.001; it_value = 0.001 });
      let random = Random.State.make [| 34 |] in
      let big = { Encode.width = 1000; height = 1000; pixels = Bytes.init 3_000_000 (fun _ -> Char.chr (Random.State.int random 256)) } in
      let interrupted = raises (fun () -> Output.write Output.Png path big) in
      ignore (Unix.setitimer Unix.ITIMER_REAL { Unix.it_interval = 0.; it_value = 0. });
      Alcotest.(check bool) "SIGINT came during the write" true !sent;
      Alcotest.(check bool) "write raises Interrupted" true interrupted;
      Alcotest.(check string) "the previous file is unchanged" "previous"
        (let ic = open_in_bin path in
         let s = really_input_string ic (in_channel_length ic) in
         close_in ic;
         s);
      Alcotest.(check (list string)) "no temporary file" [ "a.png" ] (entries dir))

let test_output_fails () =
  with_dir (fun dir ->
      let path = Filename.concat dir "a.ppm" in
      match Output.write Output.Ppm (Filename.concat path "x.ppm") image with
      | Ok () -> Alcotest.fail "wrote into a missing directory"
      | Error m -> Alcotest.(check string) "names the directory" (path ^ ": No such file or directory; nothing was written") m)

let test_pool () =
  Interrupt.install ();
  let parent = Unix.getpid () in
  let task i =
    if i = 3 then Unix.kill parent Sys.sigint;
    Unix.sleepf 0.02;
    i
  in
  Alcotest.(check bool) "map raises Interrupted" true (raises (fun () -> Pool.map ~workers:2 task (List.init 1000 Fun.id)));
  (* every worker was reaped: this process has no child left *)
  Alcotest.(check bool) "no worker left" true
    (match Unix.waitpid [ Unix.WNOHANG ] (-1) with _ -> false | exception Unix.Unix_error (Unix.ECHILD, _, _) -> true)

let tests =
  List.map
    (fun (name, f) -> Alcotest.test_case name `Quick (in_own_process name f))
    [
      ("a signal raises Interrupted", test_raises);
      ("a signal ignored at start", test_ignored);
      ("hold", test_hold);
      ("commit", test_commit);
      ("Output.write after an interrupt", test_output);
      ("Output.write interrupted while writing", test_output_during_write);
      ("Output.write into a missing directory", test_output_fails);
      ("Pool.map interrupted", test_pool);
    ]
