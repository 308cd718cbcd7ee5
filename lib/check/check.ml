(* povml check: one scene rendered by both renderers, compared, judged against the thresholds. *)

type thresholds = { max_differing : float option; max_peak : int option; min_psnr : float option }

type config = {
  povml : string;
  povray : string;
  scene : string;
  output : string option;
  switches : string list;
  runs : int;
  thresholds : thresholds;
}

type outcome = {
  switches : string list;
  povml_times : float list;
  povray_times : float list;
  cmp : Compare.t;
  povml_png : string;
  povray_png : string;
  diff_png : string;
  violations : string list;
}

let paths ~scene ~output =
  let main =
    match output with
    | None -> Filename.remove_extension scene ^ ".png"
    | Some o when Sys.file_exists o && Sys.is_directory o -> Filename.concat o (Filename.remove_extension (Filename.basename scene) ^ ".png")
    | Some o -> o
  in
  let base = Filename.remove_extension main in
  (main, base ^ "-povray.png", base ^ "-diff.png")

let violations t (c : Compare.t) =
  let share = Compare.differing_share c in
  List.filter_map Fun.id
    [ (match t.max_differing with
      | Some m when share > m ->
          Some (Printf.sprintf "%d of %d pixels differ (share %.6g), above --max-differing %g" c.differing c.pixels share m)
      | _ -> None);
      (match t.max_peak with Some m when c.peak > m -> Some (Printf.sprintf "peak %d/255 is above --max-peak %d" c.peak m) | _ -> None);
      (match t.min_psnr with
      | Some m when Compare.psnr c < m -> Some (Printf.sprintf "PSNR %.2f dB is below --min-psnr %g" (Compare.psnr c) m)
      | _ -> None) ]

type failure = Render_failed of string | Cannot_write of string

let run c =
  let cwd = Sys.getcwd () in
  let abs = if Filename.is_relative c.scene then Filename.concat cwd c.scene else c.scene in
  let args = Switches.for_renderers ~cwd ~scene:abs c.switches in
  let shown = Switches.shown c.switches in
  let dir = Runner.temp_dir "povml-check" in
  Fun.protect ~finally:(fun () -> Runner.remove_tree dir) (fun () ->
      let exception Failed of string in
      let ml = ref [] and pov = ref [] in
      let renderers = [ (Runner.Povml c.povml, "povml.png", ml); (Runner.Povray c.povray, "povray.png", pov) ] in
      let once (r, name, acc) =
        let o = Runner.render ~shown:c.scene r ~dir ~scene:abs ~out:(Filename.concat dir name) args in
        match o.image with
        | Error (f : Runner.failure) -> raise (Failed (Printf.sprintf "%s failed (exit status %d): %s" (Runner.name r) f.code f.message))
        | Ok img -> acc := (o.seconds, img) :: !acc
      in
      (* the runs alternate between the renderers *)
      match for _ = 1 to max 1 c.runs do List.iter once renderers done with
      | exception Failed m -> Error (Render_failed m)
      | () -> (
          let ml = List.rev !ml and pov = List.rev !pov in
          let img l = snd (List.hd l) and times l = List.map fst l in
          let mine = img ml and theirs = img pov in
          match (Compare.images mine theirs, Heatmap.image mine theirs) with
          | Error m, _ | _, Error m -> Error (Render_failed ("the images cannot be compared: " ^ m))
          | Ok cmp, Ok heat -> (
              let povml_png, povray_png, diff_png = paths ~scene:c.scene ~output:c.output in
              let write path img = Result.map_error (fun m -> Cannot_write (Printf.sprintf "%s: %s" path m)) (Output.write Output.Png path img) in
              match Result.bind (write povml_png mine) (fun () -> Result.bind (write povray_png theirs) (fun () -> write diff_png heat)) with
              | Error e -> Error e
              | Ok () ->
                  Ok
                    {
                      switches = shown;
                      povml_times = times ml;
                      povray_times = times pov;
                      cmp;
                      povml_png;
                      povray_png;
                      diff_png;
                      violations = violations c.thresholds cmp;
                    })))

let summary o =
  let b = Buffer.create 1024 in
  let p fmt = Printf.bprintf b fmt in
  let ml = Runner.median o.povml_times and pov = Runner.median o.povray_times in
  let runs = List.length o.povml_times in
  let c = o.cmp in
  p "switches  %s\n" (String.concat " " o.switches);
  p "povml     %8.3f s   %s\n" ml o.povml_png;
  p "POV-Ray   %8.3f s   %s\n" pov o.povray_png;
  p "time      povml / POV-Ray = %.2f (wall time of the whole process, %s)\n" (if pov > 0. then ml /. pov else nan)
    (if runs = 1 then "1 run each" else Printf.sprintf "median of %d runs each" runs);
  p "differing %d of %d pixels (%.4f%%)\n" c.differing c.pixels (100. *. (Compare.differing_share c));
  p "peak      %d/255\n" c.peak;
  p "RMSE      %.4f/255\n" c.rmse;
  p "PSNR      %s\n" (let v = Compare.psnr c in if v = infinity then "inf (identical)" else Printf.sprintf "%.2f dB" v);
  p "heat map  %s (equal: dark grey; differing: blue = 1/255 … yellow = the peak, %d/255)\n" o.diff_png c.peak;
  (match o.violations with
  | [] -> p "result    PASS\n"
  | vs -> p "result    FAIL: %s\n" (String.concat "; " vs));
  Buffer.contents b
