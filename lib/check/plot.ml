(* The report's SVG plot: error against time, one panel per scene. *)

let log_ticks lo hi =
  let k0 = int_of_float (floor (log10 lo)) and k1 = int_of_float (ceil (log10 hi)) in
  let within v = v >= lo *. (1. -. 1e-9) && v <= hi *. (1. +. 1e-9) in
  let with_mantissas ms =
    List.concat_map (fun k -> List.map (fun m -> m *. (10. ** float_of_int k)) ms) (List.init (k1 - k0 + 1) (fun i -> k0 + i))
    |> List.filter within
  in
  let coarse = with_mantissas [ 1.; 2.; 5. ] in
  if List.length coarse >= 3 then coarse
  else
    let fine = with_mantissas [ 1.; 1.5; 2.; 3.; 4.; 5.; 6.; 7.; 8.; 9. ] in
    if List.length fine >= 2 then fine
    else
      let l = log10 lo and h = log10 hi in
      List.map (fun i -> 10. ** (l +. ((h -. l) *. float_of_int i /. 2.))) [ 0; 1; 2 ]

let escape s =
  let b = Buffer.create (String.length s) in
  String.iter
    (function
      | '&' -> Buffer.add_string b "&amp;"
      | '<' -> Buffer.add_string b "&lt;"
      | '>' -> Buffer.add_string b "&gt;"
      | '"' -> Buffer.add_string b "&quot;"
      | c -> Buffer.add_char b c)
    s;
  Buffer.contents b

let tick_label v = if v >= 0.01 && v < 10000. then Printf.sprintf "%.3g" v else Printf.sprintf "%.1e" v

(* panel geometry *)
let width = 880.
let height = 520.
let left = 78.
let right = 24.
let top = 80.
let bottom = 86. (* the zero row, the tick labels, the axis title, the note *)
let x0 = left
let x1 = width -. right
let y0 = height -. bottom (* the axis *)
let y1 = top
let zero_row = y0 +. 16.

let colours = [ (`Povml, "#d95f02"); (`Povray, "#1f78b4") ]
let names = [ (`Povml, "povml"); (`Povray, "POV-Ray") ]

(* a marker in a group with its tooltip (a tooltip inside the shape hides the shape from some
   renderers) *)
let marker b r ~filled cx cy colour tooltip =
  let fill = if filled then colour else "white" in
  let op = if filled then "1" else "0.75" in
  Printf.bprintf b "<g><title>%s</title>" (escape tooltip);
  (match r with
  | `Povml ->
      Printf.bprintf b "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4.2\" fill=\"%s\" stroke=\"%s\" stroke-width=\"1.4\" opacity=\"%s\"/>" cx cy fill colour op
  | `Povray ->
      Printf.bprintf b "<rect x=\"%.1f\" y=\"%.1f\" width=\"8\" height=\"8\" fill=\"%s\" stroke=\"%s\" stroke-width=\"1.4\" opacity=\"%s\"/>" (cx -. 4.) (cy -. 4.) fill colour op);
  Buffer.add_string b "</g>\n"

let panel b (sc : Sweep.scene) =
  let points r =
    List.filter_map
      (fun (row : Sweep.row) -> match Sweep.get row r with Sweep.Rendered m -> Some (row, m.median, m.cmp.rmse) | _ -> None)
      sc.rows
  in
  let all = points `Povml @ points `Povray in
  let times = List.map (fun (_, t, _) -> Float.max t 1e-4) all in
  let errs = List.filter (fun e -> e > 0.) (List.map (fun (_, _, e) -> e) all) in
  let range l ~default ~pad =
    match l with
    | [] -> default
    | v :: _ ->
        let lo = List.fold_left Float.min v l and hi = List.fold_left Float.max v l in
        let lo, hi = if hi /. lo < 1.5 then (lo /. 1.25, hi *. 1.25) else (lo, hi) in
        (lo /. pad, hi *. pad)
  in
  let tlo, thi = range times ~default:(0.1, 10.) ~pad:1.15 in
  let elo, ehi = range errs ~default:(0.1, 10.) ~pad:1.3 in
  let sx t = x0 +. ((x1 -. x0) *. (log10 (Float.max t 1e-4) -. log10 tlo) /. (log10 thi -. log10 tlo)) in
  let sy e = if e <= 0. then zero_row else y0 -. ((y0 -. y1) *. (log10 e -. log10 elo) /. (log10 ehi -. log10 elo)) in
  let p fmt = Printf.bprintf b fmt in
  p "<rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" fill=\"white\"/>\n" width height;
  p "<text x=\"%.0f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">%s</text>\n" left (escape (Printf.sprintf "%s — error against time" sc.path));
  p "<text x=\"%.0f\" y=\"44\" font-size=\"11.5\" fill=\"#444\">%s</text>\n" left
    (escape
       (Printf.sprintf "%d×%d %s; error: RMSE against POV-Ray %s; time: median wall time of %d run(s)" sc.width sc.height
          (String.concat " " (List.filter (fun s -> match Switches.key s with Some ("W" | "H" | "L" | "D" | "V" | "F") -> false | _ -> true) sc.switches))
          (String.concat " " sc.truth) sc.runs));
  (* grid and ticks *)
  List.iter
    (fun t ->
      let x = sx t in
      p "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#e4e4e4\"/>\n" x y1 x y0;
      p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"middle\">%s</text>\n" x (zero_row +. 22.) (tick_label t))
    (log_ticks tlo thi);
  List.iter
    (fun e ->
      let y = sy e in
      p "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#e4e4e4\"/>\n" x0 y x1 y;
      p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"end\">%s</text>\n" (x0 -. 6.) (y +. 4.) (tick_label e))
    (log_ticks elo ehi);
  p "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" stroke=\"#888\"/>\n" x0 y1 (x1 -. x0) (y0 -. y1);
  p "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#bbb\" stroke-dasharray=\"3,3\"/>\n" x0 zero_row x1 zero_row;
  p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" text-anchor=\"end\">0</text>\n" (x0 -. 6.) (zero_row +. 4.);
  p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\">median wall time, seconds (log scale)</text>\n" ((x0 +. x1) /. 2.) (zero_row +. 40.);
  p "<text transform=\"translate(18,%.1f) rotate(-90)\" font-size=\"12\" text-anchor=\"middle\">RMSE against the ground truth, 1/255 (log scale)</text>\n" ((y0 +. y1) /. 2.);
  (* the points: others first, then each front as a line through its points *)
  let fronts =
    List.map
      (fun r ->
        let colour = List.assoc r colours and rname = List.assoc r names in
        let front = Sweep.front sc r in
        let tip (row : Sweep.row) t e = Printf.sprintf "%s %s: %.3f s, RMSE %.3f" rname (Sweep.label row.setting) t e in
        List.iter (fun ((row : Sweep.row), t, e) -> if not (List.memq row front) then marker b r ~filled:false (sx t) (sy e) colour (tip row t e)) (points r);
        let on_front = List.filter (fun (row, _, _) -> List.memq row front) (points r) in
        let on_front = List.sort (fun (_, a, _) (_, b, _) -> compare a b) on_front in
        if List.length on_front > 1 then
          p "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.8\" points=\"%s\"/>\n" colour
            (String.concat " " (List.map (fun (_, t, e) -> Printf.sprintf "%.1f,%.1f" (sx t) (sy e)) on_front));
        List.iter (fun ((row : Sweep.row), t, e) -> marker b r ~filled:true (sx t) (sy e) colour (tip row t e)) on_front;
        (colour, on_front))
      [ `Povray; `Povml ]
  in
  (* the front points' labels, where one fits without covering another label; every point has its
     setting as a tooltip *)
  let placed = ref [] in
  let free (l, t, r, bt) = l >= x0 && r <= x1 && t >= y1 && bt <= zero_row && not (List.exists (fun (l', t', r', b') -> l < r' && l' < r && t < b' && t' < bt) !placed) in
  List.iter
    (fun (colour, on_front) ->
      List.iter
        (fun ((row : Sweep.row), t, e) ->
          let label = Sweep.label row.setting in
          let w = 5.6 *. float_of_int (String.length label) and x = sx t and y = sy e in
          let candidates =
            [ ("start", x +. 6., y -. 6.); ("start", x +. 6., y +. 13.); ("end", x -. 6., y -. 6.); ("end", x -. 6., y +. 13.) ]
          in
          let box (anchor, tx, ty) = if anchor = "start" then (tx, ty -. 9., tx +. w, ty +. 2.) else (tx -. w, ty -. 9., tx, ty +. 2.) in
          match List.find_opt (fun c -> free (box c)) candidates with
          | None -> ()
          | Some ((anchor, tx, ty) as c) ->
              placed := box c :: !placed;
              p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"9.5\" fill=\"%s\" text-anchor=\"%s\">%s</text>\n" tx ty colour anchor (escape label))
        on_front)
    (List.rev fronts);
  (* the legend, one row between the subtitle and the plot *)
  let ly = 62. in
  List.iteri
    (fun i r ->
      let lx = left +. (110. *. float_of_int i) in
      let colour = List.assoc r colours in
      p "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.8\"/>\n" lx ly (lx +. 28.) ly colour;
      marker b r ~filled:true (lx +. 14.) ly colour (List.assoc r names);
      p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">%s</text>\n" (lx +. 36.) (ly +. 4.) (List.assoc r names))
    [ `Povml; `Povray ];
  p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" fill=\"#444\">filled and joined: the Pareto front; hollow: the other settings</text>\n" (left +. 230.) (ly +. 4.);
  (* what was not drawn *)
  let missing r =
    let n = List.length (List.filter (fun row -> match Sweep.get row r with Sweep.Rendered _ -> false | _ -> true) sc.rows) in
    if n = 0 then None else Some (Printf.sprintf "%s: %d of %d settings not rendered (not supported or failed)" (List.assoc r names) n (List.length sc.rows))
  in
  match List.filter_map missing [ `Povml; `Povray ] with
  | [] -> ()
  | notes -> p "<text x=\"%.1f\" y=\"%.1f\" font-size=\"11\" fill=\"#a00\">Not plotted: %s.</text>\n" x0 (height -. 8.) (escape (String.concat "; " notes))

let svg scenes =
  let b = Buffer.create 16384 in
  let n = max 1 (List.length scenes) in
  Printf.bprintf b
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
    width (height *. float_of_int n) width (height *. float_of_int n);
  List.iteri
    (fun i sc ->
      Printf.bprintf b "<g transform=\"translate(0,%.0f)\">\n" (height *. float_of_int i);
      panel b sc;
      Buffer.add_string b "</g>\n")
    scenes;
  Buffer.add_string b "</svg>\n";
  Buffer.contents b
