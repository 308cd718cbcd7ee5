(* povml check and povml report: their command lines. POV-Ray switches are taken out of the
   arguments before cmdliner sees the rest; the work is done by the library (Check, Report). *)

open Cmdliner

let exit_usage = 2
let exit_render_failed = 3
let exit_no_povray = 4

let fail ~sub code fmt = Printf.ksprintf (fun m -> Printf.eprintf "povml %s: error: %s\n%!" sub m; code) fmt

(* A POV-Ray switch: '+' or '-' then a letter ("-5" is a number, "--x" a long option). *)
let is_switch a =
  String.length a >= 2 && (a.[0] = '+' || (a.[0] = '-' && a.[1] <> '-' && not (a.[1] >= '0' && a.[1] <= '9'))) && a <> "-h"

(* ---------------------------------------------------------------------------------------------- *)
(* Converters *)

let int_list =
  let one s =
    match String.split_on_char '-' (String.trim s) with
    | [ n ] -> Option.map (fun n -> [ n ]) (int_of_string_opt n)
    | [ a; b ] -> (
        match (int_of_string_opt a, int_of_string_opt b) with
        | Some a, Some b when a <= b -> Some (List.init (b - a + 1) (fun i -> a + i))
        | _ -> None)
    | _ -> None
  in
  let parse s =
    if String.trim s = "" || s = "none" then Ok []
    else
      let parts = List.map one (String.split_on_char ',' s) in
      if List.mem None parts then Error (`Msg (Printf.sprintf "expected integers and ranges like 1-4,8, got '%s'" s))
      else Ok (List.concat_map Option.get parts)
  in
  Arg.conv (parse, fun ppf l -> Format.pp_print_string ppf (String.concat "," (List.map string_of_int l)))

let float_list =
  let parse s =
    if String.trim s = "" || s = "none" then Ok []
    else
      let parts = List.map (fun x -> float_of_string_opt (String.trim x)) (String.split_on_char ',' s) in
      if List.mem None parts then Error (`Msg (Printf.sprintf "expected numbers separated by commas, got '%s'" s))
      else Ok (List.map Option.get parts)
  in
  Arg.conv (parse, fun ppf l -> Format.pp_print_string ppf (String.concat "," (List.map Sweep.threshold l)))

let parts_conv : [ `Aa | `Trace ] list Arg.conv = Arg.list (Arg.enum [ ("aa", `Aa); ("trace", `Trace) ])

let povray_opt =
  Arg.(value & opt (some string) None & info [ "povray" ] ~docv:"PATH"
         ~doc:"POV-Ray's executable. Default: the environment variable $(b,POVRAY), else $(b,povray) in $(b,PATH).")

let povray_env = Cmd.Env.info "POVRAY" ~doc:"POV-Ray's executable, when $(b,--povray) is not given."

let common_man =
  [ `P "Both renderers run as separate processes in a private directory under /tmp, with the same \
        switches: those given, $(b,+W160 +H120 +WT2) unless given, $(b,-D -V +FN), and $(b,+L) the scene's \
        directory and the working directory (so include files resolve as they would beside the scene). \
        POV-Ray reads an empty ini file (environment $(b,POVINI)), not the system's povray.ini, whose \
        800×600 and display would otherwise apply. The wall time is that of the whole process: \
        start-up, parsing, rendering and writing the PNG." ]

(* ---------------------------------------------------------------------------------------------- *)
(* povml check *)

let check_cmd ~switches ~input ~output =
  let run positional povray runs max_differing max_peak min_psnr =
    let sub = "check" in
    let scene = match (input, positional) with Some i, _ -> Some i | None, p -> p in
    match scene with
    | None -> fail ~sub exit_usage "no scene file given: povml check SCENE [switches]"
    | Some scene when not (Sys.file_exists scene) -> fail ~sub exit_usage "scene file not found: %s" scene
    | Some scene -> (
        match Runner.find_povray povray with
        | Error m -> fail ~sub exit_no_povray "%s" m
        | Ok povray -> (
            let thresholds = { Check.max_differing; max_peak; min_psnr } in
            let config = { Check.povml = Sys.executable_name; povray; scene; output; switches; runs = max 1 runs; thresholds } in
            match Check.run config with
            | exception e -> fail ~sub exit_render_failed "%s" (match e with Unix.Unix_error (e, f, _) -> f ^ ": " ^ Unix.error_message e | Sys_error m | Failure m -> m | e -> Printexc.to_string e)
            | Error (Check.Render_failed m) -> fail ~sub exit_render_failed "%s" m
            | Error (Check.Cannot_write m) -> fail ~sub exit_render_failed "cannot write an image: %s" m
            | Ok o ->
                print_string (Check.summary o);
                if o.violations = [] then 0 else 1))
  in
  let scene = Arg.(value & pos 0 (some string) None & info [] ~docv:"SCENE" ~doc:"The scene file (or +I$(i,file)).") in
  let runs = Arg.(value & opt int 1 & info [ "runs" ] ~docv:"N" ~doc:"Render N times with each renderer (alternating) and report the median wall times (default 1).") in
  let max_differing =
    Arg.(value & opt (some float) None & info [ "max-differing" ] ~docv:"SHARE"
           ~doc:"Fail (exit 1) when the share of differing pixels, 0 … 1, is above SHARE; $(b,--max-differing 0) requires identical images.")
  in
  let max_peak = Arg.(value & opt (some int) None & info [ "max-peak" ] ~docv:"N" ~doc:"Fail (exit 1) when some channel differs by more than N/255.") in
  let min_psnr = Arg.(value & opt (some float) None & info [ "min-psnr" ] ~docv:"DB" ~doc:"Fail (exit 1) when the PSNR is below DB decibels.") in
  let man =
    [ `S Manpage.s_synopsis;
      `P "$(b,povml check) [$(i,OPTION)]… $(i,SCENE) [$(i,SWITCH)]…";
      `S Manpage.s_description;
      `P "$(b,povml check) renders $(i,SCENE) with povml and with the installed POV-Ray 3.7, compares the two PNGs \
          and prints both wall times and their ratio, the number and share of differing pixels, the peak \
          channel difference, the RMSE (both in 1/255 units) and the PSNR.";
      `P "$(i,SWITCH)es are POV-Ray switches as $(b,povml --help) lists them ($(b,+W), $(b,+H), $(b,+A), $(b,+R), \
          $(b,+J), $(b,+L), $(b,+K), $(b,+WT) …); $(b,+O)$(i,file) names povml's image (default: the scene's \
          name with .png, beside the scene). POV-Ray's image is written beside it as $(i,name)$(b,-povray.png) \
          and a heat map of the differences as $(i,name)$(b,-diff.png): equal pixels in dark grey (povml's \
          image, dimmed), differing ones from blue (1/255) through magenta and red to yellow (the peak \
          difference of the image)." ]
    @ common_man
    @ [ `S Manpage.s_exit_status;
        `P "0: both rendered and no threshold is exceeded (without thresholds, whenever both rendered); \
            1: a threshold is exceeded; 2: usage error (unknown switch, no or missing scene file); \
            3: a renderer failed (its first error line is printed), the images differ in size or cannot be written; \
            4: POV-Ray was not found.";
        `S Manpage.s_examples;
        `P "povml check scenes/bench/spheres.pov +W320 +H240 +A0.3 --max-differing 0" ]
  in
  let info =
    Cmd.info "check" ~doc:"render a scene with povml and with POV-Ray and compare the images" ~man ~exits:[]
      ~envs:[ povray_env ]
  in
  Cmd.v info Term.(const run $ scene $ povray_opt $ runs $ max_differing $ max_peak $ min_psnr)

(* ---------------------------------------------------------------------------------------------- *)
(* povml report *)

let report_cmd ~switches ~input =
  let run positional out povray runs parts thresholds depths methods trace_levels truth =
    let sub = "report" in
    let scenes = Option.to_list input @ positional in
    let swept = List.filter (fun s -> match Switches.key s with Some ("A" | "AM" | "R" | "O" | "F") -> true | _ -> false) switches in
    let truth_list = List.filter (( <> ) "") (String.split_on_char ' ' truth) in
    match (scenes, out) with
    | [], _ -> fail ~sub exit_usage "no scene file given: povml report SCENES… --out DIR"
    | _, None -> fail ~sub exit_usage "no output directory given: --out DIR"
    | _, Some out -> (
        match (List.find_opt (fun s -> not (Sys.file_exists s)) scenes, swept, List.find_opt (fun s -> not (is_switch s)) truth_list) with
        | Some s, _, _ -> fail ~sub exit_usage "scene file not found: %s" s
        | None, s :: _, _ -> fail ~sub exit_usage "%s: the report sweeps +A, +AM and +R itself and names its own images (+O, +F)" s
        | None, [], Some t -> fail ~sub exit_usage "--truth: '%s' is not a POV-Ray switch" t
        | None, [], None -> (
            match Runner.find_povray povray with
            | Error m -> fail ~sub exit_no_povray "%s" m
            | Ok povray -> (
                match Report.prepare_out_dir out with
                | Error m -> fail ~sub 1 "%s" m
                | Ok () -> (
                    let settings =
                      Sweep.settings ~aa:(List.mem `Aa parts) ~trace:(List.mem `Trace parts) ~thresholds ~methods ~depths ~trace_levels
                    in
                    let config =
                      { Report.povml = Sys.executable_name; povray; out_dir = out; switches; runs = max 1 runs; truth = truth_list;
                        settings; progress = (fun l -> prerr_endline l) }
                    in
                    Printf.eprintf "povml report: %d scene(s), %d settings, %d run(s) each with povml and POV-Ray\n%!"
                      (List.length scenes) (List.length settings) (max 1 runs);
                    match Report.run config scenes with
                    | exception e -> fail ~sub 1 "%s" (match e with Unix.Unix_error (e, f, _) -> f ^ ": " ^ Unix.error_message e | Sys_error m | Failure m -> m | e -> Printexc.to_string e)
                    | Error m -> fail ~sub 1 "%s" m
                    | Ok (measured, failed) ->
                        List.iter
                          (fun f -> Printf.printf "%s\n" (Filename.concat out f))
                          ([ "report.csv"; "report.md"; "report.svg" ] @ List.map (fun (sc : Sweep.scene) -> sc.stem ^ ".svg") measured);
                        if failed = [] then 0
                        else (
                          List.iter (fun (p, m) -> Printf.eprintf "povml report: %s was not measured: %s\n" p m) failed;
                          1)))))
  in
  let scenes = Arg.(value & pos_all string [] & info [] ~docv:"SCENE" ~doc:"The scene files (or +I$(i,file)).") in
  let out = Arg.(value & opt (some string) None & info [ "out" ] ~docv:"DIR" ~doc:"The output directory (created when missing). Required.") in
  let runs = Arg.(value & opt int 3 & info [ "runs" ] ~docv:"N" ~doc:"Timed runs per setting and renderer; the median is reported (default 3).") in
  let parts =
    Arg.(value & opt parts_conv [ `Aa; `Trace ] & info [ "parts" ] ~docv:"PARTS"
           ~doc:"Which sweeps to run, comma-separated: $(b,aa) (no antialiasing, then every method × depth × threshold) \
                 and $(b,trace) (no antialiasing, each max_trace_level). Default: aa,trace.")
  in
  let thresholds =
    Arg.(value & opt float_list [ 0.9; 0.8; 0.7; 0.6; 0.5; 0.4; 0.3; 0.2; 0.1; 0.0 ] & info [ "thresholds" ] ~docv:"LIST"
           ~doc:"Antialiasing thresholds (+A) of the aa sweep.")
  in
  let depths = Arg.(value & opt int_list [ 1; 2; 3; 4 ] & info [ "depths" ] ~docv:"LIST" ~doc:"Supersampling depths (+R) of the aa sweep; ranges like 1-4 allowed.") in
  let methods = Arg.(value & opt int_list [ 1; 2 ] & info [ "methods" ] ~docv:"LIST" ~doc:"Antialiasing methods (+AM) of the aa sweep.") in
  let trace_levels =
    Arg.(value & opt int_list (List.init 20 (fun i -> i + 1)) & info [ "trace-levels" ] ~docv:"LIST"
           ~doc:"max_trace_level values of the trace sweep (default 1-20).")
  in
  let truth =
    Arg.(value & opt string "+AM2 +R5 +A0.0" & info [ "truth" ] ~docv:"SWITCHES"
           ~doc:"The switches of the ground truth, rendered once per scene by POV-Ray with the scene's own max_trace_level.")
  in
  let man =
    [ `S Manpage.s_synopsis;
      `P "$(b,povml report) [$(i,OPTION)]… $(i,SCENE)… $(b,--out) $(i,DIR) [$(i,SWITCH)]…";
      `S Manpage.s_description;
      `P "$(b,povml report) measures, for each scene, how the settings that trade error for time do in povml and in \
          POV-Ray: antialiasing off, every antialiasing method × depth ($(b,+R)) × threshold ($(b,+A)), and, without antialiasing, \
          max_trace_level 1 … 20 (set by a copy of the scene that ends with a $(b,global_settings) block, \
          which both renderers let override the scene's). Each image is compared with one ground truth per \
          scene: POV-Ray's image with $(b,--truth) (default $(b,+AM2 +R5 +A0.0)); each setting is rendered \
          $(b,--runs) times by each renderer and the median wall time kept.";
      `P "It writes into $(i,DIR): $(b,report.csv) (a line per scene, setting and renderer: times, RMSE, PSNR, \
          share of differing pixels, peak, Pareto front), $(b,report.md) (a table per scene), $(b,report.svg) \
          (RMSE against time on log scales, one panel per scene, each renderer's Pareto front joined) and \
          one $(i,scene)$(b,.svg) per scene. The files are rewritten after each scene. A setting a renderer \
          refuses is recorded as not supported and left out of the plot; a progress line per setting goes \
          to stderr.";
      `P "$(i,SWITCH)es are POV-Ray switches given to every render ($(b,+W), $(b,+H), $(b,+WT), $(b,+L), $(b,+K), \
          $(b,+J) …); not $(b,+A), $(b,+AM), $(b,+R) (swept) or $(b,+O), $(b,+F)." ]
    @ common_man
    @ [ `S Manpage.s_exit_status;
        `P "0: every scene measured; 1: a scene's ground truth failed (the others are still measured) or the \
            output directory cannot be written; 2: usage error; 4: POV-Ray was not found.";
        `S Manpage.s_examples;
        `P "povml report scenes/bench/spheres.pov --out report +W320 +H240";
        `P "povml report scenes/bench/*.pov --out report +W160 +H120 --runs 1 --parts aa --methods 1 --depths 2,3" ]
  in
  let info =
    Cmd.info "report" ~doc:"error against time of povml and POV-Ray over antialiasing and trace-depth settings" ~man ~exits:[]
      ~envs:[ povray_env ]
  in
  Cmd.v info Term.(const run $ scenes $ out $ povray_opt $ runs $ parts $ thresholds $ depths $ methods $ trace_levels $ truth)

(* ---------------------------------------------------------------------------------------------- *)

let main ~translate prog sub rest =
  let switches = List.filter is_switch rest and others = List.filter (fun a -> not (is_switch a)) rest in
  let bad = List.find_opt (fun s -> match translate s with `Bad -> true | _ -> false) switches in
  let valued k = List.filter_map (fun s -> if Switches.key s = Some k then Some (Switches.value s) else None) switches in
  let last = function [] -> None | l -> Some (List.nth l (List.length l - 1)) in
  match bad with
  | Some a -> fail ~sub exit_usage "unknown or incomplete switch '%s' (see povml --help)" a
  | None -> (
      let input = last (valued "I") in
      let plain = List.filter (fun s -> match Switches.key s with Some ("I" | "O") -> false | _ -> true) switches in
      let cmd =
        match sub with
        | "check" -> check_cmd ~switches:plain ~input ~output:(last (valued "O"))
        | _ -> report_cmd ~switches:(List.filter (fun s -> Switches.key s <> Some "I") switches) ~input
      in
      let group = Cmd.group (Cmd.info "povml" ~version:"0.1.0") [ cmd ] in
      match Cmd.eval_value ~argv:(Array.of_list (prog :: sub :: others)) group with
      | Ok (`Ok code) -> code
      | Ok (`Version | `Help) -> 0
      | Error (`Parse | `Term) -> exit_usage
      | Error `Exn -> exit_render_failed)

(* povml merge OUT PART…: partial renders put back together (Merge) *)
let merge prog = function
  | [] | [ _ ] | ("-h" | "--help") :: _ ->
      Printf.eprintf
        "usage: %s merge OUT PART...\n\
        \  joins partial renders (+SR/+ER/+SC/+EC, PNGs written by povml) into OUT, the image one render writes;\n\
        \  the parts must have one size and cover it without overlap\n"
        prog;
      2
  | out :: parts -> (
      match Merge.merge ~warn:(Printf.eprintf "povml merge: warning: %s\n") parts with
      | Error msg -> Printf.eprintf "povml merge: error: %s\n" msg; 1
      | Ok img -> (
          let full = Merge.to_text { Merge.left = 0; top = 0; right = img.width - 1; bottom = img.height - 1; block = 32 } in
          match Output.write ~area:full Output.Png out img with
          | Error msg -> Printf.eprintf "povml merge: error: cannot write %s: %s\n" out msg; 5
          | Ok () -> Printf.eprintf "Wrote %s (%dx%d) from %d parts\n" out img.width img.height (List.length parts); 0))
