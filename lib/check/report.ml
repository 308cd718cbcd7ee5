(* povml report: the sweep run over every scene by both renderers, and its tables and plot written. *)

type config = {
  povml : string;
  povray : string;
  out_dir : string;
  switches : string list;
  runs : int;
  truth : string list;
  settings : Sweep.setting list;
  progress : string -> unit;
}

let default_truth = [ "+AM2"; "+R5"; "+A0.0" ]

let rec mkdir_p d =
  if not (Sys.file_exists d) then (
    let parent = Filename.dirname d in
    if parent <> d then mkdir_p parent;
    try Unix.mkdir d 0o755 with Unix.Unix_error (Unix.EEXIST, _, _) -> ())

let unix_message = function
  | Unix.Unix_error (e, _, _) -> Unix.error_message e
  | Sys_error m -> m
  | e -> Printexc.to_string e

let prepare_out_dir dir =
  match mkdir_p dir with
  | exception e -> Error (Printf.sprintf "cannot create the output directory %s: %s" dir (unix_message e))
  | () ->
      if not (Sys.is_directory dir) then Error (Printf.sprintf "the output directory %s is not a directory" dir)
      else
        let probe = Filename.concat dir ".povml-report-probe" in
        match open_out probe with
        | exception Sys_error m -> Error (Printf.sprintf "cannot write in the output directory %s: %s" dir m)
        | oc -> close_out oc; (try Sys.remove probe with Sys_error _ -> ()); Ok ()

let stems paths =
  let seen = Hashtbl.create 8 in
  List.map
    (fun p ->
      let base = Filename.remove_extension (Filename.basename p) in
      let n = try Hashtbl.find seen base + 1 with Not_found -> 1 in
      Hashtbl.replace seen base n;
      if n = 1 then base else Printf.sprintf "%s-%d" base n)
    paths

let read_file path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

(* whole or not at all; a failure raises Sys_error with the reason *)
let write_file path text = match Whole_file.write path text with Ok () -> () | Error reason -> raise (Sys_error reason)

let int_switch k default switches =
  match List.rev (List.filter (fun s -> Switches.key s = Some k) switches) with
  | s :: _ -> ( match int_of_string_opt (Switches.value s) with Some n -> n | None -> default)
  | [] -> default

let short f = Printf.sprintf "%.3f s" f

let measure_scene c ~dir ~stem path =
  let cwd = Sys.getcwd () in
  let abs = if Filename.is_relative path then Filename.concat cwd path else path in
  let common = Switches.for_renderers ~cwd ~scene:abs c.switches in
  let shown = Switches.shown c.switches in
  let out = Filename.concat dir "out.png" in
  let povml = Runner.Povml c.povml and povray = Runner.Povray c.povray in
  let name = Filename.basename path in
  c.progress (Printf.sprintf "%s: ground truth, POV-Ray %s …" name (String.concat " " c.truth));
  let truth = Runner.render ~shown:path povray ~dir ~scene:abs ~out (common @ c.truth) in
  match truth.image with
  | Error f -> Error (Printf.sprintf "the ground truth (POV-Ray %s) failed: %s" (String.concat " " c.truth) f.message)
  | Ok truth_img ->
      c.progress (Printf.sprintf "%s: ground truth in %s" name (short truth.seconds));
      let text = lazy (read_file abs) in
      (* a copy of the scene with the overriding global_settings, once per scene and level, under its
         own name (stems are unique in the report) *)
      let scene_for (s : Sweep.setting) =
        match s.trace_level with
        | None -> abs
        | Some n ->
            let sub = Filename.concat dir (Printf.sprintf "%s.mtl%d" stem n) in
            let copy = Filename.concat sub (Filename.basename abs) in
            if not (Sys.file_exists copy) then (
              mkdir_p sub;
              write_file copy (Sweep.with_trace_level (Lazy.force text) n));
            copy
      in
      let total = List.length c.settings in
      let rows =
        List.mapi
          (fun i (s : Sweep.setting) ->
            let scene = scene_for s in
            let args = common @ Sweep.switches s in
            (* runs alternate between the renderers; a renderer that fails is not run again *)
            let state = [| `Times []; `Times [] |] and first = [| None; None |] in
            for _ = 1 to max 1 c.runs do
              List.iteri
                (fun k r ->
                  match state.(k) with
                  | `Failed _ -> ()
                  | `Times ts -> (
                      let o = Runner.render ~shown:path r ~dir ~scene ~out args in
                      match o.image with
                      | Error f -> state.(k) <- `Failed f
                      | Ok img ->
                          if first.(k) = None then first.(k) <- Some img;
                          state.(k) <- `Times (o.seconds :: ts)))
                [ povml; povray ]
            done;
            let measured k : Sweep.measured =
              match (state.(k), first.(k)) with
              | `Failed (f : Runner.failure), _ -> if f.unsupported then Not_supported f.message else Failed f.message
              | `Times ts, Some img -> (
                  match Compare.images img truth_img with
                  | Ok cmp -> Rendered { times = List.rev ts; median = Runner.median ts; cmp }
                  | Error m -> Failed ("cannot compare with the ground truth: " ^ m))
              | `Times _, None -> Failed "no run"
            in
            let row = { Sweep.setting = s; povml = measured 0; povray = measured 1 } in
            let show = function
              | Sweep.Rendered m -> Printf.sprintf "%7.3f s  RMSE %7.3f" m.median m.cmp.rmse
              | Sweep.Not_supported _ -> "not supported       "
              | Sweep.Failed m -> "failed: " ^ m
            in
            c.progress
              (Printf.sprintf "%s [%*d/%d] %-36s povml %s   POV-Ray %s" name (String.length (string_of_int total)) (i + 1) total
                 (Sweep.label s) (show row.povml) (show row.povray));
            row)
          c.settings
      in
      Ok
        {
          Sweep.path;
          stem;
          width = int_switch "W" 160 c.switches;
          height = int_switch "H" 120 c.switches;
          switches = shown;
          truth = c.truth;
          truth_seconds = truth.seconds;
          runs = max 1 c.runs;
          rows;
        }

let write c scenes =
  let files =
    [ ("report.csv", Tables.csv scenes);
      ("report.md", Tables.markdown ~plot:(fun (sc : Sweep.scene) -> Some (sc.stem ^ ".svg")) scenes);
      ("report.svg", Plot.svg scenes) ]
    @ List.map (fun (sc : Sweep.scene) -> (sc.stem ^ ".svg", Plot.svg [ sc ])) scenes
  in
  let rec go acc = function
    | [] -> Ok (List.rev acc)
    | (name, text) :: rest -> (
        let path = Filename.concat c.out_dir name in
        match write_file path text with
        | () -> go (path :: acc) rest
        | exception e -> Error (Printf.sprintf "cannot write %s: %s" path (unix_message e)))
  in
  go [] files

let run c paths =
  let dir = Runner.temp_dir "povml-report" in
  Fun.protect ~finally:(fun () -> Runner.remove_tree dir) (fun () ->
      let rec go done_ failed = function
        | [] -> (
            let scenes = List.rev done_ in
            match if scenes = [] then write c [] else Ok [] with
            | Error m -> Error m
            | Ok _ -> Ok (scenes, List.rev failed))
        | (path, stem) :: rest -> (
            let measured = try measure_scene c ~dir ~stem path with (Sys_error _ | Unix.Unix_error _) as e -> Error (unix_message e) in
            match measured with
            | Error m ->
                c.progress (Printf.sprintf "%s: %s" (Filename.basename path) m);
                go done_ ((path, m) :: failed) rest
            | Ok sc -> (
                let done_ = sc :: done_ in
                match write c (List.rev done_) with
                | Error m -> Error m
                | Ok _ -> go done_ failed rest))
      in
      go [] [] (List.combine paths (stems paths)))
