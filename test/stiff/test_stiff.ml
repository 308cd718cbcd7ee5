(* The stiff and extreme scenes (scenes/stiff, found by listing the directory, so a new scene is
   covered without touching this file), rendered in-process with Pipeline.run at 40×30:
   - every float of the image before quantisation is finite (no NaN, no infinity), with and
     without antialiasing;
   - the recursion-limit scenes run to max_trace_level 256 (the largest POV-Ray accepts): the
     statistics' deepest level is 256, and the render returns (no Stack_overflow, no crash).
   Their pixels are compared with POV-Ray's by the image tests (reference/manifest.tsv). *)

let dir = "../../scenes/stiff"

let scenes () =
  Sys.readdir dir |> Array.to_list |> List.filter (fun f -> Filename.check_suffix f ".pov") |> List.sort compare

let opts ?antialias () = { (Render.defaults 40 30) with antialias }

let render ?antialias file = Pipeline.run (opts ?antialias ()) (Filename.concat dir file)

(* The first non-finite value of the raw image, as (x, y, channel, value). *)
let first_non_finite (img : Image.t) =
  let n = Image.channels img in
  let rec go i =
    if i >= n then None
    else
      let v = Image.channel img i in
      if Float.is_finite v then go (i + 1) else Some ((i / 3) mod img.width, i / 3 / img.width, i mod 3, v)
  in
  go 0

let check_finite ?antialias file () =
  let r = render ?antialias file in
  Alcotest.(check int) "raw image size" (3 * 40 * 30) (Image.channels r.raw);
  match first_non_finite r.raw with
  | None -> ()
  | Some (x, y, c, v) -> Alcotest.failf "%s: pixel (%d,%d) channel %d is %h" file x y c v

(* A scene at the recursion limit: max_trace_level 256 is kept (no clipping, no warning), and some
   ray goes all the way down. *)
let check_level ?antialias file expected () =
  let r = render ?antialias file in
  Alcotest.(check int) "max_trace_level as parsed" expected r.scene.max_trace_level;
  Alcotest.(check int) "no warning" 0 (List.length r.warnings);
  Alcotest.(check int) "deepest trace level reached" expected r.stats.max_level;
  Alcotest.(check bool) "finite" true (first_non_finite r.raw = None)

let () =
  let files = scenes () in
  if files = [] then failwith ("no scenes in " ^ dir);
  Alcotest.run "stiff"
    [
      ("finite", List.map (fun f -> Alcotest.test_case f `Quick (check_finite f)) files);
      ("finite with +A0.3", List.map (fun f -> Alcotest.test_case f `Quick (check_finite ~antialias:0.3 f)) files);
      ( "trace level 256",
        [
          Alcotest.test_case "mirrors_256" `Quick (check_level "mirrors_256.pov" 256);
          Alcotest.test_case "mirrors_256 +A0.3" `Quick (check_level ~antialias:0.3 "mirrors_256.pov" 256);
          Alcotest.test_case "tir_trap_256 (refraction)" `Quick (check_level "tir_trap_256.pov" 256);
          Alcotest.test_case "tir_trap (200)" `Quick (check_level "tir_trap.pov" 200);
        ] );
    ]
