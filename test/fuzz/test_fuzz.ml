(* The short deterministic fuzz run of make test: with a fixed seed, mutations of the scenes in
   scenes/, test/fuzz/seeds and test/bad go through the interpreter and an 8×8 render, and every outcome
   other than a scene or a located scene error fails the test, the input saved beside it.

   A mutator of our own rather than crowbar: crowbar's inputs are values built by generators, and
   without AFL it only samples them at random; mutating real scenes keeps most inputs close to
   valid, so the run reaches directives, macros and objects in its few seconds. AFL++ (make fuzz)
   is the long, coverage-guided run.

   Each input has a time budget: a CPU-time timer whose handler raises, and a wall-clock timer ten
   times longer left at its default action, which ends the process where the handler cannot run
   (a blocking system call, C code); the input being run is in fuzz_current.pov for that case.
   POVML_FUZZ_INPUTS sets the number of inputs, POVML_FUZZ_SEED the seed (for a longer run of
   different inputs by hand). *)

open Povml_fuzz

let inputs = try int_of_string (Sys.getenv "POVML_FUZZ_INPUTS") with Not_found | Failure _ -> 20_000
let seed = try int_of_string (Sys.getenv "POVML_FUZZ_SEED") with Not_found | Failure _ -> 6
let budget = 2.
let max_seed_bytes = 8192

(* the scenes of scenes/bench are left out: their loops run for seconds on purpose *)
let scene_dirs =
  [ "../../scenes"; "../../scenes/course"; "../../scenes/fidelity"; "../../scenes/stiff"; "seeds"; "../bad"; "../bad/fuzz" ]

let read path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

let seeds =
  List.concat_map
    (fun d ->
      if Sys.file_exists d then
        Sys.readdir d |> Array.to_list |> List.sort compare
        |> List.filter (fun f -> Filename.check_suffix f ".pov")
        |> List.map (Filename.concat d)
        |> List.filter (fun p -> (Unix.stat p).st_size <= max_seed_bytes)
      else [])
    scene_dirs
  |> Array.of_list

open Fuzz_io

let () =
  Printexc.record_backtrace true;
  if Array.length seeds < 20 then (Printf.eprintf "test_fuzz: only %d seed scenes found\n" (Array.length seeds); exit 1);
  let texts = Array.map read seeds in
  (* rewritten in place for each input: opening with truncation costs a millisecond on ext4 *)
  let current = Unix.openfile "fuzz_current.pov" [ O_WRONLY; O_CREAT ] 0o644 in
  let rng = Random.State.make [| seed; 4 |] in
  let scenes = ref 0 and refused = ref 0 and bugs = ref [] in
  let t0 = Unix.gettimeofday () in
  for i = 1 to inputs do
    let k = Random.State.int rng (Array.length seeds) in
    let text = Mutate.mutate rng ~seeds:texts texts.(k) in
    keep current text;
    match within budget (fun () -> Target.run ~file:seeds.(k) text) with
    | None -> bugs := (i, seeds.(k), text, Printf.sprintf "took more than %g s of CPU time" budget) :: !bugs
    | Some (Scene _) -> incr scenes
    | Some (Refused _) -> incr refused
    | Some (Bug msg) -> bugs := (i, seeds.(k), text, msg) :: !bugs
  done;
  Unix.close current;
  Sys.remove "fuzz_current.pov";
  let bugs = List.rev !bugs in
  Printf.printf "%d inputs from %d seed scenes in %.1f s: %d scenes, %d scene errors, %d bugs\n" inputs (Array.length seeds)
    (Unix.gettimeofday () -. t0) !scenes !refused (List.length bugs);
  let shown = 10 in
  List.iteri
    (fun n (i, seed, text, msg) ->
      if n < shown then begin
        let path = Printf.sprintf "fuzz_failure_%d.pov" i in
        write path text;
        Printf.printf "input %d (a mutation of %s, saved as %s): %s\n" i seed (Filename.concat (Sys.getcwd ()) path) msg
      end)
    bugs;
  if List.length bugs > shown then Printf.printf "… and %d more\n" (List.length bugs - shown);
  if bugs <> [] then exit 1
