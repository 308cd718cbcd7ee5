(* The short deterministic fuzz run of the decoders in make test: with a fixed seed, mutations
   (Byte_mutate) of the small real files in image_seeds/<format>/ (and of POV-Ray's own fonts)
   and of the corpus AFL++ grew from them (image_corpus/<format>/) go through each decoder and every pixel is read back (Image_target); any exception other than
   the decoder's own refusal fails the test, the input saved beside it. Half the PNG inputs get
   their CRCs put right first, so that they reach past the CRC check.

   Each input has a CPU-time budget, as in test_fuzz.ml; the input being run is in
   fuzz_image_current, for a crash in C code (libjpeg). POVML_FUZZ_IMAGE_INPUTS sets the number
   of inputs per format, POVML_FUZZ_SEED the seed, POVML_FUZZ_IMAGE_FORMATS the formats (png,gif,…),
   POVML_FUZZ_IMAGE_DUMP a directory to write every input to. *)

open Povml_fuzz

let inputs = try int_of_string (Sys.getenv "POVML_FUZZ_IMAGE_INPUTS") with Not_found | Failure _ -> 10_000
let seed = try int_of_string (Sys.getenv "POVML_FUZZ_SEED") with Not_found | Failure _ -> 6
let budget = 2.

(* POVML_FUZZ_IMAGE_FORMATS: the targets to run, comma-separated (all by default) *)
let formats =
  match Sys.getenv_opt "POVML_FUZZ_IMAGE_FORMATS" with
  | Some l -> List.filter (fun (n, _) -> List.mem n (String.split_on_char ',' l)) Image_target.kinds
  | None -> Image_target.kinds

let read path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))

(* the seed files of a format: its directory of image_seeds, or POV-Ray's fonts *)
let seed_files name =
  match name with
  | "ttf" ->
      List.map (Filename.concat Access.standard_include_dir) [ "povlogo.ttf"; "crystal.ttf" ] |> List.filter Sys.file_exists
  | _ ->
      let dir = Filename.concat "image_seeds" (if name = "pot" then "gif" else name) in
      Sys.readdir dir |> Array.to_list |> List.sort compare |> List.map (Filename.concat dir)

(* the corpus AFL++ found from them (make fuzz, minimised with afl-cmin): more files to mutate,
   valid or not *)
let corpus_files name =
  let dir = Filename.concat "image_corpus" name in
  if Sys.file_exists dir then Sys.readdir dir |> Array.to_list |> List.sort compare |> List.map (Filename.concat dir) else []

(* POVML_FUZZ_IMAGE_DUMP: a directory where every input is also written, to replay them elsewhere *)
let dump = Sys.getenv_opt "POVML_FUZZ_IMAGE_DUMP"

open Fuzz_io

let () =
  Printexc.record_backtrace true;
  let failed = ref false in
  let current = Unix.openfile "fuzz_image_current" [ O_WRONLY; O_CREAT ] 0o644 in
  List.iteri
    (fun f (name, kind) ->
      let files = seed_files name in
      if List.length files < (if name = "ttf" then 1 else 3) then begin
        Printf.printf "%s: only %d seed files found\n" name (List.length files);
        failed := true
      end
      else begin
        let seeds = List.length files in
        let files = files @ corpus_files name in
        let texts = Array.of_list (List.map read files) in
        let files = Array.of_list files in
        let rng = Random.State.make [| seed; 34; f |] in
        let decoded = ref 0 and refused = ref 0 and bugs = ref [] in
        let t0 = Unix.gettimeofday () in
        (* the seeds themselves first: each must decode *)
        Array.iteri
          (fun i t ->
            match Image_target.run kind t with
            | Decoded -> ()
            | Refused _ when i >= seeds -> ()
            | Refused m | Bug m -> bugs := (-i - 1, files.(i), t, "the seed itself: " ^ m) :: !bugs)
          texts;
        for i = 1 to inputs do
          let k = Random.State.int rng (Array.length texts) in
          let data = Byte_mutate.mutate rng ~seeds:texts texts.(k) in
          (* where a crash in C code (libjpeg) leaves the input that caused it *)
          keep current data;
          Option.iter (fun dir -> write (Filename.concat dir (Printf.sprintf "%s_%05d.%s" name i name)) data) dump;
          match within budget (fun () -> Image_target.run ~fix_png_crcs:(i land 1 = 0) kind data) with
          | None -> bugs := (i, files.(k), data, Printf.sprintf "took more than %g s of CPU time" budget) :: !bugs
          | Some Decoded -> incr decoded
          | Some (Refused _) -> incr refused
          | Some (Bug m) -> bugs := (i, files.(k), data, m) :: !bugs
        done;
        let bugs = List.rev !bugs in
        Printf.printf "%s: %d inputs from %d seed and corpus files in %.1f s: %d decoded, %d refused, %d bugs\n" name inputs (Array.length files)
          (Unix.gettimeofday () -. t0) !decoded !refused (List.length bugs);
        List.iteri
          (fun n (i, seed, data, msg) ->
            if n < 5 then begin
              let path = Printf.sprintf "fuzz_image_failure_%s_%d.%s" name i name in
              write path data;
              Printf.printf "  input %d (a mutation of %s, saved as %s): %s\n" i seed (Filename.concat (Sys.getcwd ()) path) msg
            end)
          bugs;
        if bugs <> [] then failed := true
      end)
    formats;
  Unix.close current;
  Sys.remove "fuzz_image_current";
  if !failed then exit 1
