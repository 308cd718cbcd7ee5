(* The report's tables: CSV and Markdown. *)

let csv_field s =
  if String.exists (fun c -> c = ',' || c = '"' || c = '\n' || c = '\r') s then
    "\"" ^ String.concat "\"\"" (String.split_on_char '"' s) ^ "\""
  else s

let num f = if Float.is_integer f && Float.abs f < 1e15 then Printf.sprintf "%.0f" f else Printf.sprintf "%.6g" f
let psnr_text p = if p = infinity then "inf" else Printf.sprintf "%.2f" p
let seconds s = Printf.sprintf "%.3f" s

let header =
  [ "scene"; "width"; "height"; "renderer"; "setting"; "antialias"; "threshold"; "method"; "depth"; "max_trace_level";
    "status"; "runs"; "median_s"; "times_s"; "rmse"; "psnr_db"; "differing_share"; "peak"; "pareto"; "message" ]

let csv scenes =
  let b = Buffer.create 4096 in
  let line fields = Buffer.add_string b (String.concat "," (List.map csv_field fields) ^ "\n") in
  line header;
  List.iter
    (fun (sc : Sweep.scene) ->
      let common = [ sc.path; string_of_int sc.width; string_of_int sc.height ] in
      line
        (common
        @ [ "POV-Ray"; "ground truth: " ^ String.concat " " sc.truth; ""; ""; ""; ""; "scene"; "truth"; "1"; seconds sc.truth_seconds;
            seconds sc.truth_seconds; "0"; "inf"; "0"; "0"; ""; "" ]);
      let fronts = [ (`Povml, Sweep.front sc `Povml); (`Povray, Sweep.front sc `Povray) ] in
      List.iter
        (fun (row : Sweep.row) ->
          let s = row.setting in
          let setting =
            [ Sweep.label s;
              (match s.antialias with None -> "off" | Some _ -> "on");
              (match s.antialias with None -> "" | Some t -> Sweep.threshold t);
              (match s.antialias with None -> "" | Some _ -> string_of_int s.method_);
              (match s.antialias with None -> "" | Some _ -> string_of_int s.depth);
              (match s.trace_level with None -> "scene" | Some n -> string_of_int n) ]
          in
          List.iter
            (fun (r, rname) ->
              let on_front = List.memq row (List.assoc r fronts) in
              let rest =
                match Sweep.get row r with
                | Sweep.Rendered m ->
                    [ "ok"; string_of_int (List.length m.times); seconds m.median; String.concat " " (List.map seconds m.times);
                      num m.cmp.rmse; psnr_text (Compare.psnr m.cmp);
                      num (Compare.differing_share m.cmp); string_of_int m.cmp.peak; (if on_front then "yes" else "no"); "" ]
                | Sweep.Not_supported msg -> [ "not supported"; "0"; ""; ""; ""; ""; ""; ""; ""; msg ]
                | Sweep.Failed msg -> [ "failed"; "0"; ""; ""; ""; ""; ""; ""; ""; msg ]
              in
              line (common @ [ rname ] @ setting @ rest))
            [ (`Povml, "povml"); (`Povray, "POV-Ray") ])
        sc.rows)
    scenes;
  Buffer.contents b

(* A Markdown table cell may not hold a '|'. *)
let cell s = String.concat "\\|" (String.split_on_char '|' s)

let markdown ~plot scenes =
  let b = Buffer.create 4096 in
  let p fmt = Printf.bprintf b fmt in
  p "# povml report: error against time\n\n";
  (match scenes with
  | [] -> p "No scene was measured.\n"
  | (first : Sweep.scene) :: _ ->
      p "Each scene is rendered with every setting by povml and by POV-Ray, %d timed run(s) each.\n\n" first.runs;
      p "- **Ground truth** (one image per scene): POV-Ray with `%s`, the scene's own max_trace_level.\n"
        (String.concat " " first.truth);
      p "- **Error**: RMSE against the ground truth, in 1/255 units (PSNR in dB; *differing*: share of pixels with any channel different).\n";
      p "- **Time**: median wall time of the whole process (start-up, parsing, rendering, writing the PNG).\n";
      p "- **★**: on that renderer's Pareto front: none of its other settings is both faster and closer to the ground truth.\n";
      p "- *not supported*: the renderer refused the setting; *failed*: the render failed (the CSV has the message).\n");
  List.iter
    (fun (sc : Sweep.scene) ->
      p "\n## %s\n\n" sc.path;
      p "%d×%d, switches `%s`; ground truth: POV-Ray `%s` in %.3f s.\n\n" sc.width sc.height (String.concat " " sc.switches)
        (String.concat " " sc.truth) sc.truth_seconds;
      (match plot sc with Some f -> p "![error against time, %s](%s)\n\n" (Filename.basename sc.path) f | None -> ());
      p "| setting | povml s | RMSE | PSNR dB | differing | POV-Ray s | RMSE | PSNR dB | differing |\n";
      p "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
      let fronts = [ (`Povml, Sweep.front sc `Povml); (`Povray, Sweep.front sc `Povray) ] in
      List.iter
        (fun (row : Sweep.row) ->
          let cols r =
            match Sweep.get row r with
            | Sweep.Rendered m ->
                let star = if List.memq row (List.assoc r fronts) then " ★" else "" in
                Printf.sprintf "%.3f%s | %.3f | %s | %.2f%%" m.median star m.cmp.rmse (psnr_text (Compare.psnr m.cmp))
                  (100. *. (Compare.differing_share m.cmp))
            | Sweep.Not_supported _ -> "*not supported* | | |"
            | Sweep.Failed _ -> "*failed* | | |"
          in
          p "| %s | %s | %s |\n" (cell (Sweep.label row.setting)) (cols `Povml) (cols `Povray))
        sc.rows)
    scenes;
  Buffer.contents b
