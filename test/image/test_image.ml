(* Image tests: each (scene, options) line of reference/manifest.tsv is rendered with the povml
   executable and compared with POV-Ray 3.7.0.10's reference PNG. The thresholds come from the
   manifest, never from this file: the most pixels that may differ (0 for every image identical
   to POV-Ray's; a row with differences records their measured count and why) and the largest
   difference in a channel. *)

let povml = ref ""
let summary = ref [] (* lines of the report printed after the run *)

type case = { name : string; scene : string; options : string list; max_differing : int; max_peak : int; reason : string }

let read_manifest path =
  let ic = open_in path in
  let rec lines acc = match input_line ic with l -> lines (l :: acc) | exception End_of_file -> close_in ic; List.rev acc in
  lines []
  |> List.filter (fun l -> String.trim l <> "" && l.[0] <> '#')
  |> List.tl (* header *)
  |> List.map (fun l ->
         match String.split_on_char '\t' l with
         | name :: scene :: options :: mi :: mp :: reason ->
             {
               name;
               scene;
               options = List.filter (( <> ) "") (String.split_on_char ' ' options);
               max_differing = int_of_string mi;
               max_peak = int_of_string mp;
               reason = String.concat "\t" reason;
             }
         | _ -> failwith ("malformed manifest line: " ^ l))

(* povml reads the ini file POV-Ray made the references with, and no other *)
let () = Unix.putenv "POVINI" (Filename.concat (Sys.getcwd ()) "../../reference/povray.ini")

let run_povml args =
  let cmd = Filename.quote_command !povml args ~stdout:"/dev/null" ~stderr:"/dev/null" in
  Sys.command cmd

let render case out extra = run_povml ([ "+I" ^ case.scene; "+O" ^ out; "-D" ] @ case.options @ extra)

let load path = match Output.read_png path with Ok i -> i | Error e -> Alcotest.failf "%s: %s" path e

let check case () =
  let out = Filename.temp_file ("povml-" ^ case.name) ".png" in
  let code = render case out [] in
  Alcotest.(check int) (case.name ^ ": povml exit status") 0 code;
  let mine = load out and theirs = load (Filename.concat "reference" (case.name ^ ".png")) in
  Sys.remove out;
  match Compare.images mine theirs with
  | Error e -> Alcotest.fail e
  | Ok c ->
      let share = Compare.identical_share c in
      summary :=
        Printf.sprintf "%-36s %9.4f%% identical %6d differing  peak %3d/255   (needs <= %d differing, peak <= %d)" case.name
          (100. *. share) c.differing c.peak case.max_differing case.max_peak
        :: !summary;
      if c.differing > case.max_differing then
        Alcotest.failf "%s: %d %s from POV-Ray's (the manifest allows %d)" case.name c.differing
          (if c.differing = 1 then "pixel differs" else "pixels differ")
          case.max_differing;
      if c.peak > case.max_peak then Alcotest.failf "%s: peak channel error %d/255 exceeds %d" case.name c.peak case.max_peak

(* The image must not depend on the number of render processes (§ issue: both cores). *)
let same_for_any_thread_count case () =
  let a = Filename.temp_file "povml-wt1" ".png" and b = Filename.temp_file "povml-wt2" ".png" in
  Alcotest.(check int) "exit +WT1" 0 (render case a [ "+WT1" ]);
  Alcotest.(check int) "exit +WT2" 0 (render case b [ "+WT2" ]);
  let ia = load a and ib = load b in
  Sys.remove a;
  Sys.remove b;
  Alcotest.(check bool) "identical pixels for +WT1 and +WT2" true (Bytes.equal ia.pixels ib.pixels)

let () =
  povml := (if Filename.is_relative Sys.argv.(1) then Filename.concat (Sys.getcwd ()) Sys.argv.(1) else Sys.argv.(1));
  Sys.chdir "../..";
  let cases = read_manifest "reference/manifest.tsv" in
  let aa = List.find (fun c -> List.exists (fun o -> String.length o > 1 && String.sub o 0 2 = "+A") c.options) cases in
  let report () =
    print_endline "povml against POV-Ray 3.7.0.10 (reference/manifest.tsv):";
    List.iter print_endline (List.rev !summary)
  in
  match
    Alcotest.run ~and_exit:false ~argv:[| "test_image" |] "images"
      [
        ("against POV-Ray", List.map (fun c -> Alcotest.test_case c.name `Quick (check c)) cases);
        ("determinism", [ Alcotest.test_case ("+WT1 = +WT2 on " ^ aa.name) `Quick (same_for_any_thread_count aa) ]);
      ]
  with
  | () -> report ()
  | exception e -> report (); raise e
