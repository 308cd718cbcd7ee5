(* The interpreter: a recursive-descent reader of the token array that evaluates as it goes, the way
   POV-Ray does, and builds an immutable Scene.t. The parser state is private to one [load] call. *)

open Token
module V = Value

(* Tables keyed by names: the symbol tables and the keyword sets, searched for every identifier. *)
module Names = Hashtbl.Make (struct
  type t = string

  let equal = String.equal
  let hash = Hashtbl.hash
end)

type options = {
  width : int;
  height : int;
  clock : float;  (** +K *)
  library_paths : string list;  (** +L, searched in order after the including file's directory *)
  debug : string -> unit;  (** where #debug text goes *)
  included : string -> depth:int -> float -> unit;  (** an include file was read: path, nesting, seconds *)
}

type camera_spec = V.camera_spec = {
  c_location : Vec.t option;
  c_direction : Vec.t option;
  c_up : Vec.t option;
  c_right : Vec.t option;
  c_sky : Vec.t option;
  c_look_at : (Vec.t * Loc.t) option;
  c_angle : (float * Loc.t) option;
  c_trans : Transform.t option;  (* the camera's transforms, applied last (§1.3) *)
}

(* A feature povml does not render yet. Inside a declaration it makes the declared value
   [V.Unsupported] (an error only where it is used); anywhere else it is a located error. *)
exception Unsupported of Loc.t * string * (Loc.t * string) list

(* Where tokens come from: the scene file, an included file, or a macro body (§11.3). Each frame
   has its own stack of open conditionals and loops. *)
type frame = { lx : Lexer.t; kind : frame_kind; mutable conds : cond list }

and frame_kind =
  | Main
  | Included of Loc.t * float  (* where the #include was, and when reading it began *)
  | Macro_body of string * Loc.t  (* the macro and where it was called *)

and cond =
  | If_branch of Loc.t  (* inside the branch of an #if/#ifdef that is taken *)
  | While_loop of Lexer.mark * Loc.t  (* the mark is just before the condition *)
  | For_loop of { var : V.t ref; stop : float; step : float; body : Lexer.mark; floc : Loc.t }
  | Switch_case of { value : float; mutable running : bool; sloc : Loc.t }

type st = {
  mutable frames : frame list;  (* innermost first; never empty *)
  mutable cur : Token.t;  (* the current token, valid when [have] *)
  mutable have : bool;
  mutable cur_elem : (V.array_v * int) option;  (* the current token is this array element *)
  mutable no_expand : bool;
  mutable defer : bool;  (* reading past a complete value: a directive is kept, not run *)
  mutable streams : V.stream array;  (* the random streams made by seed() *)  (* reading the argument of defined(): a macro name is not called *)
  mutable depth : int;  (* '{' minus '}' consumed: how a declaration that fails is skipped *)
  opts : options;
  global : V.t ref Names.t;
  mutable tables : V.t ref Names.t list;  (* innermost first; the global table is last *)
  mutable includes : int;  (* open include files *)
  mutable macro_depth : int;
  mutable version : int;  (* languageVersion × 100 *)
  mutable version_set : bool;
  mutable warnings : Error.t list;  (* newest first *)
  mutable objects : Scene.obj list;  (* newest first *)
  mutable lights : Scene.light list;  (* newest first *)
  mutable camera : camera_spec option;
  mutable background : Colour.t option;
  mutable sky : Scene.sky option;
  mutable assumed_gamma : float option;
  mutable max_trace_level : int;
  mutable adc_bailout : float;
  mutable ambient_light : Rgb.t;
  mutable default_texture : Scene.texture;
  mutable directive : st -> string -> Loc.t -> unit;  (* the directive reader, tied below *)
  mutable invoke : st -> V.macro -> Loc.t -> unit;  (* the macro caller, tied below *)
  mutable index : st -> V.array_v -> int;  (* reads the subscripts of an array element, tied below *)
}

(* ---------------------------------------------------------------------------------------------- *)
(* Keywords *)

(* Keywords this interpreter reads. *)
let keywords =
  [ "adc_bailout"; "ambient"; "ambient_light"; "angle"; "assumed_gamma"; "background"; "blue"; "brilliance";
    "camera"; "clock"; "color"; "colour"; "conserve_energy"; "diffuse"; "direction"; "emission"; "exponent";
    "fade_color"; "fade_colour"; "fade_distance"; "fade_power"; "falloff"; "false"; "filter"; "finish"; "fresnel";
    "global_settings"; "gray"; "grey"; "green"; "hollow"; "image_height"; "image_width"; "interior"; "ior";
    "light_source"; "location"; "look_at"; "max_trace_level"; "metallic"; "no"; "no_shadow"; "object"; "off";
    "on"; "perspective"; "phong"; "phong_size"; "pi"; "pigment"; "plane"; "red"; "reflection";
    "reflection_exponent"; "refraction"; "rgb"; "rgbf"; "rgbft"; "rgbt"; "right"; "roughness"; "shadowless";
    "sky"; "sky_sphere"; "specular"; "sphere"; "t"; "texture"; "translate"; "transmit"; "true"; "u"; "up"; "v";
    "version"; "x"; "y"; "yes"; "z"; "albedo"; "charset"; "number_of_waves"; "noise_generator";
    "irid_wavelength"; "quick_color"; "quick_colour"; "abs"; "sqrt"; "sqr"; "sin"; "cos"; "tan"; "asin"; "acos";
    "atan"; "atan2"; "pow"; "exp"; "ln"; "log"; "min"; "max"; "int"; "floor"; "ceil"; "mod"; "div"; "radians";
    "degrees"; "vlength"; "vnormalize"; "vdot"; "vcross"; "select"; "triangle"; "smooth_triangle"; "mesh";
    "mesh2"; "vertex_vectors"; "normal_vectors"; "uv_vectors"; "texture_list"; "face_indices"; "normal_indices";
    "uv_indices"; "inside_vector" ]

(* POV-Ray keywords that a later povml will read; meeting one is a located "not supported yet". *)
let unsupported =
  [ "box"; "cylinder"; "cone"; "disc"; "torus"; "polygon";
    "prism"; "lathe"; "sor"; "blob"; "text"; "height_field"; "isosurface"; "superellipsoid"; "julia_fractal";
    "parametric"; "bicubic_patch"; "ovus"; "quadric"; "cubic"; "quartic"; "poly"; "intersection";
    "difference"; "merge"; "rotate"; "scale"; "matrix"; "transform"; "inverse"; "no_image"; "no_reflection";
    "double_illuminate"; "normal"; "material"; "checker"; "gradient"; "hexagon"; "brick"; "image_map";
    "bozo"; "marble"; "wood"; "agate"; "granite"; "spotted"; "leopard"; "onion"; "radial"; "spiral1";
    "spiral2"; "ripples"; "waves"; "wrinkles"; "bumps"; "dents"; "crackle"; "color_map"; "colour_map";
    "pigment_map"; "texture_map"; "spotlight"; "parallel"; "area_light"; "cylinder"; "looks_like";
    "projected_through"; "orthographic"; "fisheye"; "panoramic"; "ultra_wide_angle"; "omnimax";
    "cylindrical"; "spherical"; "aperture"; "focal_point"; "blur_samples"; "radiosity"; "photons";
    "media"; "fog"; "rainbow"; "irid"; "crand"; "dispersion"; "dispersion_samples"; "caustics";
    "bounded_by"; "clipped_by"; "uv_mapping"; "srgb"; "srgbf"; "srgbt"; "srgbft"; "subsurface";
    "interior_texture"; "light_group"; "no_radiosity"; "split_union"; "cutaway_textures"; "sturm";
    "open"; "phong_albedo"; "metallic_albedo"; "translucency" ]

let set_of l =
  let h = Names.create 64 in
  List.iter (fun s -> Names.replace h s ()) l;
  h

let keyword_set = set_of (keywords @ unsupported)
let unsupported_set = set_of unsupported
let is_keyword s = Names.mem keyword_set s
let is_unsupported s = Names.mem unsupported_set s

(* ---------------------------------------------------------------------------------------------- *)
(* Token access

   The parser sees one token at a time, as POV-Ray's does: [peek] reads the next token only when it is
   asked for, and reading is where directives run and macros are called (§11.3). So a directive is
   executed when the parser first looks past it, and [advance] never reads ahead. *)

let top st = List.hd st.frames

let lookup_cell st name =
  let rec go = function
    | [] -> None
    | t :: rest -> ( match Names.find_opt t name with Some c -> Some c | None -> go rest)
  in
  go st.tables

let lookup st name = match lookup_cell st name with Some c -> Some !c | None -> None

(* While looking past a value, directives wait (see [peek_follow]), except those that only end a
   branch or a macro body: they change no value, and a macro's value is often followed by its #end. *)
let closes_branch f d =
  match d with
  | "else" | "elseif" -> true
  | "end" -> ( match f.conds with [] -> (match f.kind with Macro_body _ -> true | Main | Included _ -> false) | (If_branch _ | Switch_case _) :: _ -> true | (While_loop _ | For_loop _) :: _ -> false)
  | _ -> false

let rec fill st =
  let f = top st in
  let t = Lexer.next f.lx in
  match t.kind with
  | Eof -> end_of_frame st f t
  | Directive d ->
      if st.defer && not (closes_branch f d) then begin st.cur <- t; st.have <- true; st.cur_elem <- None end
      else begin
        st.directive st d t.loc;
        if not st.have then fill st
      end
  | Ident s -> (
      match lookup st s with
      | Some (V.Macro m) when not st.no_expand ->
          st.invoke st m t.loc;
          if not st.have then fill st
      | Some (V.Array a) when Lexer.next_char f.lx = Some '[' ->
          (* an array element is resolved as it is read, so every context sees its value (§11.2) *)
          let i = st.index st a in
          st.cur <- t; st.have <- true; st.cur_elem <- Some (a, i)
      | _ -> st.cur <- t; st.have <- true; st.cur_elem <- None)
  | _ -> st.cur <- t; st.have <- true; st.cur_elem <- None

and end_of_frame st f t =
  (match f.conds with
  | [] -> ()
  | c :: _ ->
      let loc, what =
        match c with
        | If_branch l -> (l, "#if")
        | While_loop (_, l) -> (l, "#while")
        | For_loop { floc; _ } -> (floc, "#for")
        | Switch_case { sloc; _ } -> (sloc, "#switch")
      in
      Error.raise_at loc "%s has no matching #end before the end of the file" what);
  match f.kind with
  | Main -> st.cur <- t; st.have <- true; st.cur_elem <- None
  | Included (_, t0) ->
      st.opts.included (Lexer.file f.lx) ~depth:st.includes (Unix.gettimeofday () -. t0);
      st.frames <- List.tl st.frames;
      st.tables <- List.tl st.tables;
      st.includes <- st.includes - 1;
      fill st
  | Macro_body (name, _) -> Error.raise_at t.loc "the body of macro '%s' ends without #end" name

(* A directive read while looking past a complete value was kept for later (see [peek_follow]);
   it runs as soon as the parser asks for the next token. *)
let rec run_pending st =
  match st.cur.kind with
  | Directive d when st.have ->
      st.have <- false;
      st.directive st d st.cur.loc;
      if not st.have then fill st;
      run_pending st
  | _ -> ()

let peek st = if not st.have then fill st else run_pending st; st.cur.kind

(* The token after a complete value, read to see whether the value goes on ('+', '.x', another
   texture layer …). A directive found there is not run yet: it runs after the value has been
   used, so "#declare A = 1 #declare B = A;" and a #declare just before #end see the new A. *)
let peek_follow st =
  if not st.have then begin
    st.defer <- true;
    (try fill st with e -> st.defer <- false; raise e);
    st.defer <- false
  end;
  st.cur.kind

(* The value of the identifier [name] that is the current token (an array element if subscripted). *)
let cur_value st name =
  match st.cur_elem with
  | Some (a, i) -> (
      match a.cells.(i) with
      | Some v -> Some v
      | None -> Error.raise_at st.cur.loc "element %d of the array '%s' has not been assigned a value" i name)
  | None -> lookup st name
let peek_loc st = if not st.have then fill st else run_pending st; st.cur.loc

let advance st =
  if not st.have then fill st else run_pending st;
  (match st.cur.kind with LBrace -> st.depth <- st.depth + 1 | RBrace -> st.depth <- st.depth - 1 | _ -> ());
  if st.cur.kind != Eof then st.have <- false

let warn st loc fmt = Printf.ksprintf (fun msg -> st.warnings <- { Error.loc; msg; notes = [] } :: st.warnings) fmt

let not_supported loc what = raise (Unsupported (loc, what, []))

(* Using a declared value that needed an unsupported feature. *)
let unsupported_use loc name what at = raise (Unsupported (loc, Printf.sprintf "%s (used through '%s')" what name, [ (at, Printf.sprintf "'%s' was declared here" name) ]))

let all_names st = List.concat_map (fun t -> Names.fold (fun k _ acc -> k :: acc) t []) st.tables

let unknown_identifier st loc name =
  let candidates = all_names st @ keywords in
  match Suggest.nearest name candidates with
  | [] -> Error.raise_at loc "unknown identifier '%s'" name
  | s -> Error.raise_at loc "unknown identifier '%s'; did you mean %s?" name (String.concat " or " (List.map (Printf.sprintf "'%s'") s))

let unexpected st what =
  let k = peek st in
  match k with
  | Ident s when is_unsupported s -> not_supported (peek_loc st) (Printf.sprintf "'%s'" s)
  | Ident s when (not (is_keyword s)) && cur_value st s = None -> (
      let candidates = all_names st @ keywords in
      match Suggest.nearest s candidates with
      | [] -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k)
      | sug ->
          Error.raise_at (peek_loc st) "expected %s but found %s; did you mean %s?" what (describe k)
            (String.concat " or " (List.map (Printf.sprintf "'%s'") sug)))
  | Ident s -> (
      match cur_value st s with
      | Some (V.Unsupported u) -> unsupported_use (peek_loc st) s u.what u.at
      | Some v -> Error.raise_at (peek_loc st) "expected %s but found '%s', which is %s" what s (V.kind_name v)
      | None -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k))
  | _ -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k)

(* [k] is always a constant constructor here, so physical equality is the cheap, exact test *)
let expect st k what = if peek st == k then advance st else unexpected st what
let accept st k = if peek st == k then (advance st; true) else false
let is_ident st s = match peek st with Ident i -> String.equal i s | _ -> false

let accept_ident st s =
  if is_ident st s then (advance st; true) else false

let include_dirs st =
  let here = Filename.dirname (Lexer.file (top st).lx) in
  let main = Filename.dirname (Lexer.file (List.nth st.frames (List.length st.frames - 1)).lx) in
  let debian = "/usr/share/povray-3.7/include" in
  ignore here;
  (* the scene's directory (POV-Ray searches the working directory, usually the scene's), then +L *)
  let dirs = [ main; Filename.current_dir_name ] @ st.opts.library_paths @ (if Sys.file_exists debian then [ debian ] else []) in
  List.fold_left (fun acc d -> if List.mem d acc then acc else acc @ [ d ]) [] dirs

let find_file st name =
  let candidates =
    let join d n = if d = Filename.current_dir_name then n else Filename.concat d n in
    if Filename.is_relative name then List.concat_map (fun d -> [ join d name; join d (name ^ ".inc") ]) (include_dirs st)
    else [ name; name ^ ".inc" ]
  in
  List.find_opt (fun p -> Sys.file_exists p && not (Sys.is_directory p)) candidates

(* ---------------------------------------------------------------------------------------------- *)
(* Expressions (§11.2) *)

let component_index = function
  | "x" | "u" | "red" -> Some 0
  | "y" | "v" | "green" -> Some 1
  | "z" | "blue" -> Some 2
  | "t" | "filter" -> Some 3
  | "transmit" -> Some 4
  | _ -> None

let colour_keywords = [ "color"; "colour"; "rgb"; "rgbf"; "rgbt"; "rgbft"; "red"; "green"; "blue"; "filter"; "transmit" ]
let colour_set = set_of colour_keywords

let is_colour_start st =
  match peek st with
  | Ident s when Names.mem colour_set s -> true
  | Ident s -> ( match cur_value st s with Some (V.Colour _) -> true | _ -> false)
  | _ -> false

let function_names =
  [ "abs"; "sqrt"; "sin"; "cos"; "tan"; "asin"; "acos"; "atan"; "atan2"; "pow"; "exp"; "ln"; "log"; "min";
    "max"; "int"; "floor"; "ceil"; "mod"; "div"; "radians"; "degrees"; "vlength"; "vnormalize"; "vdot"; "vcross";
    "select"; "sinh"; "cosh"; "tanh"; "asinh"; "acosh"; "atanh"; "defined"; "dimensions"; "dimension_size";
    "seed"; "rand"; "bitwise_and"; "bitwise_or"; "bitwise_xor"; "vrotate"; "vaxis_rotate"; "str"; "vstr";
    "concat"; "substr"; "chr"; "asc"; "strlen"; "strupr"; "strlwr"; "val"; "strcmp"; "file_exists" ]

let unsupported_functions = [ "inside"; "trace"; "min_extent"; "max_extent"; "vturbulence"; "datetime"; "function" ]

let function_set = set_of function_names
let object_set = set_of [ "sphere"; "plane"; "object"; "triangle"; "smooth_triangle"; "mesh"; "mesh2"; "union" ]

let truth x = Float.abs x > 1e-10

(* C's (int) cast on x86: truncation, and -2147483648 for what does not fit (checked with POV-Ray). *)
let c_int x = if Float.is_nan x || Float.abs x >= 2147483648. then -2147483648. else Float.trunc x

let rec parse_expr st =
  (* additive level; relational and logical operators only inside parentheses *)
  expr_rest st (parse_term st)

and expr_rest st lhs =
  match peek_follow st with
  | Plus -> let loc = peek_loc st in advance st; expr_rest st (binop st loc ( +. ) lhs (parse_term st))
  | Minus -> let loc = peek_loc st in advance st; expr_rest st (binop st loc ( -. ) lhs (parse_term st))
  | _ -> lhs

and parse_term st = term_rest st (parse_unary st)

and term_rest st lhs =
  match peek_follow st with
  | Star -> let loc = peek_loc st in advance st; term_rest st (binop st loc ( *. ) lhs (parse_unary st))
  | Slash ->
      let loc = peek_loc st in
      advance st;
      let rhs = parse_unary st in
      (* dividing by exactly 0 gives +infinity, whatever the sign, with a warning (checked with POV-Ray) *)
      let divided = ref false in
      let div a b = if b = 0. then (divided := true; Float.infinity) else a /. b in
      let r = binop st loc div lhs rhs in
      if !divided then warn st loc "divide by zero; the result is infinity";
      term_rest st r
  | _ -> lhs

and binop st loc op a b =
  ignore st;
  match V.arith op a b with
  | Some v -> v
  | None -> Error.raise_at loc "cannot do arithmetic on %s and %s" (V.kind_name a) (V.kind_name b)

and parse_unary st =
  match peek st with
  | Minus -> let loc = peek_loc st in advance st; numeric_map loc (fun x -> -.x) (parse_unary st)
  | Plus -> advance st; parse_unary st
  | Bang -> let loc = peek_loc st in advance st; numeric_map loc (fun x -> if truth x then 0. else 1.) (parse_unary st)
  | _ -> parse_postfix st

and numeric_map loc f v =
  match V.map f v with Some v -> v | None -> Error.raise_at loc "expected a number but found %s" (V.kind_name v)

and parse_postfix st = postfix_rest st (parse_primary st)

(* Component selectors after a value: .x .y .z .t .u .v .red … .gray (§11.1). *)
and postfix_rest st v =
  if peek_follow st != Dot then v
  else begin
    let loc = peek_loc st in
    advance st;
    let c = match peek st with Ident c -> advance st; c | _ -> unexpected st "a component name after '.'" in
    let pick i =
      match v with
      | V.Vector a | V.Colour a ->
          if i < Array.length a then V.Float a.(i)
          else Error.raise_at loc "'.%s' needs a vector of at least %d terms, this one has %d" c (i + 1) (Array.length a)
      | V.Float _ -> Error.raise_at loc "'.%s' cannot select from a float" c
      | _ -> Error.raise_at loc "'.%s' cannot select from %s" c (V.kind_name v)
    in
    let r =
      match c with
      | "gray" | "grey" -> (
          match v with
          | V.Vector a | V.Colour a when Array.length a >= 3 -> V.Float ((0.297 *. a.(0)) +. (0.589 *. a.(1)) +. (0.114 *. a.(2)))
          | _ -> Error.raise_at loc "'.%s' needs a colour" c)
      | _ -> ( match component_index c with Some i -> pick i | None -> Error.raise_at loc "unknown component '.%s'" c)
    in
    postfix_rest st r
  end

and parse_full st =
  (* inside parentheses: ?:, & |, relational (§11.2) *)
  let c = parse_logical st in
  if peek_follow st == Quest then begin
    let loc = peek_loc st in
    advance st;
    let a = parse_full st in
    expect st Colon "':' of a '?:' expression";
    let b = parse_full st in
    match c with
    | V.Float x -> if truth x then a else b
    | v -> Error.raise_at loc "the condition of '?:' must be a float, not %s" (V.kind_name v)
  end
  else c

and parse_logical st =
  let lhs = parse_relational st in
  let rec loop lhs =
    match peek_follow st with
    | Amp -> let loc = peek_loc st in advance st; let r = parse_relational st in loop (logic loc (fun a b -> truth a && truth b) lhs r)
    | Bar -> let loc = peek_loc st in advance st; let r = parse_relational st in loop (logic loc (fun a b -> truth a || truth b) lhs r)
    | _ -> lhs
  in
  loop lhs

and logic loc f a b =
  match (a, b) with
  | V.Float x, V.Float y -> V.Float (if f x y then 1. else 0.)
  | _ -> Error.raise_at loc "logical and relational operators need floats, not %s and %s" (V.kind_name a) (V.kind_name b)

and parse_relational st =
  (* comparisons chain left to right: (1 < 2 < 3) is ((1 < 2) < 3) *)
  let eps = 1e-10 in
  let rec loop lhs =
    let rel f =
      let loc = peek_loc st in
      advance st;
      let rhs = parse_expr st in
      match (lhs, rhs) with
      | V.String a, V.String b ->
          (* strings compare as strcmp does, against 0 *)
          loop (V.Float (if f (float_of_int (Strfmt.compare a b)) 0. then 1. else 0.))
      | _ -> loop (logic loc f lhs rhs)
    in
    match peek_follow st with
    | Lt -> rel (fun a b -> a < b)
    | Le -> rel (fun a b -> a < b || Float.abs (a -. b) < eps)
    | Gt -> rel (fun a b -> a > b)
    | Ge -> rel (fun a b -> a > b || Float.abs (a -. b) < eps)
    | Eq -> rel (fun a b -> Float.abs (a -. b) < eps)
    | Ne -> rel (fun a b -> Float.abs (a -. b) >= eps)
    | _ -> lhs
  in
  loop (parse_expr st)

and parse_primary st =
  let loc = peek_loc st in
  match peek st with
  | Num f -> advance st; V.Float f
  | LParen ->
      advance st;
      let v = parse_full st in
      expect st RParen "')'";
      v
  | Lt ->
      advance st;
      let first = parse_float st in
      let rec terms acc n =
        if accept st Comma then begin
          if n >= 5 then Error.raise_at (peek_loc st) "a vector has at most 5 terms";
          terms (parse_float st :: acc) (n + 1)
        end
        else acc
      in
      let ts = List.rev (terms [ first ] 1) in
      if List.length ts < 2 then Error.raise_at loc "a vector needs at least 2 terms";
      expect st Gt "',' or '>' in a vector";
      V.Vector (Array.of_list ts)
  | Str s -> advance st; V.String s
  | Ident name -> parse_ident_value st loc name
  | k -> ignore k; unexpected st "a numeric expression"

and parse_ident_value st loc name =
  match name with
  | "x" -> advance st; V.Vector [| 1.; 0.; 0. |]
  | "y" -> advance st; V.Vector [| 0.; 1.; 0. |]
  | "z" -> advance st; V.Vector [| 0.; 0.; 1. |]
  | "t" -> advance st; V.Vector [| 0.; 0.; 0.; 1. |]
  | "u" -> advance st; V.Vector [| 1.; 0. |]
  | "v" -> advance st; V.Vector [| 0.; 1. |]
  | "pi" -> advance st; V.Float Float.pi
  | "true" | "yes" | "on" -> advance st; V.Float 1.
  | "false" | "no" | "off" -> advance st; V.Float 0.
  | "image_width" -> advance st; V.Float (float_of_int st.opts.width)
  | "image_height" -> advance st; V.Float (float_of_int st.opts.height)
  | "clock" -> advance st; V.Float st.opts.clock
  | "clock_delta" -> advance st; V.Float 0.
  | "clock_on" | "frame_number" | "initial_clock" | "final_clock" | "initial_frame" | "final_frame" ->
      advance st;
      (* a single still image: frame 0 of no animation, clock from +K *)
      V.Float (match name with "initial_clock" | "final_clock" -> st.opts.clock | _ -> 0.)
  | "version" -> advance st; V.Float (float_of_int st.version /. 100.)
  | "now" ->
      advance st;
      (* days since 2000-01-01 00:00 UTC *)
      V.Float ((Unix.gettimeofday () -. 946684800.) /. 86400.)
  | "input_file_name" -> advance st; V.String (Lexer.file (List.nth st.frames (List.length st.frames - 1)).lx)
  | _ when Names.mem colour_set name -> V.Colour (colour_array (parse_colour st))
  | _ when Names.mem function_set name -> parse_function st loc name
  | _ -> (
      match cur_value st name with
      | Some ((V.Float _ | V.Vector _ | V.Colour _ | V.String _) as v) -> advance st; v
      | Some (V.Unsupported u) -> unsupported_use loc name u.what u.at
      | Some v -> Error.raise_at loc "expected a numeric expression but '%s' is %s" name (V.kind_name v)
      | None ->
          if is_unsupported name then not_supported loc (Printf.sprintf "'%s'" name)
          else if List.mem name unsupported_functions then not_supported loc (Printf.sprintf "the function '%s'" name)
          else if is_keyword name then Error.raise_at loc "expected a numeric expression but found '%s'" name
          else unknown_identifier st loc name)

(* The argument of defined(…) and #ifdef: an identifier (or array element) that is not evaluated. *)
and parse_defined_arg st =
  st.no_expand <- true;
  let k = Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st) in
  match k with
  | Ident s ->
      let d =
        match st.cur_elem with
        | Some (a, i) -> a.cells.(i) <> None
        | None -> lookup st s <> None || List.mem s [ "x"; "y"; "z"; "t"; "u"; "v"; "pi"; "clock"; "version" ]
      in
      advance st;
      d
  | _ -> unexpected st "an identifier"

and parse_function st loc name =
  advance st;
  expect st LParen (Printf.sprintf "'(' after '%s'" name);
  if name = "defined" then begin
    let d = parse_defined_arg st in
    expect st RParen "')' closing 'defined'";
    V.Float (if d then 1. else 0.)
  end
  else
  let rec args acc =
    let a = (peek_loc st, parse_full st) in
    if accept st Comma then args (a :: acc) else List.rev (a :: acc)
  in
  let args = if name = "dimensions" || name = "dimension_size" then array_args st else args [] in
  expect st RParen (Printf.sprintf "')' closing the arguments of '%s'" name);
  let float_arg (l, v) = match v with V.Float f -> f | v -> Error.raise_at l "'%s' expects a float argument, not %s" name (V.kind_name v) in
  let string_arg (l, v) = match v with V.String s -> s | v -> Error.raise_at l "'%s' expects a string argument, not %s" name (V.kind_name v) in
  let vec_arg (l, v) =
    match v with
    | V.Float _ | V.Vector _ | V.Colour _ -> let a = V.promote v 3 in Vec.make a.(0) a.(1) a.(2)
    | v -> Error.raise_at l "'%s' expects a vector argument, not %s" name (V.kind_name v)
  in
  let n = List.length args in
  let arity k = if n <> k then Error.raise_at loc "'%s' takes %d argument%s, not %d" name k (if k = 1 then "" else "s") n in
  let arg i = List.nth args i in
  let f1 f = arity 1; V.Float (f (float_arg (arg 0))) in
  let f2 f = arity 2; V.Float (f (float_arg (arg 0)) (float_arg (arg 1))) in
  let of_vec (v : Vec.t) = V.Vector [| v.x; v.y; v.z |] in
  let int_arg a = int_of_float (c_int (float_arg a)) in
  match name with
  | "abs" -> f1 Float.abs
  | "sqrt" -> f1 (fun x -> if x < 0. then Error.raise_at loc "sqrt of negative number %f" x else sqrt x)
  | "sin" -> f1 sin
  | "cos" -> f1 cos
  | "tan" -> f1 tan
  | "sinh" -> f1 sinh
  | "cosh" -> f1 cosh
  | "tanh" -> f1 tanh
  | "asinh" -> f1 (fun x -> Float.log (x +. sqrt ((x *. x) +. 1.)))
  | "acosh" -> f1 (fun x -> Float.log (x +. sqrt ((x *. x) -. 1.)))
  | "atanh" -> f1 (fun x -> 0.5 *. Float.log ((1. +. x) /. (1. -. x)))
  | "asin" | "acos" ->
      (* §11.2: the argument is clamped to ±1 with a warning *)
      let f = if name = "asin" then asin else acos in
      f1 (fun x ->
          if x < -1. || x > 1. then warn st loc "domain error in '%s': %g is clamped to the range -1 … 1" name x;
          f (Float.max (-1.) (Float.min 1. x)))
  | "atan" -> f1 atan
  | "atan2" -> f2 (fun a b -> if Float.abs a < 1e-10 && Float.abs b < 1e-10 then Error.raise_at loc "domain error in atan2(0, 0)" else Float.atan2 a b)
  | "pow" ->
      f2 (fun a b -> if a = 0. && b = 0. then Error.raise_at loc "pow(0, 0) is undefined" else Float.pow a b)
  | "exp" -> f1 exp
  | "ln" -> f1 (fun x -> if x <= 0. then Error.raise_at loc "ln of a number that is not positive: %f" x else log x)
  | "log" -> f1 (fun x -> if x <= 0. then Error.raise_at loc "log of a number that is not positive: %f" x else log10 x)
  | "int" -> f1 c_int
  | "floor" -> f1 floor
  | "ceil" -> f1 ceil
  | "mod" -> f2 Float.rem (* C fmod: mod(x, 0) is NaN *)
  | "div" -> f2 (fun a b -> c_int (a /. b))
  | "radians" -> f1 (fun d -> d *. Float.pi /. 180.)
  | "degrees" -> f1 (fun r -> r *. 180. /. Float.pi)
  | "min" | "max" ->
      if args = [] then Error.raise_at loc "'%s' needs at least one argument" name;
      let fs = List.map float_arg args in
      V.Float (List.fold_left (if name = "min" then Float.min else Float.max) (List.hd fs) fs)
  | "bitwise_and" | "bitwise_or" | "bitwise_xor" ->
      if n < 2 then Error.raise_at loc "'%s' needs at least two arguments" name;
      let op = match name with "bitwise_and" -> ( land ) | "bitwise_or" -> ( lor ) | _ -> ( lxor ) in
      let is = List.map int_arg args in
      V.Float (float_of_int (List.fold_left op (List.hd is) (List.tl is)))
  | "seed" ->
      (* §11.2: each seed() makes a new stream and returns its number *)
      arity 1;
      st.streams <- Array.append st.streams [| { V.state = int_arg (arg 0) land 0xFFFFFFFF } |];
      V.Float (float_of_int (Array.length st.streams - 1))
  | "rand" ->
      arity 1;
      let l, _ = arg 0 in
      let i = int_arg (arg 0) in
      if i < 0 || i >= Array.length st.streams then Error.raise_at l "rand(%d): there is no such random stream (make one with seed())" i;
      let r = st.streams.(i) in
      (* a 32-bit linear congruential step *)
      r.state <- ((r.state * 1812433253) + 12345) land 0xFFFFFFFF;
      V.Float (float_of_int r.state /. 4294967295.)
  | "vlength" -> arity 1; V.Float (Vec.length (vec_arg (arg 0)))
  | "vnormalize" ->
      arity 1;
      let a = vec_arg (arg 0) in
      if Vec.length a = 0. then begin
        warn st loc "normalizing zero-length vector; the result is <0,0,0>";
        of_vec Vec.zero
      end
      else of_vec (Vec.normalize a)
  | "vdot" -> arity 2; V.Float (Vec.dot (vec_arg (arg 0)) (vec_arg (arg 1)))
  | "vcross" -> arity 2; of_vec (Vec.cross (vec_arg (arg 0)) (vec_arg (arg 1)))
  | "vrotate" -> arity 2; of_vec (Transform.point (Transform.rotate (vec_arg (arg 1))) (vec_arg (arg 0)))
  | "vaxis_rotate" ->
      arity 3;
      of_vec (Transform.point (Transform.axis_rotate (vec_arg (arg 1)) (float_arg (arg 2))) (vec_arg (arg 0)))
  | "select" ->
      if n <> 3 && n <> 4 then Error.raise_at loc "'select' takes 3 or 4 arguments";
      let c = float_arg (arg 0) in
      let pick i = snd (arg i) in
      if n = 3 then if c < 0. then pick 1 else pick 2
      else if c < 0. then pick 1
      else if c = 0. then pick 2
      else pick 3
  | "dimensions" -> (
      match args with
      | [ (_, V.Array a) ] -> V.Float (float_of_int (Array.length a.dims))
      | _ -> Error.raise_at loc "'dimensions' takes one array")
  | "dimension_size" -> (
      match args with
      | [ (_, V.Array a); d ] ->
          let d = int_arg d in
          if d < 1 || d > Array.length a.dims then Error.raise_at loc "dimension %d is out of range: the array has %d" d (Array.length a.dims);
          V.Float (float_of_int a.dims.(d - 1))
      | _ -> Error.raise_at loc "'dimension_size' takes an array and a dimension number")
  | "str" -> arity 3; V.String (Strfmt.str (float_arg (arg 0)) (int_arg (arg 1)) (int_arg (arg 2)))
  | "vstr" ->
      arity 5;
      let k = int_arg (arg 0) in
      let k = max 2 (min 5 k) in
      (* the value is not promoted: a float is its first term, the others are 0 *)
      let terms =
        match arg 1 with
        | _, V.Float f -> Array.init k (fun i -> if i = 0 then f else 0.)
        | _, (V.Vector a | V.Colour a) -> Array.init k (fun i -> if i < Array.length a then a.(i) else 0.)
        | l, v -> Error.raise_at l "'vstr' expects a vector, not %s" (V.kind_name v)
      in
      V.String (Strfmt.vstr terms (string_arg (arg 2)) (int_arg (arg 3)) (int_arg (arg 4)))
  | "concat" -> V.String (String.concat "" (List.map string_arg args))
  | "substr" ->
      arity 3;
      let s = string_arg (arg 0) and p = int_arg (arg 1) and l = int_arg (arg 2) in
      if p < 1 || l < 0 || p + l - 1 > String.length s then
        Error.raise_at loc "substr(\"%s\", %d, %d) is outside the string (length %d)" s p l (String.length s);
      V.String (String.sub s (p - 1) l)
  | "chr" ->
      arity 1;
      let c = int_arg (arg 0) in
      if c < 0 || c > 65535 then Error.raise_at loc "chr(%d): the value must be 0 … 65535" c;
      let b = Buffer.create 4 in
      Buffer.add_utf_8_uchar b (if Uchar.is_valid c then Uchar.of_int c else Uchar.rep);
      V.String (Buffer.contents b)
  | "asc" -> arity 1; let s = string_arg (arg 0) in V.Float (if s = "" then 0. else float_of_int (Char.code s.[0]))
  | "strlen" -> arity 1; V.Float (float_of_int (String.length (string_arg (arg 0))))
  | "strupr" -> arity 1; V.String (String.uppercase_ascii (string_arg (arg 0)))
  | "strlwr" -> arity 1; V.String (String.lowercase_ascii (string_arg (arg 0)))
  | "val" -> arity 1; V.Float (Strfmt.value (string_arg (arg 0)))
  | "strcmp" -> arity 2; V.Float (float_of_int (Strfmt.compare (string_arg (arg 0)) (string_arg (arg 1))))
  | "file_exists" -> arity 1; V.Float (if find_file st (string_arg (arg 0)) <> None then 1. else 0.)
  | _ -> Error.raise_at loc "unknown function '%s'" name

(* The arguments of dimensions() and dimension_size(): an array identifier, then floats. *)
and array_args st =
  let l = peek_loc st in
  let a =
    match peek st with
    | Ident s -> (
        match cur_value st s with
        | Some (V.Array _ as a) -> advance st; a
        | Some v -> Error.raise_at l "'%s' is %s, not an array" s (V.kind_name v)
        | None -> unknown_identifier st l s)
    | _ -> unexpected st "an array identifier"
  in
  let rec more acc = if accept st Comma then more ((peek_loc st, parse_full st) :: acc) else List.rev acc in
  (l, a) :: more []

and parse_float st =
  (* A plain number that ends a list item or a vector needs no expression machinery: the fast path
     for the millions of numbers of a mesh. Otherwise the number is the first operand. *)
  let loc = peek_loc st in
  let as_float v = match v with V.Float f -> f | v -> Error.raise_at loc "expected a float but found %s" (V.kind_name v) in
  let continue v = as_float (expr_rest st (term_rest st (postfix_rest st v))) in
  match peek st with
  | Num f -> (
      advance st;
      match peek_follow st with
      | Comma | Gt | RBrace | Semi | RParen -> f
      | _ -> continue (V.Float f))
  | Minus -> (
      advance st;
      match peek st with
      | Num f -> (
          advance st;
          match peek_follow st with
          | Comma | Gt | RBrace | Semi | RParen -> -.f
          | Dot -> as_float (expr_rest st (term_rest st (numeric_map loc (fun x -> -.x) (postfix_rest st (V.Float f)))))
          | _ -> as_float (expr_rest st (term_rest st (V.Float (-.f)))))
      | _ -> as_float (expr_rest st (term_rest st (numeric_map loc (fun x -> -.x) (parse_unary st)))))
  | _ -> as_float (parse_expr st)

and parse_vector st =
  let loc = peek_loc st in
  match parse_expr st with
  | V.Vector [| x; y; z |] -> Vec.make x y z
  | (V.Float _ | V.Vector _) as v -> let a = V.promote v 3 in Vec.make a.(0) a.(1) a.(2)
  | V.Colour a -> Vec.make a.(0) a.(1) a.(2)
  | v -> Error.raise_at loc "expected a vector but found %s" (V.kind_name v)

(* Colours (§11.2): [color]/[colour] optional, then rgb… forms or an expression, then component
   keywords that overwrite single channels. *)
and parse_colour st : Colour.t =
  let c = Array.make 5 0. in
  let set_terms loc n v =
    match v with
    | V.Float _ | V.Vector _ | V.Colour _ ->
        let a = V.promote v n in
        Array.fill c 0 5 0.;
        Array.blit a 0 c 0 (if n = 5 then 5 else 3);
        a
    | v -> Error.raise_at loc "expected a colour but found %s" (V.kind_name v)
  in
  let keyword_seen = ref false in
  let rec loop () =
    let loc = peek_loc st in
    match peek st with
    | Ident ("color" | "colour") -> advance st; keyword_seen := true; loop ()
    | Ident "rgb" -> advance st; keyword_seen := true; ignore (set_terms loc 3 (parse_expr st)); loop ()
    | Ident "rgbf" ->
        advance st; keyword_seen := true;
        let a = set_terms loc 4 (parse_expr st) in
        c.(3) <- a.(3); loop ()
    | Ident "rgbt" ->
        advance st; keyword_seen := true;
        let a = set_terms loc 4 (parse_expr st) in
        c.(3) <- 0.; c.(4) <- a.(3); loop ()
    | Ident "rgbft" -> advance st; keyword_seen := true; ignore (set_terms loc 5 (parse_expr st)); loop ()
    | Ident (("red" | "green" | "blue" | "filter" | "transmit") as k) ->
        advance st; keyword_seen := true;
        let i = match component_index k with Some i -> i | None -> assert false in
        c.(i) <- parse_float st;
        loop ()
    | Ident ("srgb" | "srgbf" | "srgbt" | "srgbft" as k) -> not_supported loc (Printf.sprintf "'%s'" k)
    | _ -> ()
  in
  (* A leading colour identifier or plain expression sets all five terms: a float is replicated
     into filter and transmit too ([color 0.5] is rgbft 0.5). *)
  (match peek st with
  | Ident ("color" | "colour") ->
      advance st;
      keyword_seen := true;
      (match peek st with
      | Ident s when Names.mem colour_set s -> ()
      | _ -> let loc = peek_loc st in ignore (set_terms loc 5 (parse_expr st)))
  | Ident s when not (Names.mem colour_set s) -> (
      match cur_value st s with
      | Some (V.Colour _) -> let loc = peek_loc st in ignore (set_terms loc 5 (parse_expr st)); keyword_seen := true
      | _ -> ())
  | _ -> ());
  loop ();
  if not !keyword_seen then unexpected st "a colour";
  Colour.of_array c

and colour_array (c : Colour.t) = [| c.red; c.green; c.blue; c.filter; c.transmit |]

(* A colour where only red, green and blue count (light colours, ambient, …): a bare float is
   accepted and means grey. *)
let parse_rgb st what =
  let loc = peek_loc st in
  if is_colour_start st then begin
    (* filter and transmit are dropped silently, as POV-Ray does for light colours *)
    Colour.rgb (parse_colour st)
  end
  else
    match parse_expr st with
    | V.Float f -> Rgb.grey f
    | (V.Vector _ | V.Colour _) as v -> let a = V.promote v 3 in Rgb.make a.(0) a.(1) a.(2)
    | v -> Error.raise_at loc "expected a colour for %s but found %s" what (V.kind_name v)

(* Does the next token start a float expression (for optional values such as [metallic [M]])? *)
let float_follows st =
  match peek st with
  | Num _ | LParen | Minus | Plus -> true
  | Ident s -> ( match cur_value st s with Some (V.Float _) -> true | _ -> Names.mem function_set s || List.mem s [ "pi"; "true"; "false"; "yes"; "no"; "on"; "off"; "clock"; "version"; "image_width"; "image_height" ])
  | _ -> false

let parse_bool_opt st = if float_follows st then truth (parse_float st) else true

(* ---------------------------------------------------------------------------------------------- *)
(* Textures *)

let open_block st what = expect st LBrace (Printf.sprintf "'{' after '%s'" what)

let close_block st what = expect st RBrace (Printf.sprintf "'}' closing '%s' or one of its keywords" what)

let ident_of_kind st f =
  match peek st with
  | Ident s -> ( match cur_value st s with Some v -> (match f v with Some r -> advance st; Some r | None -> None) | None -> None)
  | _ -> None

let parse_pigment st (base : Scene.pigment) : Scene.pigment =
  open_block st "pigment";
  let p =
    match ident_of_kind st (function V.Pigment p -> Some p | _ -> None) with
    | Some p -> p
    | None -> base
  in
  let rec loop p =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; p
    | Ident s when is_colour_start st -> ignore s; loop (Scene.Solid (parse_colour st))
    | Ident "translate" -> advance st; ignore (parse_vector st); loop p (* a plain colour is the same everywhere *)
    | Ident ("quick_color" | "quick_colour") -> advance st; ignore (parse_colour st); loop p
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a pigment" s)
    | _ -> unexpected st "a colour or '}' in a pigment"
  in
  loop p

let parse_reflection_block st (r : Scene.reflection) : Scene.reflection =
  (* reflection { MIN [, MAX] [fresnel [b]] [falloff F] [exponent E] [metallic [M]] } (§5.1) *)
  open_block st "reflection";
  let r, one_colour =
    if peek st == RBrace then (r, false)
    else
      let mn = parse_rgb st "reflection" in
      if accept st Comma then ({ r with rmin = mn; rmax = parse_rgb st "reflection" }, false)
      else ({ r with rmin = mn; rmax = mn }, true)
  in
  let rec loop (r : Scene.reflection) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; r
    | Ident "fresnel" -> advance st; loop { r with fresnel = parse_bool_opt st }
    | Ident "falloff" -> advance st; loop { r with falloff = parse_float st }
    | Ident "exponent" -> advance st; loop { r with exponent = parse_float st }
    | Ident "metallic" -> advance st; loop { r with refl_metallic = (if float_follows st then parse_float st else 1.) }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in reflection" s)
    | _ -> unexpected st "'fresnel', 'falloff', 'exponent', 'metallic' or '}' in reflection"
  in
  let r = loop r in
  (* §5.1: with fresnel and a single colour, that colour is the maximum and the minimum is 0 *)
  if r.fresnel && one_colour then { r with rmin = Rgb.black } else r

let parse_finish st (base : Scene.finish) : Scene.finish =
  open_block st "finish";
  let f = match ident_of_kind st (function V.Finish f -> Some f | _ -> None) with Some f -> f | None -> base in
  let diffuse_albedo = ref false and phong_albedo = ref false and specular_albedo = ref false in
  let rec loop (f : Scene.finish) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; f
    | Ident "ambient" -> advance st; loop { f with ambient = parse_rgb st "ambient" }
    | Ident "emission" -> advance st; loop { f with emission = parse_rgb st "emission" }
    | Ident "diffuse" ->
        advance st;
        diffuse_albedo := accept_ident st "albedo";
        let d = parse_float st in
        if accept st Comma then begin
          let l = peek_loc st in
          let back = parse_float st in
          if back <> 0. then not_supported l "a back-side diffuse value"
        end;
        loop { f with diffuse = d }
    | Ident "brilliance" -> advance st; loop { f with brilliance = parse_float st }
    | Ident "phong" -> advance st; phong_albedo := accept_ident st "albedo"; loop { f with phong = parse_float st }
    | Ident "phong_size" -> advance st; loop { f with phong_size = parse_float st }
    | Ident "specular" -> advance st; specular_albedo := accept_ident st "albedo"; loop { f with specular = parse_float st }
    | Ident "roughness" ->
        advance st;
        let r = parse_float st in
        if r = 0. then warn st loc "zero roughness used";
        loop { f with roughness = r }
    | Ident "metallic" -> advance st; loop { f with metallic = (if float_follows st then parse_float st else 1.) }
    | Ident "reflection" ->
        advance st;
        if peek st == LBrace then loop { f with reflection = parse_reflection_block st f.reflection }
        else
          (* old syntax: min = max = value, falloff 1, type 0 (§5.1) *)
          let c = parse_rgb st "reflection" in
          loop { f with reflection = { f.reflection with rmin = c; rmax = c; falloff = 1.; fresnel = false } }
    | Ident "reflection_exponent" -> advance st; loop { f with reflection = { f.reflection with exponent = parse_float st } }
    | Ident "conserve_energy" -> advance st; loop { f with conserve_energy = parse_bool_opt st }
    | Ident "refraction" ->
        advance st;
        warn st loc "refraction value unnecessary to turn on refraction; to attenuate, the fade_power and fade_distance keywords should be specified in 'interior{...}'";
        loop { f with refraction = parse_float st }
    | Ident "ior" ->
        advance st;
        warn st loc "index of refraction value should be specified in 'interior{...}' statement";
        loop { f with legacy_ior = Some (parse_float st) }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a finish" s)
    | _ -> unexpected st "a finish keyword or '}'"
  in
  let f = loop f in
  (* albedo forms are converted with the final values (§10.1) *)
  let f = if !diffuse_albedo then { f with diffuse = f.diffuse *. (f.brilliance +. 1.) /. 2. } else f in
  let f = if !phong_albedo then { f with phong = f.phong *. (f.phong_size +. 1.) /. 2. } else f in
  let f =
    if !specular_albedo then
      let e = 1. /. f.roughness in
      { f with specular = f.specular *. (e +. 2.) /. (4. *. (2. -. Float.pow 2. (-.e /. 2.))) }
    else f
  in
  f

let parse_texture st (base : Scene.texture) : Scene.texture =
  open_block st "texture";
  let t = match ident_of_kind st (function V.Texture t -> Some t | _ -> None) with Some t -> t | None -> base in
  let rec loop (t : Scene.texture) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; t
    | Ident "pigment" -> advance st; loop { t with pigment = parse_pigment st t.pigment }
    | Ident "finish" -> advance st; loop { t with finish = parse_finish st t.finish }
    | Ident "translate" -> advance st; ignore (parse_vector st); loop t
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a texture" s)
    | _ -> unexpected st "'pigment', 'finish' or '}' in a texture"
  in
  loop t

let parse_interior st (base : Scene.interior) : Scene.interior =
  open_block st "interior";
  let i = match ident_of_kind st (function V.Interior i -> Some i | _ -> None) with Some i -> i | None -> base in
  let rec loop (i : Scene.interior) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; i
    | Ident "ior" -> advance st; loop { i with ior = parse_float st }
    | Ident "fade_distance" -> advance st; loop { i with fade_distance = parse_float st }
    | Ident "fade_power" -> advance st; loop { i with fade_power = parse_float st }
    | Ident ("fade_color" | "fade_colour") -> advance st; loop { i with fade_colour = parse_rgb st "fade_color" }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in an interior" s)
    | _ -> unexpected st "'ior', 'fade_distance', 'fade_power', 'fade_color' or '}' in an interior"
  in
  loop i

(* ---------------------------------------------------------------------------------------------- *)
(* Objects *)


(* A scale vector: a zero component is replaced by 1 with POV-Ray's warning (§14.2). *)
let scale_vector st loc (v : Vec.t) =
  let fix axis c = if c = 0. then (warn st loc "illegal value: scale %s by 0.0; changed to 1.0" axis; 1.) else c in
  Vec.make (fix "x" v.x) (fix "y" v.y) (fix "z" v.z)

(* translate / rotate / scale / matrix / transform, as one modifier (§14.2, §14.3). *)
let rec parse_op st : Place.op =
  let loc = peek_loc st in
  match peek st with
  | Ident "translate" -> advance st; Translate (parse_vector st)
  | Ident "rotate" -> advance st; Rotate (parse_vector st)
  | Ident "scale" -> advance st; let l = peek_loc st in Scale (scale_vector st l (parse_vector st))
  | Ident "matrix" -> advance st; Transform (parse_matrix st)
  | Ident "transform" -> advance st; Transform (parse_transform st)
  | _ -> ignore loc; unexpected st "a transformation"

and parse_matrix st =
  let loc = peek_loc st in
  expect st Lt "'<' starting the 12 numbers of a matrix";
  let a = Array.make 12 0. in
  for k = 0 to 11 do
    if k > 0 then expect st Comma (Printf.sprintf "',' after number %d of the matrix (it has 12)" k);
    a.(k) <- parse_float st
  done;
  expect st Gt "'>' after the 12 numbers of a matrix";
  match Transform.matrix a with
  | Ok (t, warnings) -> List.iter (fun w -> warn st loc "%s" w) warnings; t
  | Error msg -> Error.raise_at loc "%s" msg

(* transform { items [inverse] } or transform Id: the block starts from the identity and composes
   its items in order; inverse inverts the whole block wherever it stands (§14.3). *)
and parse_transform st =
  let ident () =
    match peek st with
    | Ident s -> (
        match cur_value st s with
        | Some (V.Transform t) -> advance st; Some t
        | Some (V.Unsupported u) -> unsupported_use (peek_loc st) s u.what u.at
        | _ -> None)
    | _ -> None
  in
  match ident () with
  | Some t -> t
  | None ->
      open_block st "transform";
      let rec loop t inv =
        match peek st with
        | RBrace -> advance st; if inv then Transform.inverse t else t
        | Ident "inverse" -> advance st; loop t true
        | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
            loop (Transform.compose t (Place.op_transform (parse_op st))) inv
        | _ -> (
            match ident () with
            | Some t' -> loop (Transform.compose t t') inv
            | None -> unexpected st "a transformation, 'inverse' or '}' in a transform block")
      in
      loop Transform.identity false

let move_shape op s = Place.shape s op

(* §14.8: a light's position moves as a point *)
let move_light op (l : Scene.light) = { l with position = Transform.point (Place.op_transform op) l.position }

let rec move_obj op (o : V.obj) =
  match o.shape with
  | Prim s -> { o with shape = Prim (move_shape op s) }
  | Union ms -> { o with shape = Union (List.map (move_member op) ms) }

and move_member op = function
  | V.Member_obj o -> V.Member_obj (move_obj op o)
  | V.Member_light l -> V.Member_light (move_light op l)

let parse_object_mods st (o : V.obj) what : V.obj =
  let tex o = match o.V.texture with Some t -> t | None -> st.default_texture in
  let rec loop (o : V.obj) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; o
    | Ident "pigment" -> advance st; let t = tex o in loop { o with texture = Some { t with pigment = parse_pigment st t.pigment } }
    | Ident "finish" -> advance st; let t = tex o in loop { o with texture = Some { t with finish = parse_finish st t.finish } }
    | Ident "texture" ->
        advance st;
        if o.texture <> None then not_supported loc "layered textures (a texture added to an object that has one)";
        loop { o with texture = Some (parse_texture st st.default_texture) }
    | Ident "interior" ->
        advance st;
        let base = match o.interior with Some i -> i | None -> Defaults.interior in
        loop { o with interior = Some (parse_interior st base) }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") -> loop (move_obj (parse_op st) o)
    | Ident "no_shadow" -> advance st; loop { o with no_shadow = true }
    | Ident "hollow" -> advance st; ignore (parse_bool_opt st); loop o
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s'" s)
    | _ -> unexpected st (Printf.sprintf "an object modifier or '}' closing '%s'" what)
  in
  loop o

let new_obj_of shape loc = { V.shape; texture = None; interior = None; no_shadow = false; oloc = loc }
let new_obj shape loc = new_obj_of (V.Prim shape) loc


(* Objects povml does not render yet: inside a union they are reported as "not supported yet". *)
let unsupported_objects =
  [ "box"; "cylinder"; "cone"; "disc"; "torus"; "polygon"; "prism"; "lathe"; "sor"; "blob"; "text"; "height_field";
    "isosurface"; "superellipsoid"; "julia_fractal"; "parametric"; "bicubic_patch"; "ovus"; "quadric"; "cubic";
    "quartic"; "poly"; "intersection"; "difference"; "merge"; "sphere_sweep"; "lemon" ]

let parse_light st =
  let loc = peek_loc st in
  advance st;
  open_block st "light_source";
  let position = parse_vector st in
  ignore (accept st Comma);
  (* §10.2: the colour after the position; without one the light is black *)
  let colour = if peek st == RBrace || (match peek st with Ident s -> List.mem s [ "shadowless"; "fade_distance"; "fade_power"; "translate" ] | _ -> false) then Rgb.black else parse_rgb st "a light colour" in
  ignore loc;
  let rec loop (l : Scene.light) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; l
    | Ident "shadowless" -> advance st; loop { l with shadowless = true }
    | Ident "fade_distance" -> advance st; loop { l with fade_distance = parse_float st }
    | Ident "fade_power" -> advance st; loop { l with fade_power = parse_float st }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") -> loop (move_light (parse_op st) l)
    | Ident ("color" | "colour" | "rgb") -> loop { l with colour = parse_rgb st "a light colour" }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a light_source" s)
    | _ -> unexpected st "a light_source keyword or '}'"
  in
  loop { Scene.position; colour; shadowless = false; fade_distance = 0.; fade_power = 0. }

let f32 x = Int32.float_of_bits (Int32.bits_of_float x)

(* Vertex normals: normalised; a zero normal becomes <1,0,0> with a warning (§2.6). *)
let unit_normal st loc (n : Vec.t) =
  if Vec.length n = 0. then begin
    warn st loc "zero-length normal replaced by <1,0,0>";
    Vec.make 1. 0. 0.
  end
  else Vec.normalize n

let comma st = ignore (accept st Comma)

(* A vector written as plain numbers, read without tokens (Lexer.scan_vector3) into [out]: true
   when that worked, and the parser then stands after the '>'. *)
let fast_vector3 st out =
  (* the '<' was read from the current frame, so the numbers are in the same text *)
  peek st == Lt && Lexer.scan_vector3 (top st).lx out && begin st.have <- false; true end

(* A vector of a mesh: by the fast path when it is written as plain numbers. *)
let mesh_vector st =
  let buf = [| 0.; 0.; 0. |] in
  if fast_vector3 st buf then Vec.make buf.(0) buf.(1) buf.(2) else parse_vector st

(* triangle { P1, P2, P3 } and smooth_triangle { P1, N1, P2, N2, P3, N3 } (§2.4, §2.5). *)
let parse_triangle_corners st ~smooth =
  let p1 = mesh_vector st in
  comma st;
  if smooth then begin
    let l1 = peek_loc st in
    let n1 = mesh_vector st in
    comma st;
    let p2 = mesh_vector st in
    comma st;
    let l2 = peek_loc st in
    let n2 = mesh_vector st in
    comma st;
    let p3 = mesh_vector st in
    comma st;
    let l3 = peek_loc st in
    let n3 = mesh_vector st in
    (p1, p2, p3, Some (unit_normal st l1 n1, unit_normal st l2 n2, unit_normal st l3 n3))
  end
  else begin
    let p2 = mesh_vector st in
    comma st;
    let p3 = mesh_vector st in
    (p1, p2, p3, None)
  end

(* Growable arrays for the lists of a mesh. With a capacity given (mesh2 announces its counts) the
   array is made once at that size and handed over as it is; otherwise the values go into chunks
   and [to_array] copies them once, so growing never holds more than the values and one copy. *)
module Grow = struct
  (* [chunks.(0)] has the first size (the capacity, or 1024), every later chunk [chunk] values *)
  type 'a t = { fill : 'a; mutable chunks : 'a array array; mutable n : int; mutable len : int }

  let chunk = 65536

  let create ?capacity x =
    let first = match capacity with Some c -> max 16 c | None -> 1024 in
    { fill = x; chunks = [| Array.make first x |]; n = 1; len = 0 }

  let first g = Array.length g.chunks.(0)

  let push g x =
    let f = first g in
    let c, i = if g.len < f then (0, g.len) else (1 + ((g.len - f) / chunk), (g.len - f) mod chunk) in
    if c = g.n then begin
      if g.n = Array.length g.chunks then g.chunks <- Array.append g.chunks (Array.make g.n [||]);
      g.chunks.(c) <- Array.make chunk g.fill;
      g.n <- g.n + 1
    end;
    Array.unsafe_set g.chunks.(c) i x;
    g.len <- g.len + 1

  let get g i =
    let f = first g in
    if i < f then g.chunks.(0).(i) else g.chunks.(1 + ((i - f) / chunk)).((i - f) mod chunk)

  let to_array g =
    if g.n = 1 && g.len = first g then g.chunks.(0)
    else begin
      let a = Array.make g.len g.fill in
      let at = ref 0 in
      for c = 0 to g.n - 1 do
        let k = min (Array.length g.chunks.(c)) (g.len - !at) in
        Array.blit g.chunks.(c) 0 a !at k;
        at := !at + k
      done;
      a
    end
end

(* Vertices (or normals) of a mesh { } merged when equal, as POV-Ray merges them: an open
   addressing table over the stored single-precision triples. *)
module Vertex_table = struct
  type t = { store : float Grow.t; mutable slots : int array; mutable count : int }

  let create () = { store = Grow.create 0.; slots = Array.make 1024 (-1); count = 0 }

  let hash x y z = Hashtbl.hash (Int64.bits_of_float x, Int64.bits_of_float y, Int64.bits_of_float z)

  let coord t i = Grow.get t.store i

  let rec insert t x y z =
    let mask = Array.length t.slots - 1 in
    let rec probe h =
      let k = t.slots.(h) in
      if k < 0 then begin
        t.slots.(h) <- t.count;
        Grow.push t.store x; Grow.push t.store y; Grow.push t.store z;
        t.count <- t.count + 1;
        t.count - 1
      end
      else if coord t (3 * k) = x && coord t ((3 * k) + 1) = y && coord t ((3 * k) + 2) = z then k
      else probe ((h + 1) land mask)
    in
    if 2 * (t.count + 1) > Array.length t.slots then begin
      let n = 2 * Array.length t.slots in
      let slots = Array.make n (-1) in
      for k = 0 to t.count - 1 do
        let rec place h = if slots.(h) < 0 then slots.(h) <- k else place ((h + 1) land (n - 1)) in
        place (hash (coord t (3 * k)) (coord t ((3 * k) + 1)) (coord t ((3 * k) + 2)) land (n - 1))
      done;
      t.slots <- slots;
      insert t x y z
    end
    else probe (hash x y z land mask)

  let to_array t = Grow.to_array t.store
end

(* A block "{ n, item, item … }" of a mesh2: [item] is called for each entry (with its location),
   and the number of entries must be n. *)
let parse_counted_block ?(start = fun (_ : int) -> ()) st what item =
  let loc = peek_loc st in
  open_block st what;
  let nloc = peek_loc st in
  let n = parse_float st in
  if n < 0. || Float.of_int (int_of_float n) <> n then Error.raise_at nloc "the count of %s must be a whole number, not %g" what n;
  let n = int_of_float n in
  (* room for the announced entries, within reason: a wrong count is reported after the block *)
  start (min n 50_000_000);
  let count = ref 0 in
  while peek st != RBrace do
    if peek st == Eof then close_block st what;
    comma st;
    if peek st != RBrace then begin
      item (peek_loc st);
      incr count
    end
  done;
  advance st;
  if !count <> n then Error.raise_at loc "%s says %d entries but lists %d" what n !count;
  n

let f32_vec (v : Vec.t) = Vec.make (f32 v.x) (f32 v.y) (f32 v.z)

let parse_texture_in_block st =
  (* texture { … } or a texture identifier inside a mesh triangle *)
  advance st;
  parse_texture st st.default_texture

(* Values povml cannot make yet; a declaration of one is kept as [V.Unsupported]. *)
let unsupported_rvalues =
  [ "material"; "normal"; "color_map"; "colour_map"; "pigment_map"; "normal_map"; "texture_map"; "slope_map";
    "function"; "spline"; "media"; "density"; "fog"; "rainbow"; "sky_sphere"; "isosurface" ]

let unsupported_rvalue_set = set_of (unsupported_objects @ unsupported_rvalues)

let unsupported_object_set = set_of unsupported_objects

let rec parse_object st : V.obj =
  let loc = peek_loc st in
  match peek st with
  | Ident ("triangle" | "smooth_triangle" as kw) ->
      advance st;
      open_block st kw;
      let smooth = kw = "smooth_triangle" in
      let p1, p2, p3, ns = parse_triangle_corners st ~smooth in
      let shape : Scene.shape =
        match ns with
        | None ->
            if Triangle.flat p1 p2 p3 = None then warn st loc "degenerate triangle; please remove it";
            Triangle { p1; p2; p3 }
        | Some (n1, n2, n3) ->
            (match Triangle.smooth p1 n1 p2 n2 p3 n3 with
            | None | Some (Error ()) -> warn st loc "degenerate triangle; please remove it"
            | Some (Ok _) -> ());
            Smooth_triangle { p1; n1; p2; n2; p3; n3 }
      in
      parse_object_mods st (new_obj shape loc) kw
  | Ident "mesh" -> advance st; parse_mesh st loc
  | Ident "mesh2" -> advance st; parse_mesh2 st loc
  | Ident "sphere" ->
      advance st;
      open_block st "sphere";
      let centre = parse_vector st in
      ignore (accept st Comma) (* POV-Ray accepts the comma as optional *);
      let rloc = peek_loc st in
      let radius = parse_float st in
      if radius <= 0. then warn st rloc "sphere radius %g is not positive" radius;
      parse_object_mods st (new_obj (Sphere { centre; radius; trans = None }) loc) "sphere"
  | Ident "plane" ->
      advance st;
      open_block st "plane";
      let nloc = peek_loc st in
      let n = parse_vector st in
      ignore (accept st Comma);
      let d = parse_float st in
      (* §2.3: the normal is normalised, the distance is NOT divided by |n| *)
      if Vec.length n = 0. then Error.raise_at nloc "degenerate plane normal <0,0,0>";
      parse_object_mods st (new_obj (Plane { normal = Vec.normalize n; offset = d; trans = None }) loc) "plane"
  | Ident "object" ->
      advance st;
      open_block st "object";
      let iloc = peek_loc st in
      let o =
        match peek st with
        | Ident s when Names.mem object_set s -> parse_object st
        | Ident s -> (
            match cur_value st s with
            | Some (V.Object o) -> advance st; { o with oloc = loc }
            | Some (V.Light l) -> advance st; { (new_obj_of (V.Union [ V.Member_light l ]) loc) with oloc = loc }
            | Some (V.Unsupported u) -> unsupported_use iloc s u.what u.at
            | Some v -> Error.raise_at iloc "'%s' is %s, not an object" s (V.kind_name v)
            | None -> if is_keyword s then unexpected st "an object identifier" else unknown_identifier st iloc s)
        | _ -> unexpected st "an object identifier"
      in
      parse_object_mods st o "object"
  | Ident "union" ->
      (* §16.4: a union is dissolved into its members when it enters the scene; its texture,
         interior and flags go to the members that have none *)
      advance st;
      open_block st "union";
      let rec members acc =
        match peek st with
        | Ident "light_source" -> members (V.Member_light (parse_light st) :: acc)
        | _ when object_follows st -> members (V.Member_obj (parse_object st) :: acc)
        | _ -> List.rev acc
      in
      let ms = members [] in
      if List.length ms < 2 then warn st loc "a union should have at least two members";
      parse_object_mods st (new_obj_of (V.Union ms) loc) "union"
  | Ident "light_source" -> new_obj_of (V.Union [ V.Member_light (parse_light st) ]) loc
  | Ident s -> (
      match cur_value st s with
      | Some (V.Object o) -> advance st; { o with oloc = loc }
      | Some (V.Light l) -> advance st; new_obj_of (V.Union [ V.Member_light l ]) loc
      | Some (V.Unsupported u) -> unsupported_use loc s u.what u.at
      | _ -> unexpected st "an object")
  | _ -> unexpected st "an object"

(* Does an object (a keyword or an identifier of one) come next? *)
and object_follows st =
  match peek st with
  | Ident s when Names.mem object_set s -> true
  | Ident s -> ( match cur_value st s with Some (V.Object _ | V.Light _) -> true | Some (V.Unsupported _) -> true | _ -> Names.mem unsupported_object_set s)
  | _ -> false

(* mesh { triangle {…} smooth_triangle {…} … [inside_vector V] modifiers } (§2.6). Vertices are kept
   in single precision; each face is set up from the values as parsed. *)
and parse_mesh st loc =
  open_block st "mesh";
  let verts = Vertex_table.create () and norms = Vertex_table.create () and corners = Grow.create 0. in
  let fv = Grow.create 0 and fn = Grow.create 0 and ftex = Grow.create 0 in
  let textures = ref [] and ntex = ref 0 in
  let inside = ref None in
  let push3 g (v : Vec.t) = Grow.push g v.x; Grow.push g v.y; Grow.push g v.z in
  let add_vertex (v : Vec.t) = Grow.push fv (Vertex_table.insert verts (f32 v.x) (f32 v.y) (f32 v.z)) in
  let add_normal (n : Vec.t) = Grow.push fn (Vertex_table.insert norms (f32 n.x) (f32 n.y) (f32 n.z)) in
  let rec items () =
    match peek st with
    | Ident ("triangle" | "smooth_triangle" as kw) ->
        advance st;
        open_block st kw;
        let p1, p2, p3, ns = parse_triangle_corners st ~smooth:(kw = "smooth_triangle") in
        let tex =
          if is_ident st "texture" then begin
            (* POV-Ray takes only a texture identifier here: texture { T } *)
            advance st;
            open_block st "texture";
            let tl = peek_loc st in
            let t =
              match ident_of_kind st (function V.Texture t -> Some t | _ -> None) with
              | Some t -> t
              | None -> Error.raise_at tl "expected a texture identifier: a mesh triangle takes texture { Identifier }"
            in
            close_block st "texture";
            textures := t :: !textures;
            incr ntex;
            !ntex - 1
          end
          else -1
        in
        close_block st kw;
        add_vertex p1; add_vertex p2; add_vertex p3;
        push3 corners p1; push3 corners p2; push3 corners p3;
        (match ns with
        | Some (a, b, c) -> add_normal a; add_normal b; add_normal c
        | None -> Grow.push fn (-1); Grow.push fn (-1); Grow.push fn (-1));
        Grow.push ftex tex;
        items ()
    | Ident "inside_vector" -> advance st; inside := Some (parse_vector st); items ()
    | _ -> ()
  in
  items ();
  let mesh =
    Mesh.build ~vertices:(Vertex_table.to_array verts) ~vertex_normals:(Vertex_table.to_array norms) ~fv:(Grow.to_array fv)
      ~fn:(Grow.to_array fn) ~ftex:(Grow.to_array ftex) ~corners:(Some (Grow.to_array corners)) ~inside_vector:!inside
  in
  if mesh.faces = 0 then warn st loc "the mesh has no triangles with an area";
  let shape = Scene.Mesh { mesh; trans = None; textures = Array.of_list (List.rev !textures) } in
  parse_object_mods st (new_obj shape loc) "mesh"

(* mesh2 { vertex_vectors normal_vectors texture_list face_indices normal_indices inside_vector … } *)
and parse_mesh2 st loc =
  open_block st "mesh2";
  let vertices = ref None and normals = ref None and textures = ref [||] in
  let faces = ref None and nidx = ref None and inside = ref None in
  let vectors what ~unit =
    let g = ref (Grow.create 0.) in
    let n =
      parse_counted_block st what ~start:(fun n -> g := Grow.create ~capacity:(3 * n) 0.) (fun l ->
          let g = !g in
          let v = mesh_vector st in
          let v = f32_vec (if unit then unit_normal st l v else v) in
          Grow.push g v.x; Grow.push g v.y; Grow.push g v.z)
    in
    (n, Grow.to_array !g)
  in
  let indices st l limit what g =
    let v = mesh_vector st in
    let check x =
      if Float.of_int (int_of_float x) <> x || x < 0. || int_of_float x >= limit then
        Error.raise_at l "%s index %g is out of range: there are %d" what x limit;
      Grow.push g (int_of_float x)
    in
    check v.x; check v.y; check v.z
  in
  let rec sections () =
    let l = peek_loc st in
    match peek st with
    | Ident "vertex_vectors" -> advance st; vertices := Some (vectors "vertex_vectors" ~unit:false); sections ()
    | Ident "normal_vectors" -> advance st; normals := Some (vectors "normal_vectors" ~unit:true); sections ()
    | Ident "uv_vectors" -> not_supported l "'uv_vectors'"
    | Ident "texture_list" ->
        advance st;
        let g = ref [] in
        ignore
          (parse_counted_block st "texture_list" (fun l ->
               if is_ident st "texture" then g := parse_texture_in_block st :: !g
               else Error.raise_at l "expected a texture in texture_list"));
        textures := Array.of_list (List.rev !g);
        sections ()
    | Ident "face_indices" ->
        advance st;
        let nv = match !vertices with Some (n, _) -> n | None -> Error.raise_at l "face_indices before vertex_vectors" in
        let ntex = Array.length !textures in
        let fv = ref (Grow.create 0) and ftex = ref (Grow.create 0) in
        let n =
          parse_counted_block st "face_indices"
            ~start:(fun n ->
              fv := Grow.create ~capacity:(3 * n) 0;
              (* per-face texture indices only when there is a texture list *)
              if ntex > 0 then ftex := Grow.create ~capacity:n 0)
            (fun l ->
              let fv = !fv and ftex = !ftex in
              indices st l nv "vertex" fv;
              (* an optional texture index (three would interpolate, which is not read yet) *)
              let tex =
                let index_follows () = accept st Comma && (match peek st with Lt | RBrace -> false | _ -> true) in
                if index_follows () then begin
                  let tl = peek_loc st in
                  let t = parse_float st in
                  if index_follows () then not_supported tl "three texture indices per face (interpolated textures)";
                  if Float.of_int (int_of_float t) <> t || t < 0. || int_of_float t >= ntex then
                    Error.raise_at tl "texture index %g is out of range: the texture_list has %d" t ntex;
                  int_of_float t
                end
                else -1
              in
              if ntex > 0 then Grow.push ftex tex)
        in
        faces := Some (l, n, Grow.to_array !fv, if ntex > 0 then Grow.to_array !ftex else [||]);
        sections ()
    | Ident "normal_indices" ->
        advance st;
        let nn = match !normals with Some (n, _) -> n | None -> Error.raise_at l "normal_indices before normal_vectors" in
        let g = ref (Grow.create 0) in
        let n =
          parse_counted_block st "normal_indices" ~start:(fun n -> g := Grow.create ~capacity:(3 * n) 0) (fun l ->
              indices st l nn "normal" !g)
        in
        nidx := Some (l, n, Grow.to_array !g);
        sections ()
    | Ident "uv_indices" -> not_supported l "'uv_indices'"
    | Ident "inside_vector" -> advance st; inside := Some (parse_vector st); sections ()
    | _ -> ()
  in
  sections ();
  let nv, vs = match !vertices with Some v -> v | None -> Error.raise_at loc "mesh2 needs vertex_vectors" in
  let fl, nf, fv, ftex = match !faces with Some f -> f | None -> Error.raise_at loc "mesh2 needs face_indices" in
  let nn, ns = match !normals with Some n -> n | None -> (0, [||]) in
  (* §2.6: without normal_indices the face indices serve when there are as many normals as vertices;
     only the first faces, as many as there are normal indices, can be smooth *)
  let fn =
    match !nidx with
    | Some (nl, n, ni) ->
        if n > nf then Error.raise_at nl "normal_indices has %d entries but there are only %d faces" n nf;
        Array.init (3 * nf) (fun i -> if i < 3 * n then ni.(i) else -1)
    | None ->
        if nn = 0 then [||]
        else if nn = nv then fv
        else
          Error.raise_at fl "normal_vectors has %d entries and vertex_vectors %d: without normal_indices they must be as many" nn nv
  in
  let mesh = Mesh.build ~vertices:vs ~vertex_normals:ns ~fv ~fn ~ftex ~corners:None ~inside_vector:!inside in
  let shape = Scene.Mesh { mesh; trans = None; textures = !textures } in
  parse_object_mods st (new_obj shape loc) "mesh2"

(* §2.7: every object gets a texture and an interior; a legacy finish ior goes into the interior. *)
let finish_prim st (o : V.obj) shape : Scene.obj =
  let texture = match o.texture with Some t -> t | None -> st.default_texture in
  let interior = match o.interior with Some i -> i | None -> Defaults.interior in
  let interior = match texture.finish.legacy_ior with Some ior -> { interior with ior } | None -> interior in
  let interior = if interior.ior = 0. then { interior with ior = 1. } else interior in
  { Scene.shape; texture; interior; no_shadow = o.no_shadow; loc = o.oloc }

(* An object entering the scene (§16.4, §16.5): a union is dissolved, its members without a texture
   or interior take the union's, and its no_shadow goes to every member; its lights join the scene's. *)
let rec add_object st (o : V.obj) =
  match o.shape with
  | Prim shape -> st.objects <- finish_prim st o shape :: st.objects
  | Union ms ->
      List.iter
        (function
          | V.Member_light l -> st.lights <- l :: st.lights
          | V.Member_obj c ->
              add_object st
                {
                  c with
                  texture = (match c.texture with Some _ -> c.texture | None -> o.texture);
                  interior = (match c.interior with Some _ -> c.interior | None -> o.interior);
                  no_shadow = c.no_shadow || o.no_shadow;
                })
        ms

(* ---------------------------------------------------------------------------------------------- *)
(* Camera, lights, settings *)

let empty_camera =
  { c_location = None; c_direction = None; c_up = None; c_right = None; c_sky = None; c_look_at = None; c_angle = None; c_trans = None }

let parse_camera st =
  open_block st "camera";
  let base =
    match peek st with
    | Ident s -> ( match cur_value st s with Some (V.Camera c) -> advance st; c | _ -> empty_camera)
    | _ -> empty_camera
  in
  let rec loop c =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; c
    | Ident "perspective" -> advance st; loop c
    | Ident "location" -> advance st; loop { c with c_location = Some (parse_vector st) }
    | Ident "direction" -> advance st; loop { c with c_direction = Some (parse_vector st) }
    | Ident "up" -> advance st; loop { c with c_up = Some (parse_vector st) }
    | Ident "right" -> advance st; loop { c with c_right = Some (parse_vector st) }
    | Ident "sky" -> advance st; loop { c with c_sky = Some (parse_vector st) }
    | Ident "look_at" -> advance st; let l = peek_loc st in loop { c with c_look_at = Some (parse_vector st, l) }
    | Ident "angle" -> advance st; let l = peek_loc st in loop { c with c_angle = Some (parse_float st, l) }
    | Ident ("translate" | "rotate" | "scale" | "matrix" | "transform") ->
        let t = Place.op_transform (parse_op st) in
        loop { c with c_trans = Some (match c.c_trans with None -> t | Some t0 -> Transform.compose t0 t) }
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in a camera" s)
    | _ -> unexpected st "a camera keyword or '}'"
  in
  loop base

(* §1.3: the camera modifiers are applied in a fixed order, whatever order they were written in. *)
let build_camera st (c : camera_spec) : Scene.camera =
  let location = Option.value c.c_location ~default:Vec.zero in
  let direction = Option.value c.c_direction ~default:(Vec.make 0. 0. 1.) in
  let up = Option.value c.c_up ~default:(Vec.make 0. 1. 0.) in
  let right = Option.value c.c_right ~default:(Vec.make 1.33 0. 0.) in
  let sky = Option.value c.c_sky ~default:(Vec.make 0. 1. 0.) in
  let direction =
    match c.c_angle with
    | None -> direction
    | Some (a, loc) ->
        if a >= 180. then Error.raise_at loc "camera angle must be less than 180 degrees, not %g" a;
        if a <= 0. then Error.raise_at loc "camera angle must be greater than 0 degrees, not %g" a;
        Vec.scale (Vec.length right /. tan (a *. Float.pi /. 360.) /. 2.) (Vec.normalize direction)
  in
  let direction, right, up =
    match c.c_look_at with
    | None -> (direction, right, up)
    | Some (p, loc) ->
        let dl = Vec.length direction and ul = Vec.length up and rl = Vec.length right in
        let handedness = Vec.dot (Vec.cross up direction) right in
        let dv = Vec.sub p location in
        if Vec.length2 dv < 1e-10 then Error.raise_at loc "camera look_at point is the same as the location";
        let d = Vec.normalize dv in
        let r = Vec.cross sky d in
        let r =
          if Float.abs r.x < 1e-10 && Float.abs r.y < 1e-10 && Float.abs r.z < 1e-10 then begin
            warn st loc "camera location and look_at are in line with the sky vector; the old right vector is kept";
            right
          end
          else r
        in
        let r = Vec.normalize r in
        let u = Vec.cross d r in
        (Vec.scale dl d, Vec.scale (if handedness > 0. then rl else -.rl) r, Vec.scale ul u)
  in
  match c.c_trans with
  | None -> { Scene.location; direction; up; right }
  | Some t ->
      (* §14.8: the location as a point, the other vectors as directions *)
      {
        Scene.location = Transform.point t location;
        direction = Transform.direction t direction;
        up = Transform.direction t up;
        right = Transform.direction t right;
      }

let parse_global_settings st =
  open_block st "global_settings";
  let rec loop () =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st
    | Ident "assumed_gamma" ->
        advance st;
        let g = parse_float st in
        if g <= 0. then Error.raise_at loc "assumed_gamma must be positive, not %g" g;
        if st.assumed_gamma = None then st.assumed_gamma <- Some g
        else warn st loc "new instance of assumed_gamma ignored";
        loop ()
    | Ident "max_trace_level" ->
        advance st;
        (* §7: clipped to 1 … 256 *)
        let n = int_of_float (parse_float st) in
        st.max_trace_level <- max 1 (min 256 n);
        loop ()
    | Ident "adc_bailout" -> advance st; st.adc_bailout <- parse_float st; loop ()
    | Ident "ambient_light" -> advance st; st.ambient_light <- parse_rgb st "ambient_light"; loop ()
    | Ident ("number_of_waves" | "noise_generator") -> advance st; ignore (parse_float st); loop ()
    | Ident "irid_wavelength" -> advance st; ignore (parse_rgb st "irid_wavelength"); loop ()
    | Ident "charset" -> advance st; (match peek st with Ident _ -> advance st | _ -> unexpected st "a charset name"); loop ()
    | Ident s when is_unsupported s -> not_supported loc (Printf.sprintf "'%s' in global_settings" s)
    | _ -> unexpected st "a global_settings keyword or '}'"
  in
  loop ()

let parse_sky_sphere st =
  let loc = peek_loc st in
  advance st;
  open_block st "sky_sphere";
  if st.sky <> None then warn st loc "a second sky_sphere replaces the first";
  let rec loop pigs emission =
    let l = peek_loc st in
    match peek st with
    | RBrace ->
        advance st;
        if pigs = [] then Error.raise_at loc "a sky_sphere needs at least one pigment";
        { Scene.sky_pigments = List.rev pigs; sky_emission = emission }
    | Ident "pigment" -> advance st; loop (parse_pigment st (Scene.Solid Colour.black) :: pigs) emission
    | Ident "emission" -> advance st; loop pigs (parse_rgb st "sky_sphere emission")
    | Ident "translate" -> advance st; ignore (parse_vector st); loop pigs emission
    | Ident s when is_unsupported s -> not_supported l (Printf.sprintf "'%s' in a sky_sphere" s)
    | _ -> unexpected st "'pigment' or '}' in a sky_sphere"
  in
  st.sky <- Some (loop [] Rgb.white)

(* §8.1: the version POV-Ray's renderer sees so far: 3.62 until a #version has been read. *)
let effective_version st = if st.version_set then st.version else 362

let parse_background st =
  advance st;
  open_block st "background";
  let c = parse_colour st in
  close_block st "background";
  (* §8.4: from 3.70 the transmit is folded into rgb; before, filter and transmit become 0 *)
  st.background <-
    Some
      (if effective_version st >= 370 then
         { Colour.red = c.red *. (1. -. c.transmit); green = c.green *. (1. -. c.transmit); blue = c.blue *. (1. -. c.transmit); filter = 0.; transmit = 0. }
       else { c with filter = 0.; transmit = 0. })

(* ---------------------------------------------------------------------------------------------- *)
(* Declarations and statements *)

(* The value of a #declare or of a macro argument (the parser's "rvalue"), and whether a ';' should
   follow it (§11.3: after floats, vectors, colours and strings). *)
let rec parse_rvalue st : V.t * bool =
  let loc = peek_loc st in
  match peek st with
  | Ident "light_source" -> (V.Light (parse_light st), false)
  | Ident s when Names.mem object_set s -> (V.Object (parse_object st), false)
  | Ident "pigment" -> advance st; (V.Pigment (parse_pigment st (Scene.Solid Colour.black)), false)
  | Ident "finish" -> advance st; (V.Finish (parse_finish st Defaults.finish), false)
  | Ident "texture" ->
      advance st;
      let t = parse_texture st st.default_texture in
      if (match peek_follow st with Ident "texture" -> true | _ -> false) then not_supported (peek_loc st) "layered textures";
      (V.Texture t, false)
  | Ident "interior" -> advance st; (V.Interior (parse_interior st Defaults.interior), false)
  | Ident "camera" -> advance st; (V.Camera (parse_camera st), false)
  | Ident "transform" -> advance st; (V.Transform (parse_transform st), false)
  | Ident "array" -> (parse_array st, false)
  | Ident s when Names.mem unsupported_rvalue_set s -> not_supported loc (Printf.sprintf "'%s'" s)
  | Ident s -> (
      match cur_value st s with
      | Some (V.Object o) -> advance st; (V.Object { o with oloc = loc }, false)
      | Some ((V.Pigment _ | V.Finish _ | V.Texture _ | V.Interior _ | V.Light _ | V.Camera _ | V.Stream _ | V.Transform _ | V.Unsupported _) as v) ->
          advance st; (v, false)
      | Some (V.Array a) -> advance st; (V.Array { a with cells = Array.copy a.cells }, false)
      | _ -> (parse_expr st, true))
  | _ -> (parse_expr st, true)

(* array[d1][d2]… [{ initialisers }] (§11.2). *)
and parse_array st =
  let loc = peek_loc st in
  advance st;
  let rec dims acc =
    if peek st == LBracket then begin
      advance st;
      let l = peek_loc st in
      let n = parse_float st in
      if n < 1. || Float.of_int (int_of_float n) <> n then Error.raise_at l "an array dimension must be a whole number of at least 1, not %g" n;
      expect st RBracket "']' after an array dimension";
      dims (int_of_float n :: acc)
    end
    else List.rev acc
  in
  let dims = Array.of_list (dims []) in
  if Array.length dims = 0 then Error.raise_at loc "'array' needs a size: array[N]";
  let total = Array.fold_left ( * ) 1 dims in
  if total > 50_000_000 then Error.raise_at loc "this array would have %d elements; the limit is 50,000,000" total;
  let cells = Array.make total None in
  if peek st == LBrace then begin
    (* nested braces, one level per dimension *)
    let rec fill_level d offset =
      let bl = peek_loc st in
      expect st LBrace "'{' of an array initialiser";
      let stride = Array.fold_left ( * ) 1 (Array.sub dims (d + 1) (Array.length dims - d - 1)) in
      for i = 0 to dims.(d) - 1 do
        if i > 0 then expect st Comma "',' between array elements";
        if peek st == RBrace then Error.raise_at bl "this initialiser has %d elements; the array dimension is %d" i dims.(d);
        if d = Array.length dims - 1 then cells.(offset + i) <- Some (fst (parse_rvalue st))
        else fill_level (d + 1) (offset + (i * stride))
      done;
      ignore (accept st Comma);
      if peek st != RBrace then Error.raise_at (peek_loc st) "too many elements in an array initialiser: the dimension is %d" dims.(d);
      advance st
    in
    fill_level 0 0
  end;
  V.Array { dims; cells }

(* The subscripts [i][j]… of an element of [a], as a row-major index. *)
let parse_index st (a : V.array_v) =
  let n = Array.length a.dims in
  let rec go d acc =
    if d = n then acc
    else begin
      expect st LBracket "'[' of an array subscript";
      let l = peek_loc st in
      let i = parse_float st in
      let i = int_of_float i in
      if i < 0 || i >= a.dims.(d) then Error.raise_at l "array subscript %d is out of range 0 … %d" i (a.dims.(d) - 1);
      expect st RBracket "']' closing an array subscript";
      go (d + 1) ((acc * a.dims.(d)) + i)
    end
  in
  go 0 0

(* Where #declare and #local write (§11.3): an existing identifier is changed where it is found (the
   innermost table that has it), a new one goes to the global table for #declare and to the current
   table (file or macro) for #local. *)
let assign st ~local name value =
  let current = List.hd st.tables in
  match (local, lookup_cell st name) with
  | true, _ -> (
      match Names.find_opt current name with Some c -> c := value | None -> Names.replace current name (ref value))
  | false, Some c -> c := value
  | false, None -> Names.replace st.global name (ref value)

(* After an unsupported feature inside a declaration: skip the rest of the declared value, that is
   the blocks it opened, or at its own level up to a ';' or through its first block. *)
let skip_declaration st d0 =
  let rec close () = if st.depth > d0 && peek st != Eof then (advance st; close ()) in
  let rec scan () =
    match peek st with
    | Semi | RBrace | Eof -> ()
    | LBrace -> advance st; close ()
    | _ -> advance st; scan ()
  in
  if st.depth > d0 then close () else scan ();
  (* the further layers of a layered texture: texture {…} texture {…} *)
  while (match peek_follow st with Ident "texture" -> true | _ -> false) do advance st; scan () done

let parse_declare st ~local dloc =
  let nloc = peek_loc st in
  st.no_expand <- true;
  let k = Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st) in
  let k =
    (* #declare deprecated [once] "message" Id = … (3.7): the message is for users of Id *)
    match k with
    | Ident "deprecated" ->
        advance st;
        ignore (accept_ident st "once");
        (match peek st with Str _ -> advance st | _ -> unexpected st "the deprecation message");
        st.no_expand <- true;
        Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st)
    | k -> k
  in
  let target =
    match k with
    | Ident s when is_keyword s -> Error.raise_at nloc "'%s' is a keyword and cannot be declared" s
    | Ident s -> (
        match st.cur_elem with
        | Some (a, i) -> advance st; `Element (s, a, i)
        | None -> advance st; `Name s)
    | _ -> unexpected st (Printf.sprintf "an identifier after '#%s'" (if local then "local" else "declare"))
  in
  let name = match target with `Name s | `Element (s, _, _) -> s in
  expect st Eq (Printf.sprintf "'=' after '%s'" name);
  let d0 = st.depth in
  let in_main = List.length st.frames = 1 in
  let value, needs_semi =
    try parse_rvalue st
    with Unsupported (l, what, _) ->
      (* a declaration povml cannot make yet is no error until it is used (issue: include files
         declare much more than a scene uses) *)
      skip_declaration st d0;
      if in_main then warn st dloc "'%s' uses %s, which povml does not support yet; using it will be an error" name what;
      (V.Unsupported { what; at = l }, false)
  in
  (* the value is stored before anything after it is read: the next token may be a directive *)
  (match target with
  | `Name s -> assign st ~local s value
  | `Element (_, a, i) -> a.cells.(i) <- Some value);
  if needs_semi && not (accept st Semi) then begin
    if st.version >= 350 then
      warn st (peek_loc st) "all #declares of float, vector, and color require semicolon ';' at end if the language version is 3.5 or higher"
  end
  else if not needs_semi then ignore (accept st Semi)

let read_file path =
  let at = { Loc.none with file = path } in
  let reason msg =
    (* Sys_error reads "path: reason"; the path is already in the location *)
    let p = path ^ ": " in
    if String.length msg > String.length p && String.sub msg 0 (String.length p) = p then
      String.sub msg (String.length p) (String.length msg - String.length p)
    else msg
  in
  if Sys.file_exists path && Sys.is_directory path then Error.raise_at at "this is a directory, not a scene file";
  match open_in_bin path with
  | exception Sys_error msg -> Error.raise_at at "cannot open the scene file: %s" (reason msg)
  | ic ->
      Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
          match really_input_string ic (in_channel_length ic) with
          | s -> s
          | exception Sys_error msg -> Error.raise_at at "cannot read the scene file: %s" (reason msg))

(* ---------------------------------------------------------------------------------------------- *)
(* Directives (§11.3): run as the token stream is read *)

let block_openers = [ "if"; "ifdef"; "ifndef"; "while"; "for"; "switch"; "macro" ]

(* Skip raw tokens of the current frame (a branch not taken, a loop that ends, a macro definition)
   up to the #end at this level, or up to one of [stops] at this level; returns what it stopped at. *)
let skip st ~stops open_loc what =
  let f = top st in
  let rec go depth =
    let t = Lexer.next f.lx in
    match t.kind with
    | Eof -> Error.raise_at open_loc "%s has no matching #end" what
    | Directive d when List.mem d block_openers -> go (depth + 1)
    | Directive "end" -> if depth = 0 then `End else go (depth - 1)
    | Directive d when depth = 0 && List.mem d stops -> `Stop (d, t.loc)
    | _ -> go depth
  in
  go 0

let skip_to_end st open_loc what = ignore (skip st ~stops:[] open_loc what)

(* (expression): the condition of #if, #while, #switch, #case. Read without looking past the ')',
   so nothing after it runs before the directive has decided. *)
let cond_value st what =
  if peek st != LParen then unexpected st (Printf.sprintf "'(' after '#%s'" what);
  advance st;
  let l = peek_loc st in
  let v = parse_full st in
  expect st RParen (Printf.sprintf "')' closing the condition of '#%s'" what);
  match v with V.Float f -> f | v -> Error.raise_at l "the condition of '#%s' must be a float, not %s" what (V.kind_name v)

(* A string argument (#include, #debug …), also read without looking past it. *)
let string_arg st what =
  let l = peek_loc st in
  match parse_primary st with
  | V.String s -> s
  | v -> Error.raise_at l "'#%s' needs a string, not %s" what (V.kind_name v)

let push_cond st c = let f = top st in f.conds <- c :: f.conds

let pop_cond st = let f = top st in f.conds <- List.tl f.conds

(* #if (c) / #elseif chain, from a condition already evaluated to [c]. *)
let rec run_if st c loc =
  if c then push_cond st (If_branch loc)
  else
    match skip st ~stops:[ "else"; "elseif" ] loc "#if" with
    | `End -> ()
    | `Stop ("else", _) -> push_cond st (If_branch loc)
    | `Stop (_, l) -> run_if st (truth (cond_value st "elseif")) l

(* Look for the #case, #range or #else of a #switch that matches. *)
let rec find_case st (sw : cond) =
  match sw with
  | Switch_case r -> (
      match skip st ~stops:[ "case"; "range"; "else" ] r.sloc "#switch" with
      | `End -> pop_cond st
      | `Stop ("else", _) -> r.running <- true
      | `Stop ("case", _) -> if Float.abs (cond_value st "case" -. r.value) < 1e-10 then r.running <- true else find_case st sw
      | `Stop (_, _) ->
          let lo, hi = range_args st in
          if lo <= r.value && r.value <= hi then r.running <- true else find_case st sw)
  | If_branch _ | While_loop _ | For_loop _ -> ()

and range_args st =
  expect st LParen "'(' after '#range'";
  let lo = parse_float st in
  expect st Comma "',' between the bounds of '#range'";
  let hi = parse_float st in
  expect st RParen "')' closing '#range'";
  (lo, hi)

let max_include_depth = 64
let max_macro_depth = 10_000

let directive_names =
  [ "declare"; "local"; "undef"; "version"; "include"; "if"; "ifdef"; "ifndef"; "elseif"; "else"; "end"; "while";
    "for"; "switch"; "case"; "range"; "break"; "macro"; "debug"; "warning"; "error"; "default"; "fopen"; "fclose";
    "read"; "write"; "render"; "statistics" ]

let directive st d loc =
  let f = top st in
  match d with
  | "declare" | "local" -> parse_declare st ~local:(d = "local") loc
  | "undef" -> (
      st.no_expand <- true;
      let k = Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st) in
      match k with
      | Ident s ->
          advance st;
          (match List.find_opt (fun t -> Names.mem t s) st.tables with
          | Some t -> Names.remove t s
          | None -> warn st loc "attempt to #undef the unknown identifier '%s'" s)
      | _ -> unexpected st "an identifier after '#undef'")
  | "version" ->
      let v = parse_float st in
      ignore (accept st Semi);
      st.version <- int_of_float ((v *. 100.) +. 0.5);
      st.version_set <- true
  | "include" -> (
      let name = string_arg st "include" in
      if st.includes >= max_include_depth then
        Error.raise_at loc "includes are nested more than %d deep (does a file include itself?)" max_include_depth;
      match find_file st name with
      | None ->
          Error.raise_at loc "cannot find the include file \"%s\" (searched %s)" name (String.concat ", " (include_dirs st))
      | Some path ->
          let text = read_file path in
          st.frames <- { lx = Lexer.create ~file:path text; kind = Included (loc, Unix.gettimeofday ()); conds = [] } :: st.frames;
          st.tables <- Names.create 16 :: st.tables;
          st.includes <- st.includes + 1)
  | "if" -> run_if st (truth (cond_value st "if")) loc
  | "ifdef" | "ifndef" ->
      expect st LParen (Printf.sprintf "'(' after '#%s'" d);
      let def = parse_defined_arg st in
      expect st RParen (Printf.sprintf "')' closing '#%s'" d);
      run_if st (if d = "ifdef" then def else not def) loc
  | "else" | "elseif" -> (
      match f.conds with
      | If_branch l :: _ -> pop_cond st; skip_to_end st l "#if"
      | Switch_case { running = true; _ } :: _ when d = "else" -> () (* falls through, as #case does *)
      | _ -> Error.raise_at loc "'#%s' without a matching #if" d)
  | "end" -> (
      match f.conds with
      | If_branch _ :: _ | Switch_case _ :: _ -> pop_cond st
      | While_loop (m, l) :: _ ->
          Lexer.reset f.lx m;
          if not (truth (cond_value st "while")) then begin pop_cond st; skip_to_end st l "#while" end
      | For_loop r :: _ -> (
          match !(r.var) with
          | V.Float i ->
              let i = i +. r.step in
              r.var := V.Float i;
              if (r.step > 0. && i <= r.stop +. 1e-10) || (r.step < 0. && i >= r.stop -. 1e-10) then Lexer.reset f.lx r.body
              else pop_cond st
          | v -> Error.raise_at r.floc "the #for variable was changed to %s inside the loop" (V.kind_name v))
      | [] -> (
          match f.kind with
          | Macro_body _ ->
              st.frames <- List.tl st.frames;
              st.tables <- List.tl st.tables;
              st.macro_depth <- st.macro_depth - 1
          | Main | Included _ -> Error.raise_at loc "'#end' without a matching #if, #while, #for, #switch or #macro"))
  | "while" ->
      let m = Lexer.mark f.lx in
      if truth (cond_value st "while") then push_cond st (While_loop (m, loc)) else skip_to_end st loc "#while"
  | "for" ->
      expect st LParen "'(' after '#for'";
      st.no_expand <- true;
      let k = Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st) in
      let name = match k with Ident s when not (is_keyword s) -> advance st; s | _ -> unexpected st "the loop variable of '#for'" in
      expect st Comma "',' after the #for variable";
      let start = parse_float st in
      expect st Comma "',' after the start value of '#for'";
      let stop = parse_float st in
      let sl = peek_loc st in
      let step = if accept st Comma then parse_float st else 1. in
      expect st RParen "')' closing '#for'";
      assign st ~local:true name (V.Float start);
      let var = Option.get (lookup_cell st name) in
      if Float.abs step < 1e-10 then Error.raise_at sl "the step of '#for' must not be 0";
      if (step > 0. && start < stop +. 1e-10) || (step < 0. && start > stop -. 1e-10) then
        push_cond st (For_loop { var; stop; step; body = Lexer.mark f.lx; floc = loc })
      else skip_to_end st loc "#for"
  | "switch" ->
      let v = cond_value st "switch" in
      let sw = Switch_case { value = v; running = false; sloc = loc } in
      push_cond st sw;
      find_case st sw
  | "case" | "range" -> (
      match f.conds with
      | Switch_case { running = true; _ } :: _ ->
          (* no #break before it: execution falls through *)
          if d = "case" then ignore (cond_value st "case") else ignore (range_args st)
      | _ -> Error.raise_at loc "'#%s' outside a #switch" d)
  | "break" -> (
      (* leave the innermost #switch, #while or #for, closing the branches opened inside it *)
      let rec out conds skipped =
        match conds with
        | (If_branch _) :: rest -> out rest (skipped + 1)
        | (Switch_case _ | While_loop _ | For_loop _) :: rest ->
            f.conds <- rest;
            for _ = 0 to skipped do skip_to_end st loc "#break" done
        | [] -> (
            match f.kind with
            | Macro_body _ ->
                (* #break in a macro returns from it *)
                st.frames <- List.tl st.frames;
                st.tables <- List.tl st.tables;
                st.macro_depth <- st.macro_depth - 1
            | Main | Included _ -> Error.raise_at loc "'#break' outside a #switch, #while, #for or macro")
      in
      out f.conds 0)
  | "macro" ->
      st.no_expand <- true;
      let k = Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st) in
      let name = match k with Ident s when not (is_keyword s) -> advance st; s | _ -> unexpected st "a macro name after '#macro'" in
      expect st LParen (Printf.sprintf "'(' after the macro name '%s'" name);
      let rec params acc =
        st.no_expand <- true;
        let k = Fun.protect ~finally:(fun () -> st.no_expand <- false) (fun () -> peek st) in
        match k with
        | RParen -> advance st; List.rev acc
        | Ident p when not (is_keyword p) ->
            advance st;
            ignore (accept st Comma);
            params (p :: acc)
        | _ -> unexpected st "a parameter name or ')'"
      in
      let params = params [] in
      let m = { V.mname = name; params; source = f.lx; body = Lexer.mark f.lx; mloc = loc } in
      skip_to_end st loc (Printf.sprintf "#macro %s" name);
      Names.replace st.global name (ref (V.Macro m))
  | "debug" -> st.opts.debug (string_arg st "debug")
  | "warning" -> let s = string_arg st "warning" in warn st loc "%s" s
  | "error" -> let s = string_arg st "error" in Error.raise_at loc "#error: %s" s
  | "default" ->
      open_block st "#default";
      let rec loop () =
        let l = peek_loc st in
        match peek st with
        | RBrace -> advance st
        | Ident "texture" -> advance st; st.default_texture <- parse_texture st st.default_texture; loop ()
        | Ident "pigment" -> advance st; st.default_texture <- { st.default_texture with pigment = parse_pigment st st.default_texture.pigment }; loop ()
        | Ident "finish" -> advance st; st.default_texture <- { st.default_texture with finish = parse_finish st st.default_texture.finish }; loop ()
        | Ident s when List.mem s [ "normal"; "radiosity"; "media" ] -> not_supported l (Printf.sprintf "'%s' in #default" s)
        | _ -> unexpected st "'texture', 'pigment', 'finish' or '}' in #default"
      in
      loop ()
  | "fopen" | "fclose" | "read" | "write" -> not_supported loc (Printf.sprintf "'#%s'" d)
  | "render" | "statistics" -> st.opts.debug (string_arg st d)
  | _ -> (
      match Suggest.nearest d directive_names with
      | [] -> Error.raise_at loc "unknown directive '#%s'" d
      | s -> Error.raise_at loc "unknown directive '#%s'; did you mean %s?" d (String.concat " or " (List.map (Printf.sprintf "'#%s'") s)))

(* A macro call (§11.3): the arguments are read in the caller, an identifier standing alone is
   passed by reference, then the body is read in a table of its own. *)
let invoke st (m : V.macro) loc =
  if st.macro_depth >= max_macro_depth then
    Error.raise_at loc "macro calls are nested more than %d deep (does '%s' call itself without end?)" max_macro_depth m.mname;
  expect st LParen (Printf.sprintf "'(' after the macro name '%s'" m.mname);
  let table = Names.create 8 in
  let nparams = List.length m.params in
  List.iteri
    (fun i p ->
      if peek st == RParen then
        raise
          (Error.Scene_error
             { loc = peek_loc st; msg = Printf.sprintf "macro '%s' takes %d argument%s, this call gives %d" m.mname nparams (if nparams = 1 then "" else "s") i; notes = [ (m.mloc, "the macro is defined here") ] });
      if i > 0 then expect st Comma "',' between macro arguments";
      let by_ref =
        match peek st with
        | Ident s when st.cur_elem = None -> (
            match lookup_cell st s with
            | Some c when (match Lexer.next_char (top st).lx with Some (',' | ')') -> true | _ -> false) -> advance st; Some c
            | _ -> None)
        | _ -> None
      in
      let cell = match by_ref with Some c -> c | None -> ref (fst (parse_rvalue st)) in
      Names.replace table p cell)
    m.params;
  if peek st != RParen then
    raise
      (Error.Scene_error
         { loc = peek_loc st; msg = Printf.sprintf "too many arguments for macro '%s', which takes %d" m.mname nparams; notes = [ (m.mloc, "the macro is defined here") ] });
  advance st;
  st.tables <- table :: st.tables;
  st.frames <- { lx = Lexer.at m.source m.body; kind = Macro_body (m.mname, loc); conds = [] } :: st.frames;
  st.macro_depth <- st.macro_depth + 1

(* ---------------------------------------------------------------------------------------------- *)
(* Statements *)

let rec parse_statements st =
  let loc = peek_loc st in
  match peek st with
  | Eof -> ()
  | Ident "camera" ->
      advance st;
      if st.camera <> None then warn st loc "more than one camera in scene; ignoring previous camera(s)";
      st.camera <- Some (parse_camera st);
      parse_statements st
  | Ident "light_source" -> st.lights <- parse_light st :: st.lights; parse_statements st
  | Ident "background" -> parse_background st; parse_statements st
  | Ident "sky_sphere" -> parse_sky_sphere st; parse_statements st
  | Ident "global_settings" -> advance st; parse_global_settings st; parse_statements st
  | _ when object_follows st -> add_object st (parse_object st); parse_statements st
  | _ -> unexpected st "an object, light_source, camera or directive"

let finish_scene st : Scene.t =
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
    | None -> if version >= 370 then Colour.black else { Colour.black with transmit = 1. }
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
    version;
    gamma;
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

let load_string opts ~file text =
  let lexer = Lexer.create ~file text in
  let global = Names.create 256 in
  let st =
    {
      frames = [ { lx = lexer; kind = Main; conds = [] } ];
      cur = { Token.kind = Eof; loc = Loc.none }; have = false; cur_elem = None; no_expand = false; defer = false; streams = [||];
      depth = 0; opts; global; tables = [ global ]; includes = 0; macro_depth = 0;
      version = 370; version_set = false; warnings = [];
      objects = []; lights = []; camera = None; background = None; sky = None;
      assumed_gamma = None; max_trace_level = 5; adc_bailout = 1. /. 255.; ambient_light = Rgb.white;
      default_texture = Defaults.texture;
      directive = (fun _ _ _ -> ()); invoke = (fun _ _ _ -> ()); index = (fun _ _ -> 0);
    }
  in
  st.directive <- directive;
  st.invoke <- invoke;
  st.index <- parse_index;
  (try parse_statements st with
  | Unsupported (loc, what, notes) ->
      raise (Error.Scene_error { loc; msg = "not supported yet: " ^ what; notes = notes @ chain st })
  | Error.Scene_error e -> raise (Error.Scene_error { e with notes = e.notes @ chain st }));
  let scene = finish_scene st in
  (scene, List.rev st.warnings)

let default_options ~width ~height =
  {
    width;
    height;
    clock = 0.;
    library_paths = [];
    debug = (fun s -> prerr_string s; flush stderr);
    included = (fun _ ~depth:_ _ -> ());
  }

let load_file opts path = load_string opts ~file:path (read_file path)
