(* povml check and povml report, their pure parts: the heat map, Pareto fronts, the sweep, the
   thresholds, the CSV, Markdown and SVG writers, the switch lists. *)

let img w h f = { Encode.width = w; height = h; pixels = Bytes.init (3 * w * h) (fun i -> Char.chr (f i)) }
let rgb (i : Encode.t) p = (Char.code (Bytes.get i.pixels (3 * p)), Char.code (Bytes.get i.pixels ((3 * p) + 1)), Char.code (Bytes.get i.pixels ((3 * p) + 2)))
let triple = Alcotest.(triple int int int)

(* ---------------------------------------------------------------------------------------------- *)
(* Heatmap *)

let test_heat_colour () =
  Alcotest.check triple "smallest difference: blue" (40, 90, 255) (Heatmap.colour ~peak:200 1);
  Alcotest.check triple "the peak: yellow" (255, 240, 60) (Heatmap.colour ~peak:200 200);
  Alcotest.check triple "peak 1: yellow" (255, 240, 60) (Heatmap.colour ~peak:1 1);
  (* d = 1 + 2/3 of the way: the third stop, red *)
  Alcotest.check triple "two thirds: red" (255, 40, 40) (Heatmap.colour ~peak:7 5);
  (* brightness never falls below the first stop's, so 1/255 stands out against the grey *)
  for d = 1 to 255 do
    let r, g, b = Heatmap.colour ~peak:255 d in
    if max r (max g b) < 200 then Alcotest.failf "difference %d is too dark" d
  done

let test_heat_image () =
  (* 3 pixels: equal white, equal black, differing by 9 in blue *)
  let a = img 3 1 (fun i -> if i < 3 then 255 else 0) in
  let b = img 3 1 (fun i -> if i = 8 then 9 else if i < 3 then 255 else 0) in
  match Heatmap.image a b with
  | Error m -> Alcotest.fail m
  | Ok h ->
      Alcotest.check triple "equal white: dimmed to 63" (63, 63, 63) (rgb h 0);
      Alcotest.check triple "equal black: black" (0, 0, 0) (rgb h 1);
      Alcotest.check triple "the one difference is the peak" (Heatmap.colour ~peak:9 9) (rgb h 2);
      (match Heatmap.image a (img 1 3 (fun _ -> 0)) with
      | Ok _ -> Alcotest.fail "sizes differ: expected an error"
      | Error m -> Helpers.check_contains "message" ~sub:"3x1" m)

(* ---------------------------------------------------------------------------------------------- *)
(* Pareto *)

let test_pareto () =
  let pts = [ ("a", (1., 10.)); ("b", (2., 5.)); ("c", (2.5, 6.)); ("d", (3., 5.)); ("e", (4., 1.)); ("f", (0.5, 20.)); ("g", (5., 1.)); ("h", (4., 0.5)) ] in
  let names l = List.map fst l in
  (* c is beaten by b, d ties b's error later, e by h (same time, larger error), g by h *)
  Alcotest.(check (list string)) "front" [ "f"; "a"; "b"; "h" ] (names (Pareto.front snd pts));
  Alcotest.(check (list string)) "empty" [] (names (Pareto.front snd []));
  Alcotest.(check (list string)) "equal costs: the first" [ "x" ] (names (Pareto.front snd [ ("x", (1., 1.)); ("y", (1., 1.)) ]));
  (* every point off the front is dominated by one on it *)
  let front = Pareto.front snd pts in
  List.iter
    (fun (n, (t, e)) ->
      if not (List.mem_assoc n front) && not (List.exists (fun (_, (t', e')) -> t' <= t && e' <= e) front) then
        Alcotest.failf "%s is neither on the front nor dominated" n)
    pts

(* ---------------------------------------------------------------------------------------------- *)
(* Sweep *)

let test_settings () =
  let s = Sweep.settings ~aa:true ~trace:true ~thresholds:[ 0.3; 0.0 ] ~methods:[ 1; 2 ] ~depths:[ 3 ] ~trace_levels:[ 1; 2 ] in
  Alcotest.(check (list string)) "labels in order"
    [ "-A"; "+A0.3 +AM1 +R3"; "+A0.0 +AM1 +R3"; "+A0.3 +AM2 +R3"; "+A0.0 +AM2 +R3"; "-A max_trace_level 1"; "-A max_trace_level 2" ]
    (List.map Sweep.label s);
  let only_trace = Sweep.settings ~aa:false ~trace:true ~thresholds:[ 0.3 ] ~methods:[ 1 ] ~depths:[ 3 ] ~trace_levels:[ 4; 4 ] in
  Alcotest.(check (list string)) "no duplicates" [ "-A max_trace_level 4" ] (List.map Sweep.label only_trace);
  Alcotest.(check int) "default sweep size" (1 + (10 * 4 * 2) + 20)
    (List.length
       (Sweep.settings ~aa:true ~trace:true ~thresholds:(List.init 10 (fun i -> float_of_int (9 - i) /. 10.)) ~methods:[ 1; 2 ] ~depths:[ 1; 2; 3; 4 ]
          ~trace_levels:(List.init 20 succ)));
  Alcotest.(check (list string)) "switches" [ "+A0.05"; "+AM2"; "+R4" ]
    (Sweep.switches { antialias = Some 0.05; method_ = 2; depth = 4; trace_level = None });
  Alcotest.(check string) "threshold 0" "0.0" (Sweep.threshold 0.);
  Alcotest.(check string) "threshold 1" "1.0" (Sweep.threshold 1.)

(* The override is the scene's text with a later global_settings block; povml keeps the scene's other
   global settings (POV-Ray does the same, checked by the report's own runs). *)
let test_trace_override () =
  let text = "#version 3.7;\nglobal_settings { assumed_gamma 1.0 max_trace_level 8 adc_bailout 0.01 }\nsphere { 0, 1 } // no newline" in
  let t = Sweep.with_trace_level text 3 in
  Helpers.check_contains "appended" ~sub:"global_settings { max_trace_level 3 }" t;
  let s = Helpers.scene t in
  Alcotest.(check int) "max_trace_level overridden" 3 s.max_trace_level;
  Helpers.float_eq "adc_bailout kept" 0.01 s.adc_bailout;
  Alcotest.(check int) "the object still there" 1 (List.length s.objects);
  Alcotest.(check int) "unchanged without the override" 8 (Helpers.scene text).max_trace_level

(* ---------------------------------------------------------------------------------------------- *)
(* Check *)

let cmp ~differing ~peak ~rmse = { Compare.pixels = 100; differing; peak; rmse }

let test_violations () =
  let none = { Check.max_differing = None; max_peak = None; min_psnr = None } in
  let c = cmp ~differing:3 ~peak:7 ~rmse:1. in
  Alcotest.(check int) "no thresholds" 0 (List.length (Check.violations none c));
  Alcotest.(check int) "all within" 0
    (List.length (Check.violations { max_differing = Some 0.03; max_peak = Some 7; min_psnr = Some 48. } c));
  let v = Check.violations { max_differing = Some 0.02; max_peak = Some 6; min_psnr = Some 49. } c in
  Alcotest.(check int) "all three exceeded" 3 (List.length v);
  Helpers.check_contains "differing" ~sub:"3 of 100 pixels differ" (List.nth v 0);
  Helpers.check_contains "peak" ~sub:"peak 7/255 is above --max-peak 6" (List.nth v 1);
  Helpers.check_contains "psnr" ~sub:"PSNR 48.13 dB is below --min-psnr 49" (List.nth v 2);
  let same = cmp ~differing:0 ~peak:0 ~rmse:0. in
  Alcotest.(check int) "identical passes --max-differing 0 and any PSNR" 0
    (List.length (Check.violations { max_differing = Some 0.; max_peak = Some 0; min_psnr = Some 1000. } same))

let test_paths () =
  let a, b, c = Check.paths ~scene:"dir/s.pov" ~output:None in
  Alcotest.(check (list string)) "beside the scene" [ "dir/s.png"; "dir/s-povray.png"; "dir/s-diff.png" ] [ a; b; c ];
  let a, b, c = Check.paths ~scene:"dir/s.pov" ~output:(Some "out/x.png") in
  Alcotest.(check (list string)) "beside +O" [ "out/x.png"; "out/x-povray.png"; "out/x-diff.png" ] [ a; b; c ]

(* ---------------------------------------------------------------------------------------------- *)
(* Runner, Switches *)

let test_median () =
  Helpers.float_eq "odd" 2. (Runner.median [ 3.; 1.; 2. ]);
  Helpers.float_eq "even" 2.5 (Runner.median [ 4.; 1.; 2.; 3. ]);
  Helpers.float_eq "one" 7. (Runner.median [ 7. ]);
  Alcotest.(check bool) "none" true (Float.is_nan (Runner.median []))

let test_switches () =
  let key = Alcotest.(option string) in
  Alcotest.check key "+W640" (Some "W") (Switches.key "+W640");
  Alcotest.check key "+WT2" (Some "WT") (Switches.key "+WT2");
  Alcotest.check key "+am2" (Some "AM") (Switches.key "+am2");
  Alcotest.check key "-A" (Some "A") (Switches.key "-A");
  Alcotest.check key "--out" None (Switches.key "--out");
  Alcotest.check key "file" None (Switches.key "s.pov");
  Alcotest.(check string) "value" "0.3" (Switches.value "+A0.3");
  Alcotest.(check string) "value of +L" "inc/dir" (Switches.value "+Linc/dir");
  Alcotest.(check (list string)) "shown" [ "+W32"; "+A0.3"; "+H120"; "+WT2" ] (Switches.shown [ "+W32"; "+A0.3" ]);
  let l = Switches.for_renderers ~cwd:"/w" ~scene:"/s/x.pov" [ "+W32"; "+Linc"; "+WT1" ] in
  List.iter (fun s -> if not (List.mem s l) then Alcotest.failf "%s missing" s) [ "+W32"; "+H120"; "+WT1"; "+L/s"; "+L/w"; "+L/w/inc"; "-D"; "-V"; "+FN" ];
  Alcotest.(check bool) "no default +WT when given" false (List.mem "+WT2" l);
  let index s = let rec go i = function [] -> -1 | x :: r -> if x = s then i else go (i + 1) r in go 0 l in
  Alcotest.(check bool) "scene directory searched first" true (index "+L/s" < index "+L/w/inc")

(* ---------------------------------------------------------------------------------------------- *)
(* Tables and Plot, on a made-up report *)

let aa t m d = { Sweep.antialias = Some t; method_ = m; depth = d; trace_level = None }
let off = { Sweep.antialias = None; method_ = 1; depth = 3; trace_level = None }
let rendered median rmse = Sweep.Rendered { times = [ median; median ]; median; cmp = cmp ~differing:10 ~peak:20 ~rmse }

let sample =
  {
    Sweep.path = "scenes/x.pov";
    stem = "x";
    width = 32;
    height = 24;
    switches = [ "+W32"; "+H24"; "+WT2" ];
    truth = [ "+AM2"; "+R5"; "+A0.0" ];
    truth_seconds = 2.5;
    runs = 2;
    rows =
      [
        { setting = off; povml = rendered 0.1 4.; povray = rendered 0.8 4. };
        { setting = aa 0.3 1 3; povml = rendered 0.2 1.; povray = rendered 0.9 1. };
        { setting = aa 0.3 1 2; povml = rendered 0.3 2.; povray = rendered 0.85 2. };
        { setting = aa 0.3 2 3; povml = Sweep.Not_supported "sampling method 2, is not supported"; povray = rendered 1.2 0. };
        { setting = { off with trace_level = Some 1 }; povml = Sweep.Failed "boom"; povray = rendered 0.7 30. };
      ];
  }

let test_front () =
  let labels r = List.map (fun (row : Sweep.row) -> Sweep.label row.setting) (Sweep.front sample r) in
  Alcotest.(check (list string)) "povml" [ "-A"; "+A0.3 +AM1 +R3" ] (labels `Povml);
  Alcotest.(check (list string)) "POV-Ray" [ "-A max_trace_level 1"; "-A"; "+A0.3 +AM1 +R2"; "+A0.3 +AM1 +R3"; "+A0.3 +AM2 +R3" ] (labels `Povray)

let test_csv () =
  Alcotest.(check string) "plain" "abc" (Tables.csv_field "abc");
  Alcotest.(check string) "comma" "\"a,b\"" (Tables.csv_field "a,b");
  Alcotest.(check string) "quote" "\"say \"\"hi\"\"\"" (Tables.csv_field "say \"hi\"");
  let lines = String.split_on_char '\n' (String.trim (Tables.csv [ sample ])) in
  (* header, truth, 5 settings × 2 renderers *)
  Alcotest.(check int) "lines" 12 (List.length lines);
  Helpers.check_contains "header" ~sub:"scene,width,height,renderer,setting" (List.hd lines);
  Alcotest.(check string) "truth" "scenes/x.pov,32,24,POV-Ray,ground truth: +AM2 +R5 +A0.0,,,,,scene,truth,1,2.500,2.500,0,inf,0,0,,"
    (List.nth lines 1);
  Alcotest.(check string) "povml -A" "scenes/x.pov,32,24,povml,-A,off,,,,scene,ok,2,0.100,0.100 0.100,4,36.09,0.1,20,yes,"
    (List.nth lines 2);
  Alcotest.(check string) "not supported, message quoted"
    "scenes/x.pov,32,24,povml,+A0.3 +AM2 +R3,on,0.3,2,3,scene,not supported,0,,,,,,,,\"sampling method 2, is not supported\""
    (List.nth lines 8);
  Alcotest.(check string) "POV-Ray at zero error" "scenes/x.pov,32,24,POV-Ray,+A0.3 +AM2 +R3,on,0.3,2,3,scene,ok,2,1.200,1.200 1.200,0,inf,0.1,20,yes,"
    (List.nth lines 9);
  Helpers.check_contains "failed" ~sub:"povml,-A max_trace_level 1,off,,,,1,failed,0" (List.nth lines 10)

let test_markdown () =
  let md = Tables.markdown ~plot:(fun sc -> Some (sc.stem ^ ".svg")) [ sample ] in
  Helpers.check_contains "truth stated" ~sub:"POV-Ray with `+AM2 +R5 +A0.0`" md;
  Helpers.check_contains "plot" ~sub:"](x.svg)" md;
  Helpers.check_contains "row, front marked" ~sub:"| -A | 0.100 ★ | 4.000 | 36.09 | 10.00% | 0.800 ★ | 4.000 | 36.09 | 10.00% |" md;
  Helpers.check_contains "off the front" ~sub:"| +A0.3 +AM1 +R2 | 0.300 | 2.000 |" md;
  Helpers.check_contains "not supported" ~sub:"| +A0.3 +AM2 +R3 | *not supported* | | | | 1.200 ★ | 0.000 | inf |" md

let count ~sub s =
  let ls = String.length s and lsub = String.length sub in
  let rec go i n = if i + lsub > ls then n else go (i + 1) (if String.sub s i lsub = sub then n + 1 else n) in
  go 0 0

let test_svg () =
  let ticks = Plot.log_ticks 0.07 3. in
  Alcotest.(check (list (float 1e-12))) "1-2-5 ticks" [ 0.1; 0.2; 0.5; 1.; 2. ] ticks;
  Alcotest.(check (list (float 1e-12))) "fine ticks" [ 1.5; 2.; 3.; 4. ] (Plot.log_ticks 1.5 4.5);
  Alcotest.(check (list (float 1e-12))) "fine ticks, 1.5 too" [ 1.5; 2.; 3. ] (Plot.log_ticks 1.08 3.17);
  Alcotest.(check int) "at least two" 3 (List.length (Plot.log_ticks 1.05 1.4));
  Alcotest.(check string) "escape" "a&lt;b&amp;&quot;c&quot;&gt;" (Plot.escape "a<b&\"c\">");
  let svg = Plot.svg [ sample; { sample with path = "scenes/y.pov" } ] in
  Helpers.check_contains "svg root" ~sub:"<svg xmlns=\"http://www.w3.org/2000/svg\"" svg;
  Alcotest.(check int) "one panel per scene" 2 (count ~sub:"<g transform=\"translate(0," svg);
  Alcotest.(check int) "one front line per renderer and panel" 4 (count ~sub:"<polyline" svg);
  (* povml: 3 rendered settings + the legend's marker; POV-Ray: 5 + the legend's *)
  Alcotest.(check int) "povml circles" (2 * 4) (count ~sub:"<circle" svg);
  Alcotest.(check int) "POV-Ray squares" (2 * 6) (count ~sub:"width=\"8\" height=\"8\"" svg);
  Helpers.check_contains "what was not drawn" ~sub:"povml: 2 of 5 settings not rendered" svg;
  Alcotest.(check bool) "balanced groups" true (count ~sub:"<g" svg = count ~sub:"</g>" svg);
  Helpers.check_contains "closed" ~sub:"</svg>" svg

let tests =
  [
    Alcotest.test_case "heat map colours" `Quick test_heat_colour;
    Alcotest.test_case "heat map image" `Quick test_heat_image;
    Alcotest.test_case "Pareto front" `Quick test_pareto;
    Alcotest.test_case "sweep settings" `Quick test_settings;
    Alcotest.test_case "max_trace_level override" `Quick test_trace_override;
    Alcotest.test_case "check thresholds" `Quick test_violations;
    Alcotest.test_case "check image paths" `Quick test_paths;
    Alcotest.test_case "median" `Quick test_median;
    Alcotest.test_case "switches" `Quick test_switches;
    Alcotest.test_case "report fronts" `Quick test_front;
    Alcotest.test_case "CSV" `Quick test_csv;
    Alcotest.test_case "Markdown" `Quick test_markdown;
    Alcotest.test_case "SVG" `Quick test_svg;
  ]
