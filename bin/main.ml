(* povml's command line: POV-Ray-style switches translated to long options, the options record
   [run] takes, one error printer, the statistics. Everything it renders comes from the library. *)

open Cmdliner

(* ---------------------------------------------------------------------------------------------- *)
(* POV-Ray switches (+W640, -D, +A0.3 …) become long options before cmdliner sees them. *)

let translate_switch arg =
  let n = String.length arg in
  if n < 2 || (arg.[0] <> '+' && arg.[0] <> '-') || arg.[1] = '-' then `Keep arg
  else
    let on = arg.[0] = '+' in
    let body = String.sub arg 1 (n - 1) in
    let up = String.uppercase_ascii body in
    let starts p = String.length up >= String.length p && String.sub up 0 (String.length p) = p in
    let rest p = String.sub body (String.length p) (String.length body - String.length p) in
    let valued long p = if rest p = "" then `Bad else `Use [ Printf.sprintf "--%s=%s" long (rest p) ] in
    let either yes no = `Use [ (if on then yes else no) ] in
    if starts "AM" then valued "sampling-method" "AM"
    else if starts "AG" then valued "aa-gamma" "AG"
    else if starts "WT" then valued "threads" "WT"
    else if starts "SR" then valued "start-row" "SR"
    else if starts "ER" then valued "end-row" "ER"
    else if starts "SC" then valued "start-column" "SC"
    else if starts "EC" then valued "end-column" "EC"
    else if starts "BS" then valued "block-size" "BS"
    (* +F[type] writes a file (of that type), -F[type] none *)
    else if up = "F" then either "--output-to-file" "--no-output-to-file"
    else if up = "FN" || up = "FN8" || up = "FP" then
      if on then `Use [ (if up = "FP" then "--format=ppm" else "--format=png"); "--output-to-file" ] else `Use [ "--no-output-to-file" ]
    else if starts "F" then `Bad
    (* +MB[n]: bounding on (with threshold n); -MB: off *)
    else if starts "MB" then
      if not on then `Use [ "--no-bounding" ]
      else if rest "MB" = "" then `Use [ "--bounding" ]
      else `Use [ Printf.sprintf "--bounding-threshold=%s" (rest "MB"); "--bounding" ]
    else if up = "D" || (starts "D" && n = 3) then either "--display" "--no-display"
    else if up = "V" then either "--verbose" "--no-verbose"
    (* +A0.2 turns antialiasing on and sets its threshold, -A0.2 sets it and turns it off; the
       threshold is Antialias_Threshold's too, so the later of the two wins (the same for +J) *)
    else if starts "A" then
      `Use ((if on then "--antialias" else "--no-antialias") :: (if rest "A" = "" then [] else [ "--antialias-threshold=" ^ rest "A" ]))
    else if starts "J" then
      `Use ((if on then "--jitter" else "--no-jitter") :: (if rest "J" = "" then [] else [ "--jitter-amount=" ^ rest "J" ]))
    else if starts "I" then valued "input" "I"
    else if starts "O" then valued "output" "O"
    else if starts "W" then valued "width" "W"
    else if starts "H" && up <> "H" then valued "height" "H"
    else if starts "R" then valued "aa-depth" "R"
    else if starts "L" then valued "library-path" "L"
    else if starts "KFI" then valued "initial-frame" "KFI"
    else if starts "KFF" then valued "final-frame" "KFF"
    else if starts "KI" then valued "initial-clock" "KI"
    else if starts "KF" then valued "final-clock" "KF"
    else if up = "KC" then either "--cyclic" "--no-cyclic"
    else if starts "K" && up <> "K" then valued "clock" "K"
    else if starts "SF" then valued "subset-start" "SF"
    else if starts "EF" then valued "subset-end" "EF"
    else if arg = "-h" then `Keep arg
    else `Bad

(* ---------------------------------------------------------------------------------------------- *)
(* Printing *)

let source file =
  match open_in_bin file with
  | exception Sys_error _ -> None
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          try Some (really_input_string ic (in_channel_length ic)) with Sys_error _ | End_of_file -> None)

let print_error e = prerr_string (Error.render ~source ~kind:"error" e)

let fail (e : Error.t) = print_error e; `Ok (Exits.scene_error e.kind)
let print_warning e = prerr_string (Error.render ~source ~kind:"warning" e)

let hms s =
  let t = int_of_float s in
  Printf.sprintf "%2d hours %2d minutes %2d seconds (%.3f seconds)" (t / 3600) (t / 60 mod 60) (t mod 60) s

let print_stats (r : Pipeline.result) (o : Render.options) =
  let s = r.stats in
  let line = String.make 76 '-' in
  let pct a b = if b = 0 then 0. else 100. *. float_of_int a /. float_of_int b in
  let pixels = (o.area.right - o.area.left + 1) * (o.area.bottom - o.area.top + 1) in
  let rays = s.camera_rays + s.reflected_rays + s.refracted_rays in
  Printf.eprintf "%s\nRender Statistics\nImage Resolution %d x %d\n%s\n" line o.width o.height line;
  Printf.eprintf "Pixels:      %11d   Samples:     %11d   Smpls/Pxl: %.2f\n" pixels s.samples
    (if pixels = 0 then 0. else float_of_int s.samples /. float_of_int pixels);
  Printf.eprintf "Rays:        %11d   Max Level: %d/%d\n%s\n" rays s.max_level r.scene.max_trace_level line;
  Printf.eprintf "Ray->Shape Intersection          Tests       Succeeded  Percentage\n%s\n" line;
  (* the table's lines in POV-Ray's order; a counter never tested has none *)
  List.iter
    (fun (r : Stats.row) -> if r.tests > 0 then Printf.eprintf "%-27s%11d     %11d  %10.2f\n" r.name r.tests r.hits (pct r.hits r.tests))
    (Stats.rows s);
  Printf.eprintf "%s\n" line;
  if Stats.tests s Stats.roots > 0 then
    Printf.eprintf "Roots tested:%22d   eliminated:%21d\n" (Stats.tests s Stats.roots) (Stats.hits s Stats.roots);
  let iso_roots = Stats.tests s Stats.isosurface_roots in
  if iso_roots > 0 then Printf.eprintf "Isosurface roots:          %11d\n" iso_roots;
  Printf.eprintf "Camera Rays:               %11d\n" s.camera_rays;
  Printf.eprintf "Shadow Ray Tests:          %11d\n" s.shadow_rays;
  Printf.eprintf "Reflected Rays:            %11d\n" s.reflected_rays;
  Printf.eprintf "Refracted Rays:            %11d\n" s.refracted_rays;
  Printf.eprintf "%s\n" line;
  if r.includes <> [] then
    Printf.eprintf "Include files: %s\n"
      (String.concat ", " (List.map (fun (p, dt) -> Printf.sprintf "%s %.3f s" (Filename.basename p) dt) r.includes));
  Printf.eprintf "Parse Time:    %s\nBounding Time: %s\nRender Time:   %s\n              using %d process(es)\n"
    (hms r.parse_seconds) (hms r.build_seconds) (hms r.render_seconds) o.workers

(* ---------------------------------------------------------------------------------------------- *)
(* The render command *)

type fmt = Png_fmt | Ppm_fmt

let default_output input fmt =
  let base = Filename.remove_extension input in
  base ^ match fmt with Png_fmt -> ".png" | Ppm_fmt -> ".ppm"

(* §10.3: a value in [0,1) is a fraction of the size, otherwise a 1-based index. *)
let area_bound size v ~is_end =
  match v with
  | None -> if is_end then size - 1 else 0
  | Some v ->
      (* POV-Ray keeps these values in single precision: 0.9 of 160 is 143.99…, so column 143 *)
      let v = Precision.f32 v in
      if v < 1. || (is_end && v = 1.) then
        if is_end then int_of_float (float_of_int size *. v) - 1 else int_of_float (float_of_int size *. v)
      else if is_end then int_of_float (v -. 1.)
      else int_of_float v - 1

let usage_error msg = `Error (false, msg)

let dump_scene iopts input =
  match Interp.load_file iopts input with
  | exception Error.Scene_error e -> fail e
  | scene, warnings ->
      List.iter print_warning warnings;
      print_string (Dump.scene scene);
      `Ok 0

(* The command line as cmdliner read it, one field per option, before any value is checked or
   clipped (that is [run]'s work). *)
type options = {
  input : string option;  (** +I: the scene file *)
  scene : string option;  (** the scene file given without +I, as the first positional argument *)
  output : string option;  (** +O: the output file, or a directory to write it in *)
  width : int;  (** +W: image width in pixels *)
  height : int;  (** +H: image height in pixels *)
  antialias : bool;  (** +A or -A *)
  aa_threshold : float;  (** +A0.3's value, Antialias_Threshold *)
  sampling_method : int;  (** +AM: the antialiasing method, as given *)
  aa_depth : int;  (** +R: the supersampling depth, as given *)
  jitter : bool;  (** +J or -J *)
  jitter_amount : float;  (** +J0.5's value, Jitter_Amount, as given *)
  aa_gamma : float;  (** +AG: the gamma of the antialiasing colour comparison *)
  library_paths : string list;  (** +L: the include directories, in order *)
  threads : int;  (** +WT: render processes, as given *)
  start_row : float option;  (** +SR: a fraction below 1, else a 1-based row *)
  end_row : float option;  (** +ER *)
  start_column : float option;  (** +SC *)
  end_column : float option;  (** +EC *)
  block_size : int;  (** +BS: render block size, as given *)
  format : [ `Png | `Ppm ];  (** +FN or +FP *)
  output_to_file : bool;  (** +F or -F: whether the image is written *)
  bounding_threshold : int;  (** +MBn: POV-Ray's Bounding_Threshold, [max_int] with -MB (Bounding=off) *)
  display : bool;  (** +D or -D: accepted, without effect *)
  verbose : bool;  (** +V or -V: accepted, without effect *)
  clock : float option;  (** +K: the value of [clock] in the scene *)
  animation : Animation.settings;  (** +KFI, +KFF, +KI, +KF, +KC, +SF, +EF, Frame_Step *)
  declares : string list;  (** Declare=NAME=VALUE, as given *)
  dump : bool;  (** --dump: print the evaluated scene instead of rendering it *)
  robust : bool;  (** --robust: robust intersection limits instead of POV-Ray's *)
  scene_scale : float;  (** --scene-scale: the scene scaled about the origin *)
  scene_translate : Vec.t;  (** --scene-translate: the scene moved, after the scale *)
  allow_read : string list;  (** --allow-read: directories the scene may read *)
  allow_write : string list;  (** --allow-write: directories the scene may write *)
  limits : Scene_limits.t;  (** the --max-… limits *)
}

let make_options input scene output width height antialias aa_threshold sampling_method aa_depth jitter
    jitter_amount aa_gamma library_paths threads start_row end_row start_column end_column block_size format
    output_to_file bounding_threshold display verbose clock animation declares dump robust scene_scale scene_translate allow_read allow_write limits =
  { input; scene; output; width; height; antialias; aa_threshold; sampling_method; aa_depth; jitter;
    jitter_amount; aa_gamma; library_paths; threads; start_row; end_row; start_column; end_column; block_size; format;
    output_to_file; bounding_threshold; display; verbose; clock; animation; declares; dump; robust; scene_scale; scene_translate; allow_read; allow_write; limits }

let run (args : options) =
  let { width; height; limits; _ } = args in
  let input = match (args.input, args.scene) with Some i, _ -> Some i | None, Some p -> Some p | None, None -> None in
  match input with
  | None -> usage_error "no scene file given: use +I<file> or give the file name"
  | Some input ->
      let access = List.fold_left Access.allow_read Access.default args.allow_read in
      let access = List.fold_left Access.allow_write access args.allow_write in
      let iopts =
        {
          (Interp.default_options ~width ~height) with
          (* POV-Ray keeps the clock in single precision *)
          clock = Precision.f32 (Option.value args.clock ~default:0.);
          animation = Animation.still ~clock_on:(args.clock <> None);
          declares = List.filter_map Ini.declaration args.declares;
          library_paths = args.library_paths;
          access;
          limits;
        }
      in
      if width < 1 || height < 1 then usage_error "width and height must be at least 1"
      else if width > limits.pixels / height then
        fail
          (Error.limit_error Loc.none
             (Printf.sprintf "a %d×%d image has %s pixels, more than povml's limit of %s (raise it with --max-pixels N)" width height
                (if width > max_int / height then "over " ^ Reader.commas max_int else Reader.commas (width * height))
                (Reader.commas limits.pixels)))
      else if args.dump then dump_scene iopts input
      else
        let fmt = match args.format with `Png -> Png_fmt | `Ppm -> Ppm_fmt in
        if fmt = Png_fmt && args.output_to_file && (width > Output.png_max_side || height > Output.png_max_side) then
          fail
            (Error.limit_error Loc.none
               (Printf.sprintf
                  "a PNG is at most %s pixels wide and high (libpng's limit; POV-Ray's render fails when it writes one), this image is %d×%d: write a PPM instead (+FP)"
                  (Reader.commas Output.png_max_side) width height))
        else
        let output =
          match args.output with
          | None -> default_output input fmt
          | Some o when Sys.file_exists o && Sys.is_directory o ->
              Filename.concat o (Filename.basename (default_output input fmt))
          | Some o -> o
        in
        let area =
          {
            Render.left = max 0 (area_bound width args.start_column ~is_end:false);
            right = min (width - 1) (area_bound width args.end_column ~is_end:true);
            top = max 0 (area_bound height args.start_row ~is_end:false);
            bottom = min (height - 1) (area_bound height args.end_row ~is_end:true);
          }
        in
        if area.left > area.right || area.top > area.bottom then usage_error "the partial render area is empty"
        else
          (* POV-Ray clips the method to 0 … 2, and method 0 is no antialiasing *)
          let method_ = args.sampling_method in
          let antialias = if args.antialias && method_ > 0 then Some args.aa_threshold else None in
          let opts =
            {
              Render.width;
              height;
              antialias = Option.map (fun t -> Float.min 1. (Float.max 0. t)) antialias;
              aa_method = (if method_ >= 2 then Render.Adaptive else Render.Non_adaptive);
              aa_depth = max 1 (min 9 args.aa_depth);
              jitter = (if args.jitter then Float.min 1. (Float.max 0. args.jitter_amount) else 0.);
              aa_gamma = args.aa_gamma;
              area;
              block_size = max 4 (min (max width height) args.block_size);
              workers = max 1 args.threads;
              progress = Unix.isatty Unix.stderr;
              robust = args.robust;
            }
          in
          let scene_scale = args.scene_scale and scene_translate = args.scene_translate in
          let move =
            if scene_scale = 1. && scene_translate = Vec.zero then None else Some (scene_scale, scene_translate)
          in
          if not (scene_scale > 0. && Float.is_finite scene_scale) then usage_error "--scene-scale must be a positive number"
          else
          let () = Interrupt.install () in
          let render_to iopts output =
          match Pipeline.run ~interp:iopts ?move ~bounding_threshold:args.bounding_threshold opts input with
          | exception Error.Scene_error e -> fail e
          | exception Pool.Cannot_write reason ->
              Printf.eprintf "povml: cannot write the render processes' results in %s; no image was written\n" reason;
              `Ok Exits.cannot_write
          | exception Pool.Worker_failed msg ->
              (* a render process died: not the scene's fault *)
              Printf.eprintf "povml: internal error: %s; no image was written (please report it)\n" msg;
              `Ok Exits.internal_error
          | r -> (
              List.iter print_warning r.warnings;
              let f = match fmt with Png_fmt -> Output.Png | Ppm_fmt -> Output.Ppm in
              let drawn = Merge.to_text { Merge.left = area.left; top = area.top; right = area.right; bottom = area.bottom; block = opts.block_size } in
              if not args.output_to_file then begin print_stats r opts; `Ok 0 end
              else
              match Interrupt.commit (fun () -> Output.write ~area:drawn f output r.image) with
              | Error msg ->
                  Printf.eprintf "%s: error: cannot write the image: %s\n" output msg;
                  `Ok Exits.cannot_write
              | Ok () ->
                  print_stats r opts;
                  Printf.eprintf "Wrote %s (%dx%d)\n" output width height;
                  `Ok 0)
          in
          match Animation.plan args.animation with
          | None -> render_to iopts output
          | Some plan ->
              (* one image per frame, the scene read anew for each, named as POV-Ray names them:
                 the output name without its extension (or the scene's name), the frame number
                 padded to the final frame's digits, the extension *)
              let ext = match fmt with Png_fmt -> ".png" | Ppm_fmt -> ".ppm" in
              let base =
                match args.output with
                | Some o when not (Sys.file_exists o && Sys.is_directory o) ->
                    if Filename.check_suffix o ext then Filename.chop_suffix o ext
                    else if o <> "" && o.[String.length o - 1] = '.' then String.sub o 0 (String.length o - 1)
                    else o
                | Some _ | None -> Filename.remove_extension output
              in
              let rec frames i (rest : Animation.frame Seq.t) =
                match rest () with
                | Seq.Nil -> `Ok 0
                | Seq.Cons (f, rest) -> (
                    Printf.eprintf "Frame %d of %d: frame_number %d, clock %s\n%!" i plan.count f.values.frame_number
                      (Printf.sprintf "%.9g" f.clock);
                    let iopts = { iopts with clock = f.clock; animation = f.values } in
                    match render_to iopts (Animation.numbered base ~frame:f.values.frame_number ~digits:plan.digits ^ ext) with
                    | `Ok 0 -> frames (i + 1) rest
                    | r -> r)
              in
              frames 1 plan.frames

(* the switch that keeps povml from reading POVINI's file or a povray.ini *)
let no_povray_ini = "no-povray-ini"

let cmd =
  let doc = "render POV-Ray 3.7 scenes, pixel for pixel as POV-Ray does" in
  let sw = "POV-RAY SWITCHES" in
  let man =
    [
      `S Manpage.s_description;
      `P "$(tname) reads a POV-Ray scene description ($(b,.pov)) and renders it with a recursive \
          Whitted ray tracer that follows POV-Ray 3.7.0.10's rules, so that on the features it supports \
          the PNG it writes equals POV-Ray's.";
      `P "POV-Ray's own switches are accepted as they are and mean the same: $(b,+I)file, $(b,+O)file, \
          $(b,+W)n, $(b,+H)n, $(b,+A)[threshold], $(b,-A), $(b,+AM)n, $(b,+R)n, $(b,+J)[amount], $(b,-J), \
          $(b,+L)dir, $(b,+K)v, $(b,+WT)n, $(b,+SR)/$(b,+ER)/$(b,+SC)/$(b,+EC) (partial render: full-size file, \
          unrendered pixels black), $(b,+FN) (PNG), $(b,+FP) (PPM), $(b,-F) (no file), $(b,+MB)n/$(b,-MB) (bounding \
          threshold, or none), $(b,+D)/$(b,-D), $(b,+V)/$(b,-V). \
          Each is shown below with its long form.";
      `P "A scene reads files ($(b,#include), $(b,#fopen), $(b,file_exists)) only under its own directory, \
          the working directory, the $(b,+L) directories, /usr/share/povray-3.7/include and each \
          $(b,--allow-read) directory, and writes files only under an $(b,--allow-write) directory; paths are \
          resolved ($(b,..), symbolic links) before they are compared. POV-Ray's povray.conf is not read.";
      `S sw;
      `S Manpage.s_commands;
      `P "$(b,povml check) $(i,SCENE) [$(i,SWITCH)]… renders the scene with povml and with the installed POV-Ray, \
          prints the differing pixels, peak, RMSE, PSNR and both wall times, writes a heat map of the \
          differences and fails above the thresholds given ($(b,povml check --help)).";
      `P "$(b,povml report) $(i,SCENE)… $(b,--out) $(i,DIR) [$(i,SWITCH)]… sweeps antialiasing and trace-depth \
          settings in both renderers and writes error against time as CSV, Markdown and an SVG plot with each \
          renderer's Pareto front ($(b,povml report --help)).";
    ]
    @ Exits.man
    @ [
      `S "LIMITS";
      `P "Every scene ends, with an image or a located error, in bounded time and memory: loops, macro calls, \
          nesting, objects, memory and image size have limits, each set with its switch. The defaults are far above \
          what ordinary scenes need.";
      `S Manpage.s_examples;
      `P "povml +Iscenes/showcase.pov +W640 +H480 +A0.3";
    ]
  in
  let docs = sw in
  let opt_str names dv doc = Arg.(value & opt (some string) None & info names ~docv:dv ~docs ~doc) in
  let input = opt_str [ "input"; "I" ] "FILE" "+I: the scene file to render." in
  let positional = Arg.(value & pos 0 (some string) None & info [] ~docv:"SCENE" ~doc:"The scene file (same as +I).") in
  let output = opt_str [ "output"; "O" ] "FILE" "+O: the output file. Default: the scene's name with .png (or .ppm), beside the scene." in
  let width = Arg.(value & opt int 160 & info [ "width"; "W" ] ~docv:"N" ~docs ~doc:"+W: image width in pixels (POV-Ray's built-in default 160).") in
  let height = Arg.(value & opt int 120 & info [ "height"; "H" ] ~docv:"N" ~docs ~doc:"+H: image height in pixels (default 120).") in
  let antialias =
    Arg.(value & vflag false
           [ (true, info [ "antialias" ] ~docs ~doc:"+A[threshold], Antialias=on: antialias.");
             (false, info [ "no-antialias" ] ~docs ~doc:"-A: no antialiasing (the default).") ])
  in
  let aa_threshold =
    Arg.(value & opt float 0.3 & info [ "antialias-threshold" ] ~docv:"T" ~docs
           ~doc:"+A's value, Antialias_Threshold: a pixel is supersampled when it differs from a neighbour by at least T \
                 (default 0.3); setting it does not turn antialiasing on.")
  in
  let jitter_amount =
    Arg.(value & opt float 1. & info [ "jitter-amount" ] ~docv:"J" ~docs
           ~doc:"+J's value, Jitter_Amount: how far antialiasing samples are jittered (default 1; POV-Ray's deterministic jitter).")
  in
  let method_ = Arg.(value & opt int 1 & info [ "sampling-method" ] ~docv:"N" ~docs ~doc:"+AM: antialiasing method: 1 (non-adaptive, the default), 2 (adaptive, recursive); as in POV-Ray, 0 or less means no antialiasing and more than 2 means 2.") in
  let depth = Arg.(value & opt int 3 & info [ "aa-depth" ] ~docv:"N" ~docs ~doc:"+R: supersampling depth (1 … 9, default 3): N×N samples per supersampled pixel with method 1, at most N−1 subdivisions of a pixel with method 2.") in
  let jitter =
    Arg.(value & vflag true
           [ (true, info [ "jitter" ] ~docs ~doc:"+J[amount], Jitter=on: jitter antialiasing samples (the default).");
             (false, info [ "no-jitter" ] ~docs ~doc:"-J: no jitter.") ])
  in
  let aa_gamma = Arg.(value & opt float 2.5 & info [ "aa-gamma" ] ~docv:"G" ~docs ~doc:"+AG: gamma for the antialiasing colour comparison (default 2.5).") in
  let libs = Arg.(value & opt_all string [] & info [ "library-path" ] ~docv:"DIR" ~docs ~doc:"+L: a directory searched for include files (repeatable).") in
  let threads = Arg.(value & opt int 2 & info [ "threads" ] ~docv:"N" ~docs ~doc:"+WT: render processes (default 2). The image is the same for any N.") in
  let fl names doc = Arg.(value & opt (some float) None & info names ~docv:"V" ~docs ~doc) in
  let sr = fl [ "start-row" ] "+SR: first row of a partial render (a fraction below 1, else a 1-based row)." in
  let er = fl [ "end-row" ] "+ER: last row of a partial render." in
  let sc = fl [ "start-column" ] "+SC: first column of a partial render." in
  let ec = fl [ "end-column" ] "+EC: last column of a partial render." in
  let block_size = Arg.(value & opt int 32 & info [ "block-size" ] ~docv:"N" ~docs ~doc:"+BS: render block size (default 32, as POV-Ray; antialiasing depends on it).") in
  let format =
    Arg.(value & opt (enum [ ("png", `Png); ("ppm", `Ppm) ]) `Png & info [ "format" ] ~docv:"FMT" ~docs ~doc:"+FN (png, default) or +FP (ppm): output file type.")
  in
  let output_to_file =
    Arg.(value & vflag true [ (true, info [ "output-to-file" ] ~docs ~doc:"+F: write the image (the default)."); (false, info [ "no-output-to-file" ] ~docs ~doc:"-F: render without writing the image.") ])
  in
  let bounding =
    let on = Arg.(value & vflag true [ (true, info [ "bounding" ] ~docs ~doc:"+MB: use POV-Ray's bounding tree (the default)."); (false, info [ "no-bounding" ] ~docs ~doc:"-MB, Bounding=off: never use it.") ]) in
    let threshold =
      Arg.(value & opt int Compile.pov_bounding_threshold & info [ "bounding-threshold" ] ~docv:"N" ~docs
             ~doc:"+MBn, Bounding_Threshold: POV-Ray builds its bounding tree only for scenes of at least N objects and light \
                   sources (default 1; Debian's povray.ini sets 3). Without it objects are tested in scene order, and the order \
                   in which POV-Ray tests objects decides exact ties and the isosurfaces' shared cache, so it shows in the image.")
    in
    Term.(const (fun on n -> if on then n else max_int) $ on $ threshold)
  in
  let display = Arg.(value & vflag false [ (true, info [ "display" ] ~docs ~doc:"+D: accepted; povml has no preview window."); (false, info [ "no-display" ] ~docs ~doc:"-D: no preview window.") ]) in
  let verbose = Arg.(value & vflag false [ (true, info [ "verbose" ] ~docs ~doc:"+V: accepted."); (false, info [ "no-verbose" ] ~docs ~doc:"-V: accepted.") ]) in
  let clock = Arg.(value & opt (some float) None & info [ "clock" ] ~docv:"V" ~docs ~doc:"+K: the value of $(b,clock) in the scene (default 0).") in
  let declares =
    Arg.(value & opt_all string [] & info [ "declare" ] ~docv:"NAME=VALUE" ~docs
           ~doc:"Declare=NAME=VALUE: declare the identifier NAME before the scene is read, a float (C's atof, single precision, six significant digits, as POV-Ray passes it) or a string when VALUE is quoted.")
  in
  let animation =
    let io kind names docv doc = Arg.(value & opt (some kind) None & info names ~docv ~docs ~doc) in
    let make initial_frame final_frame initial_clock final_clock cyclic no_cyclic subset_start subset_end frame_step =
      { Animation.initial_frame; final_frame; initial_clock; final_clock; cyclic = cyclic && not no_cyclic; subset_start; subset_end; frame_step }
    in
    Term.(
      const make
      $ io Arg.int [ "initial-frame" ] "N" "+KFIn, Initial_Frame: the animation's first frame (default 1)."
      $ io Arg.int [ "final-frame" ] "N"
          "+KFFn, Final_Frame: the animation's last frame; with frames other than 1 to 1 povml renders an animation, one \
           image per frame, numbered."
      $ io Arg.float [ "initial-clock" ] "V" "+KIv, Initial_Clock: the clock of the first frame (default 0)."
      $ io Arg.float [ "final-clock" ] "V" "+KFv, Final_Clock: the clock of the last frame (default 1)."
      $ Arg.(value & flag & info [ "cyclic" ] ~docs ~doc:"+KC, Cyclic_Animation: the last frame is not the final clock but one step before it.")
      $ Arg.(value & flag & info [ "no-cyclic" ] ~docs ~doc:"-KC: not cyclic (the default).")
      $ io Arg.float [ "subset-start" ] "N" "+SFn, Subset_Start_Frame: render the frames from N (a fraction below 1: that share of them)."
      $ io Arg.float [ "subset-end" ] "N" "+EFn, Subset_End_Frame: render the frames up to N."
      $ io Arg.int [ "frame-step" ] "N" "Frame_Step: render every N-th frame.")
  in
  let dump =
    Arg.(value & flag & info [ "dump" ]
           ~doc:"Print the evaluated scene instead of rendering it: every object after all directives, macros and \
                 loops, with its final shape, transform, texture and interior, and where it was written.")
  in
  let robust =
    Arg.(value & flag & info [ "robust" ]
           ~doc:"Robust mode: instead of POV-Ray's fixed intersection limits (hits nearer than 1e-4, shadow hits \
                 within 1e-3, nothing beyond 1e7), secondary rays leave from the hit point moved off the surface by a \
                 bound on its rounding error and accept every positive depth, so the picture does not depend on the \
                 scene's size or distance from the origin. The default is exactly POV-Ray's.")
  in
  let scene_scale =
    Arg.(value & opt float 1. & info [ "scene-scale" ] ~docv:"S"
           ~doc:"Render the scene scaled by S about the origin: objects, lights, camera and fade distances (for \
                 checking that a picture does not depend on the scene's size).")
  in
  let scene_translate =
    let vec =
      let parse s =
        match List.map float_of_string_opt (String.split_on_char ',' s) with
        | [ Some x; Some y; Some z ] -> Ok (Vec.make x y z)
        | _ -> Error (`Msg (Printf.sprintf "'%s' is not a vector X,Y,Z" s))
      in
      Arg.conv (parse, fun f (v : Vec.t) -> Format.fprintf f "%g,%g,%g" v.x v.y v.z)
    in
    Arg.(value & opt vec Vec.zero & info [ "scene-translate" ] ~docv:"X,Y,Z"
           ~doc:"Render the scene moved by X,Y,Z (after $(b,--scene-scale)): objects, lights and camera.")
  in
  let allow_read =
    Arg.(value & opt_all dir [] & info [ "allow-read" ] ~docv:"DIR" ~docs
           ~doc:"Let the scene read the files under DIR ($(b,#include), $(b,#fopen) ... $(b,read), \
                 $(b,file_exists)); repeatable. Without it a scene reads only under its own directory, the \
                 working directory, the $(b,+L) directories and /usr/share/povray-3.7/include.")
  in
  let allow_write =
    Arg.(value & opt_all dir [] & info [ "allow-write" ] ~docv:"DIR" ~docs
           ~doc:"Let the scene write (and read) the files under DIR ($(b,#fopen) ... $(b,write) or \
                 $(b,append)); repeatable. Without it a scene writes no file.")
  in
  let limits =
    let lim = "LIMITS" in
    let n names default doc = Arg.(value & opt int default & info names ~docv:"N" ~docs:lim ~doc) in
    let d = Scene_limits.default in
    let make include_depth macro_depth macro_calls iterations objects nesting memory_mb pixels pattern_steps function_steps string_mb =
      { Scene_limits.include_depth; macro_depth; macro_calls; iterations; objects; nesting; memory_mb; pixels; pattern_steps; function_steps; string_mb }
    in
    Term.(
      const make
      $ n [ "max-include-depth" ] d.include_depth "Include files nested deeper than N are an error (default 64; POV-Ray stops at 31)."
      $ n [ "max-macro-depth" ] d.macro_depth "Macro calls nested deeper than N are an error (default 10,000; POV-Ray stops at 98)."
      $ n [ "max-macro-calls" ] d.macro_calls "More than N macro calls in the whole scene are an error (default 3,000,000)."
      $ n [ "max-iterations" ] d.iterations
          "More than N iterations of $(b,#while) and $(b,#for) loops, all loops together, are an error (default 10,000,000): \
           a loop that never ends stops with an error at the loop."
      $ n [ "max-objects" ] d.objects "More than N objects and light sources in the scene are an error (default 10,000,000; a mesh counts as one)."
      $ n [ "max-nesting" ] d.nesting
          "Parentheses, vectors, signs and unions nested deeper than N are an error (default 10,000; POV-Ray warns about \
           blocks nested deeper than 200 and povml gives the same warning)."
      $ n [ "max-memory" ] d.memory_mb "Reading a scene that needs more than N MiB of memory is an error (default 4,096, or half of $(b,ulimit -v) when that is less)."
      $ n [ "max-pixels" ] d.pixels "An image of more than N pixels (width × height) is an error (default 67,108,864 = 8192²)."
      $ n [ "max-pattern-steps" ] d.pattern_steps
          "A pattern that does more than N steps at each point is an error (default 100,000): a fractal's iterations, \
           $(b,number_of_waves)."
      $ n [ "max-function-steps" ] d.function_steps
          "User functions called while the scene is read that take more than N steps, all calls together, are an \
           error (default 1,000,000,000): a step is an operation of a function's body, taken at each call and at \
           each iteration of $(b,sum) and $(b,prod). Rendering is not counted."
      $ n [ "max-strings" ] d.string_mb
          "Strings built by the string functions ($(b,concat), $(b,str), $(b,substr) …) of more than N MiB, all \
           together, are an error (default 4,096): a string grown one character at a time a million times stops.")
  in
  let term =
    let options =
      Term.(
        const make_options $ input $ positional $ output $ width $ height $ antialias $ aa_threshold $ method_ $ depth $ jitter
        $ jitter_amount $ aa_gamma $ libs $ threads $ sr $ er $ sc $ ec $ block_size $ format $ output_to_file $ bounding $ display $ verbose $ clock $ animation $ declares
        $ dump $ robust $ scene_scale $ scene_translate $ allow_read $ allow_write $ limits)
    in
    let ignore_ini =
      Arg.(value & flag & info [ no_povray_ini ]
             ~doc:"Read no ini file before the command line. Without it povml reads the one POV-Ray reads: the file the \
                   $(b,POVINI) environment variable names, else the first of ./povray.ini, ~/.povray/3.7/povray.ini, \
                   /etc/povray/3.7/povray.ini, ~/.povrayrc and /etc/povray.ini (Debian's sets 800×600 and \
                   Bounding_Threshold=3); the command line's switches come after it and win.")
    in
    Term.(ret (const (fun o _ -> run o) $ options $ ignore_ini))
  in
  Cmd.v (Cmd.info "povml" ~version:"0.1.0" ~doc ~man ~exits:[]) term

let () =
  (* a larger minor heap: rays allocate small short-lived vectors, and fewer of them get promoted;
     no compaction: a render is one short run, and compacting a large parsed scene only costs time *)
  Gc.set { (Gc.get ()) with minor_heap_size = 1 lsl 20; max_overhead = 1_000_000 };
  let argv = Array.to_list Sys.argv in
  let prog = List.hd argv in
  (match argv with
  | _ :: (("check" | "report") as sub) :: rest -> exit (Subcommands.main ~translate:translate_switch prog sub rest)
  | _ :: "merge" :: rest -> exit (Subcommands.merge prog rest)
  | _ -> ());
  (* an ini file, named alone or after +I, stands for the switches it holds, where it is named *)
  let argv =
    let expand a =
      let named = if String.length a > 2 && (a.[0] = '+' || a.[0] = '-') && Char.uppercase_ascii a.[1] = 'I' then Some (String.sub a 2 (String.length a - 2)) else if a <> "" && a.[0] <> '-' && a.[0] <> '+' then Some a else None in
      match named with
      | Some f when Ini.is_ini f -> Ini.switches ~warn:print_warning f
      | Some f when f == a && Ini.is_option a -> Ini.option ~warn:print_warning a
      | Some _ | None -> [ a ]
    in
    (* POV-Ray's Unix front end reads one ini file before the command line (POVINI's, or the
       first povray.ini it finds) and puts POVINC's directory after every other library path *)
    let default_ini () =
      if List.mem ("--" ^ no_povray_ini) argv then []
      else
        let readable f = Sys.file_exists f && (not (Sys.is_directory f)) && match open_in_bin f with ic -> close_in ic; true | exception Sys_error _ -> false in
        let file, warnings = Ini.default_file ~getenv:Sys.getenv_opt ~readable in
        List.iter print_warning warnings;
        match file with Some f -> Ini.switches ~warn:print_warning f | None -> []
    in
    let povinc = match Sys.getenv_opt "POVINC" with Some d when d <> "" -> [ "+L" ^ d ] | Some _ | None -> [] in
    match default_ini () @ List.concat_map expand (List.tl argv) @ povinc with
    | exception Error.Scene_error e -> print_error e; exit (Exits.scene_error e.kind)
    | args -> prog :: args
  in
  let bad = ref None in
  let args =
    List.concat_map
      (fun a ->
        match translate_switch a with
        (* a long option with its value (an ini file's --antialias-threshold=0.3) is a switch too *)
        | `Keep a when String.length a > 2 && String.sub a 0 2 = "--" && String.contains a '=' -> [ `Switch a ]
        | `Keep a -> [ `Keep a ]
        | `Use l -> List.map (fun a -> `Switch a) l
        | `Bad -> if !bad = None then bad := Some a; [ `Keep a ])
      (List.tl argv)
  in
  (* As in POV-Ray, the last of repeated switches wins (+W16 … +W640 is 640 wide; -A … +A0.3
     antialiases); +L, Declare and the --allow-… directories accumulate. *)
  let key a =
    let name = match String.index_opt a '=' with Some i -> String.sub a 2 (i - 2) | None -> String.sub a 2 (String.length a - 2) in
    if String.length name > 3 && String.sub name 0 3 = "no-" then String.sub name 3 (String.length name - 3) else name
  in
  let rec last_wins = function
    | [] -> []
    | `Keep a :: rest -> a :: last_wins rest
    | `Switch a :: rest ->
        let k = key a in
        if (not (List.mem k [ "library-path"; "declare"; "allow-read"; "allow-write" ])) && List.exists (function `Switch b -> key b = k | `Keep _ -> false) rest then last_wins rest
        else a :: last_wins rest
  in
  let args = last_wins args in
  match !bad with
  | Some a ->
      Printf.eprintf "povml: unknown or incomplete switch '%s' (see povml --help)\n" a;
      exit 2
  | None -> (
      exit @@ Exits.guard @@ fun () ->
      match Cmd.eval_value ~catch:false ~argv:(Array.of_list (prog :: args)) cmd with
      | Ok (`Ok code) -> code
      | Ok (`Version | `Help) -> 0
      | Error (`Parse | `Term) -> 2
      | Error `Exn -> Exits.internal_error)
