(* The interpreter: the statements of a scene read by a recursive-descent reader that evaluates as
   it goes, the way POV-Ray does, then the immutable Scene.t built from them. The parser state is
   private to one [load_string] call. *)

open Token
open Reader
open Objects
open Settings
open Declare
open Directives

type options = Reader.options = {
  width : int;
  height : int;
  clock : float;
  animation : Animation.values;
  declares : (string * Value.t) list;
  library_paths : string list;
  debug : string -> unit;
  included : string -> depth:int -> float -> unit;
  limits : Scene_limits.t;
  access : Access.t;
}

let keywords = Reader.keywords


let rec parse_statements st =
  let loc = peek_loc st in
  match peek st with
  | Eof -> ()
  | Ident "camera" ->
      advance st;
      if st.camera <> None then warn st loc "more than one camera in scene; ignoring previous camera(s)";
      st.camera <- Some (parse_camera st);
      parse_statements st
  | Ident "light_source" ->
      (match parse_light_source st with Lights.Lone l -> st.lights <- l :: st.lights | Shaped o -> Csg_build.add_object st o);
      parse_statements st
  | Ident "background" -> parse_background st; parse_statements st
  | Ident "sky_sphere" -> parse_sky_sphere st; parse_statements st
  | Ident "global_settings" -> advance st; parse_global_settings st; parse_statements st
  | Ident "max_trace_level" ->
      (* the old place of max_trace_level, still read, with POV-Ray's two warnings (Parse_Frame) *)
      advance st;
      if st.version >= 350 then
        warn st loc "'max_trace_level' should be in global_settings block. Future versions may not support 'max_trace_level' outside global_settings.";
      if st.version >= 300 then warn st loc "'max_trace_level' should be in 'global_settings{...}' statement.";
      parse_max_trace_level st loc;
      parse_statements st
  | Ident "max_intersections" ->
      advance st;
      ignore (Expr.parse_float st);
      if st.version >= 370 then warn st loc "'max_intersections' is no longer needed and has no effect in POV-Ray 3.7 or later.";
      parse_statements st
  | Ident ("default" | "version" as d) ->
      (* old scenes write these directives without '#' where an object may stand; POV-Ray takes them *)
      advance st; directive st d loc; parse_statements st
  | Ident ("declare" | "include" as d) ->
      warn st loc "should have '#' before '%s'" d;
      advance st; directive st d loc; parse_statements st
  | _ when object_follows st -> Csg_build.add_object st (parse_object st); parse_statements st
  | _ -> unexpected st "an object, light_source, camera or directive"

let finish_scene st : Scene.t =
  if st.objects = [] && st.lights = [] then warn st Loc.none "no objects in scene";
  (* §8.1: without #version the effective version is 3.62 *)
  let version = if st.version_set then st.version else 362 in
  let gamma =
    match st.assumed_gamma with
    | Some g -> Scene.Working g
    | None when version >= 370 ->
        warn st Loc.none
          "assumed_gamma not specified in this POV-Ray 3.7 or later scene; the working gamma is 1.0 (add 'assumed_gamma 1.0' to global_settings)";
        Scene.Working 1.
    | None ->
        warn st Loc.none "assumed_gamma not specified, so gamma correction is turned off for compatibility with this pre POV-Ray 3.7 scene";
        Scene.Gamma_off
  in
  if not st.version_set then
    warn st Loc.none
      "this scene did not contain a #version directive; it is rendered as a POV-Ray 3.62 scene (no gamma correction, legacy transparency); add '#version 3.7;' at the start";
  let background =
    match st.background with
    | Some b -> b
    | None -> Colour.black
  in
  let camera = build_camera st (match st.camera with Some c -> c | None -> empty_camera) in
  {
    Scene.camera;
    objects = List.rev st.objects;
    lights = List.rev st.lights;
    background;
    sky = st.sky;
    ambient_light = st.ambient_light;
    max_trace_level = st.max_trace_level;
    adc_bailout = st.adc_bailout;
    noise_generator = st.noise_generator;
    irid_wavelength = st.irid_wavelength;
    version;
    gamma;
    shift = 0.;
  }

(* Where the reading was when an error arose: the include and macro-call chain, innermost first. *)
let chain st =
  let notes =
    List.filter_map
      (fun f ->
        match f.kind with
        | Main -> None
        | Included (l, _) -> Some (l, "in the file included from here")
        | Macro_body (name, l) -> Some (l, Printf.sprintf "in macro '%s' called from here" name))
      st.frames
  in
  (* a deep recursion is shown by its innermost calls and the outermost ones *)
  let n = List.length notes in
  if n <= 8 then notes
  else
    List.filteri (fun i _ -> i < 5) notes
    @ [ (Loc.none, Printf.sprintf "… %d more calls and includes …" (n - 7)) ]
    @ List.filteri (fun i _ -> i >= n - 2) notes

let reader_state opts ~file text =
  (* the scene may read the files beside it and in the library paths *)
  let access = List.fold_left Access.allow_read opts.access (Filename.dirname file :: opts.library_paths) in
  let opts = { opts with access } in
  let lexer = Lexer.create ~file text in
  let global = Names.create 256 in
  let st =
    {
      frames = [ { lx = lexer; kind = Main; conds = [] } ];
      cur = { Token.kind = Eof; loc = Loc.none }; have = false; cur_elem = None; no_expand = false; defer = false; in_rvalue = false; pending_macro = None; streams = [||];
      depth = 0; parens = 0; opts; global; tables = [ global ]; includes = 0; macro_depth = 0;
      macro_calls = 0; iterations = 0; string_bytes = 0; nesting = 0; braces = 0; object_count = 0; isosurfaces = 0; split_unions = 0; probe_work = lazy (Scratch.create ~robust:false (Stats.create ())); probed = None;
      version = 370; version_set = false; charset = Ascii; warnings = [];
      objects = []; lights = []; camera = None; background = None; sky = None;
      assumed_gamma = None; max_trace_level = 5; adc_bailout = 1. /. 255.; noise_generator = 2; irid_wavelength = Rgb.make (Precision.f32 0.70) (Precision.f32 0.52) (Precision.f32 0.48); number_of_waves = 10; ambient_light = Rgb.white;
      default_texture = Defaults.layer;
      directive = (fun _ _ _ -> ()); invoke = (fun _ _ _ -> ()); index = (fun _ _ -> 0); files = [];
      read_object = (fun _ -> None);
      read_pigment = (fun _ -> Scene.Solid Colour.black);
      read_special_function = (fun _ _ _ -> None);
    }
  in
  st.directive <- directive;
  st.invoke <- invoke;
  st.index <- parse_index;
  st.read_object <- (fun st -> if object_follows st then Some (parse_object st) else None);
  st.read_pigment <- (fun st -> Materials.parse_pigment st (Scene.Solid Colour.black));
  st.read_special_function <- special_function;
  st

let load_string opts ~file text =
  let st = reader_state opts ~file text in
  List.iter (fun (name, v) -> Reader.Names.replace st.global name (ref v)) opts.declares;
  Fn_budget.start opts.limits.function_steps;
  (* the scene's files are closed when its text has been read, or at its first error *)
  Fun.protect ~finally:(fun () -> User_files.close_all st) (fun () ->
      try parse_statements st with
      | Unsupported (loc, what, notes) -> raise (unsupported_error loc what (notes @ chain st))
      | Error.Scene_error e -> raise (Error.Scene_error { e with notes = e.notes @ chain st })
      (* the limits above should come first; these are the last line of defence, located where the
         reader was *)
      | Stack_overflow ->
          raise
            (Error.Scene_error
               { loc = st.cur.loc; kind = Limit; notes = chain st;
                 msg = "the scene nests too deeply for the stack (lower --max-nesting or --max-macro-depth, or raise the stack size with ulimit -s)" })
      | Out_of_memory ->
          raise
            (Error.Scene_error
               { loc = st.cur.loc; kind = Limit; notes = chain st;
                 msg = "the scene needs more memory than the system gives povml (see --max-memory)" }));
  let scene = finish_scene st in
  (scene, List.rev st.warnings)

let default_options ~width ~height =
  {
    width;
    height;
    clock = 0.;
    animation = Animation.still ~clock_on:false;
    declares = [];
    library_paths = [];
    debug = (fun s -> prerr_string s; flush stderr);
    included = (fun _ ~depth:_ _ -> ());
    limits = Scene_limits.default;
    access = Access.default;
  }

let load_file opts path = load_string opts ~file:path (read_file path)

