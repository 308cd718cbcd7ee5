(* The interpreter: a recursive-descent reader of the token array that evaluates as it goes, the way
   POV-Ray does, and builds an immutable Scene.t. The parser state is private to one [load] call. *)

open Token
module V = Value

type options = { width : int; height : int }

type camera_spec = {
  c_location : Vec.t option;
  c_direction : Vec.t option;
  c_up : Vec.t option;
  c_right : Vec.t option;
  c_sky : Vec.t option;
  c_look_at : (Vec.t * Loc.t) option;
  c_angle : (float * Loc.t) option;
  c_translate : Vec.t;
}

type st = {
  lexer : Lexer.t;
  mutable cur : Token.t;  (* the next token *)
  mutable ahead : Token.t option;  (* the one after it, once peeked *)
  opts : options;
  table : (string, V.t) Hashtbl.t;
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
    "parametric"; "bicubic_patch"; "ovus"; "quadric"; "cubic"; "quartic"; "poly"; "union"; "intersection";
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

let unsupported_directives =
  [ "include"; "macro"; "if"; "ifdef"; "ifndef"; "else"; "elseif"; "end"; "while"; "for"; "switch"; "case";
    "range"; "break"; "undef"; "default"; "debug"; "warning"; "error"; "fopen"; "fclose"; "read"; "write";
    "render"; "statistics" ]

let is_keyword s = List.mem s keywords || List.mem s unsupported

(* ---------------------------------------------------------------------------------------------- *)
(* Token access *)

let peek st = st.cur.kind
let peek_loc st = st.cur.loc

let peek2 st =
  match st.ahead with
  | Some t -> t.kind
  | None ->
      let t = Lexer.next st.lexer in
      st.ahead <- Some t;
      t.kind

let advance st =
  match st.ahead with
  | Some t -> st.cur <- t; st.ahead <- None
  | None -> if st.cur.kind != Eof then st.cur <- Lexer.next st.lexer

let warn st loc fmt = Printf.ksprintf (fun msg -> st.warnings <- { Error.loc; msg; notes = [] } :: st.warnings) fmt

let not_supported loc what = Error.raise_at loc "not supported yet: %s" what

let unknown_identifier st loc name =
  let candidates = Hashtbl.fold (fun k _ acc -> k :: acc) st.table [] @ keywords in
  match Suggest.nearest name candidates with
  | [] -> Error.raise_at loc "unknown identifier '%s'" name
  | s -> Error.raise_at loc "unknown identifier '%s'; did you mean %s?" name (String.concat " or " (List.map (Printf.sprintf "'%s'") s))

let unexpected st what =
  let k = peek st in
  match k with
  | Ident s when List.mem s unsupported -> not_supported (peek_loc st) (Printf.sprintf "'%s'" s)
  | Ident s when (not (is_keyword s)) && not (Hashtbl.mem st.table s) -> (
      let candidates = Hashtbl.fold (fun k _ acc -> k :: acc) st.table [] @ keywords in
      match Suggest.nearest s candidates with
      | [] -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k)
      | sug ->
          Error.raise_at (peek_loc st) "expected %s but found %s; did you mean %s?" what (describe k)
            (String.concat " or " (List.map (Printf.sprintf "'%s'") sug)))
  | Directive d when List.mem d unsupported_directives -> not_supported (peek_loc st) (Printf.sprintf "'#%s'" d)
  | _ -> Error.raise_at (peek_loc st) "expected %s but found %s" what (describe k)

(* [k] is always a constant constructor here, so physical equality is the cheap, exact test *)
let expect st k what = if peek st == k then advance st else unexpected st what
let accept st k = if peek st == k then (advance st; true) else false
let is_ident st s = match peek st with Ident i -> String.equal i s | _ -> false

let accept_ident st s =
  if is_ident st s then (advance st; true) else false

let lookup st name = Hashtbl.find_opt st.table name

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

let is_colour_start st =
  match peek st with
  | Ident s when List.mem s colour_keywords -> true
  | Ident s -> ( match lookup st s with Some (V.Colour _) -> true | _ -> false)
  | _ -> false

let truth x = Float.abs x > 1e-10

let rec parse_expr st =
  (* additive level; relational and logical operators only inside parentheses *)
  expr_rest st (parse_term st)

and expr_rest st lhs =
  match peek st with
  | Plus -> let loc = peek_loc st in advance st; expr_rest st (binop st loc ( +. ) lhs (parse_term st))
  | Minus -> let loc = peek_loc st in advance st; expr_rest st (binop st loc ( -. ) lhs (parse_term st))
  | _ -> lhs

and parse_term st = term_rest st (parse_unary st)

and term_rest st lhs =
  match peek st with
  | Star -> let loc = peek_loc st in advance st; term_rest st (binop st loc ( *. ) lhs (parse_unary st))
  | Slash ->
      let loc = peek_loc st in
      advance st;
      let rhs = parse_unary st in
      let divided = ref false in
      let div a b = if b = 0. then (divided := true; 1e17) else a /. b in
      let r = binop st loc div lhs rhs in
      if !divided then warn st loc "division by zero; the result is 1e17";
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

and parse_postfix st =
  let v = parse_primary st in
  let rec loop v =
    match (peek st, peek2 st) with
    | Dot, Ident c ->
        let loc = peek_loc st in
        advance st;
        advance st;
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
        loop r
    | _ -> v
  in
  loop v

and parse_full st =
  (* inside parentheses: ?:, & |, relational (§11.2) *)
  let c = parse_logical st in
  if peek st == Quest then begin
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
    match peek st with
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
  let lhs = parse_expr st in
  let rel f =
    let loc = peek_loc st in
    advance st;
    let rhs = parse_expr st in
    logic loc f lhs rhs
  in
  match peek st with
  | Lt -> rel (fun a b -> a < b)
  | Le -> rel (fun a b -> a <= b)
  | Gt -> rel (fun a b -> a > b)
  | Ge -> rel (fun a b -> a >= b)
  | Eq -> rel (fun a b -> Float.abs (a -. b) <= 1e-10)
  | Ne -> rel (fun a b -> Float.abs (a -. b) > 1e-10)
  | _ -> lhs

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
  | "clock" -> advance st; V.Float 0.
  | "version" -> advance st; V.Float (float_of_int st.version /. 100.)
  | _ when List.mem name colour_keywords -> V.Colour (colour_array (parse_colour st))
  | _ when List.mem name function_names -> parse_function st loc name
  | _ -> (
      match lookup st name with
      | Some ((V.Float _ | V.Vector _ | V.Colour _ | V.String _) as v) -> advance st; v
      | Some v -> Error.raise_at loc "expected a numeric expression but '%s' is %s" name (V.kind_name v)
      | None ->
          if List.mem name unsupported then not_supported loc (Printf.sprintf "'%s'" name)
          else if is_keyword name then Error.raise_at loc "expected a numeric expression but found '%s'" name
          else unknown_identifier st loc name)

and function_names =
  [ "abs"; "sqrt"; "sqr"; "sin"; "cos"; "tan"; "asin"; "acos"; "atan"; "atan2"; "pow"; "exp"; "ln"; "log"; "min";
    "max"; "int"; "floor"; "ceil"; "mod"; "div"; "radians"; "degrees"; "vlength"; "vnormalize"; "vdot"; "vcross";
    "select" ]

and parse_function st loc name =
  advance st;
  expect st LParen (Printf.sprintf "'(' after '%s'" name);
  let rec args acc =
    let a = (peek_loc st, parse_full st) in
    if accept st Comma then args (a :: acc) else List.rev (a :: acc)
  in
  let args = args [] in
  expect st RParen (Printf.sprintf "')' closing the arguments of '%s'" name);
  let float_arg (l, v) = match v with V.Float f -> f | v -> Error.raise_at l "'%s' expects a float argument, not %s" name (V.kind_name v) in
  let vec_arg (l, v) =
    match v with
    | V.Float _ | V.Vector _ | V.Colour _ -> let a = V.promote v 3 in Vec.make a.(0) a.(1) a.(2)
    | v -> Error.raise_at l "'%s' expects a vector argument, not %s" name (V.kind_name v)
  in
  let arity n = if List.length args <> n then Error.raise_at loc "'%s' takes %d argument%s, not %d" name n (if n = 1 then "" else "s") (List.length args) in
  let f1 f = arity 1; V.Float (f (float_arg (List.hd args))) in
  let f2 f = arity 2; V.Float (f (float_arg (List.nth args 0)) (float_arg (List.nth args 1))) in
  let of_vec (v : Vec.t) = V.Vector [| v.x; v.y; v.z |] in
  match name with
  | "abs" -> f1 Float.abs
  | "sqrt" -> f1 sqrt
  | "sqr" -> f1 (fun x -> x *. x)
  | "sin" -> f1 sin
  | "cos" -> f1 cos
  | "tan" -> f1 tan
  | "asin" | "acos" ->
      (* §11.2: the argument is clamped to ±1 with a warning *)
      let f = if name = "asin" then asin else acos in
      f1 (fun x ->
          if x < -1. || x > 1. then warn st loc "domain error in '%s': %g is clamped to the range -1 … 1" name x;
          f (Float.max (-1.) (Float.min 1. x)))
  | "atan" -> f1 atan
  | "atan2" -> f2 Float.atan2
  | "pow" ->
      f2 (fun a b -> if a = 0. && b = 0. then Error.raise_at loc "pow(0, 0) is undefined" else Float.pow a b)
  | "exp" -> f1 exp
  | "ln" -> f1 log
  | "log" -> f1 log10
  | "int" -> f1 Float.trunc
  | "floor" -> f1 floor
  | "ceil" -> f1 ceil
  | "mod" -> f2 Float.rem
  | "div" -> f2 (fun a b -> Float.trunc (a /. b))
  | "radians" -> f1 (fun d -> d *. Float.pi /. 180.)
  | "degrees" -> f1 (fun r -> r *. 180. /. Float.pi)
  | "min" | "max" ->
      if args = [] then Error.raise_at loc "'%s' needs at least one argument" name;
      let fs = List.map float_arg args in
      V.Float (List.fold_left (if name = "min" then Float.min else Float.max) (List.hd fs) fs)
  | "vlength" -> arity 1; V.Float (Vec.length (vec_arg (List.hd args)))
  | "vnormalize" ->
      arity 1;
      let a = vec_arg (List.hd args) in
      if Vec.length a = 0. then warn st loc "normalizing zero-length vector; the result is <0,0,0>";
      of_vec (Vec.normalize a)
  | "vdot" -> arity 2; V.Float (Vec.dot (vec_arg (List.nth args 0)) (vec_arg (List.nth args 1)))
  | "vcross" -> arity 2; of_vec (Vec.cross (vec_arg (List.nth args 0)) (vec_arg (List.nth args 1)))
  | "select" ->
      if List.length args <> 3 && List.length args <> 4 then Error.raise_at loc "'select' takes 3 or 4 arguments";
      let c = float_arg (List.hd args) in
      let pick i = snd (List.nth args i) in
      if List.length args = 3 then if c < 0. then pick 1 else pick 2
      else if c < 0. then pick 1
      else if c = 0. then pick 2
      else pick 3
  | _ -> Error.raise_at loc "unknown function '%s'" name

and parse_float st =
  (* A plain number that ends a list item or a vector needs no expression machinery: the fast path
     for the millions of numbers of a mesh. *)
  let ends = function Comma | Gt | RBrace | Semi | RParen -> true | _ -> false in
  match peek st with
  | Num f when ends (peek2 st) -> advance st; f
  | Minus when (match peek2 st with Num _ -> true | _ -> false) -> (
      advance st;
      match peek st with
      | Num f when ends (peek2 st) -> advance st; -.f
      | _ -> (
          (* the minus applies to a longer operand: negate the rest of the unary operand *)
          let loc = peek_loc st in
          match numeric_map loc (fun x -> -.x) (parse_unary st) |> term_rest st |> expr_rest st with
          | V.Float f -> f
          | v -> Error.raise_at loc "expected a float but found %s" (V.kind_name v)))
  | _ -> (
      let loc = peek_loc st in
      match parse_expr st with
      | V.Float f -> f
      | v -> Error.raise_at loc "expected a float but found %s" (V.kind_name v))

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
      | Ident s when List.mem s colour_keywords -> ()
      | _ -> let loc = peek_loc st in ignore (set_terms loc 5 (parse_expr st)))
  | Ident s when not (List.mem s colour_keywords) -> (
      match lookup st s with
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
  | Ident s -> ( match lookup st s with Some (V.Float _) -> true | _ -> List.mem s function_names || List.mem s [ "pi"; "true"; "false"; "yes"; "no"; "on"; "off"; "clock"; "version"; "image_width"; "image_height" ])
  | _ -> false

let parse_bool_opt st = if float_follows st then truth (parse_float st) else true

(* ---------------------------------------------------------------------------------------------- *)
(* Textures *)

let open_block st what = expect st LBrace (Printf.sprintf "'{' after '%s'" what)

let close_block st what = expect st RBrace (Printf.sprintf "'}' closing '%s' or one of its keywords" what)

let ident_of_kind st f =
  match peek st with
  | Ident s -> ( match lookup st s with Some v -> (match f v with Some r -> advance st; Some r | None -> None) | None -> None)
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
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in a pigment" s)
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
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in reflection" s)
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
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in a finish" s)
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
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in a texture" s)
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
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in an interior" s)
    | _ -> unexpected st "'ior', 'fade_distance', 'fade_power', 'fade_color' or '}' in an interior"
  in
  loop i

(* ---------------------------------------------------------------------------------------------- *)
(* Objects *)

let translate_shape (s : Scene.shape) (v : Vec.t) : Scene.shape = Place.shape s (Translate v)

let parse_object_mods st (o : V.obj) what : V.obj =
  let tex o = match o.V.texture with Some t -> t | None -> Defaults.texture in
  let rec loop (o : V.obj) =
    let loc = peek_loc st in
    match peek st with
    | RBrace -> advance st; o
    | Ident "pigment" -> advance st; let t = tex o in loop { o with texture = Some { t with pigment = parse_pigment st t.pigment } }
    | Ident "finish" -> advance st; let t = tex o in loop { o with texture = Some { t with finish = parse_finish st t.finish } }
    | Ident "texture" ->
        advance st;
        if o.texture <> None then not_supported loc "layered textures (a texture added to an object that has one)";
        loop { o with texture = Some (parse_texture st Defaults.texture) }
    | Ident "interior" ->
        advance st;
        let base = match o.interior with Some i -> i | None -> Defaults.interior in
        loop { o with interior = Some (parse_interior st base) }
    | Ident "translate" -> advance st; let v = parse_vector st in loop { o with shape = translate_shape o.shape v }
    | Ident "no_shadow" -> advance st; loop { o with no_shadow = true }
    | Ident "hollow" -> advance st; ignore (parse_bool_opt st); loop o
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s'" s)
    | _ -> unexpected st (Printf.sprintf "an object modifier or '}' closing '%s'" what)
  in
  loop o

let new_obj shape loc = { V.shape; texture = None; interior = None; no_shadow = false; oloc = loc }

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
  st.cur.kind == Lt && Option.is_none st.ahead && Lexer.scan_vector3 st.lexer out
  && begin st.cur <- Lexer.next st.lexer; true end

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
  parse_texture st Defaults.texture

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
        | Ident s -> (
            match lookup st s with
            | Some (V.Object o) -> advance st; { o with oloc = loc }
            | Some v -> Error.raise_at iloc "'%s' is %s, not an object" s (V.kind_name v)
            | None -> if is_keyword s then unexpected st "an object identifier" else unknown_identifier st iloc s)
        | _ -> unexpected st "an object identifier"
      in
      parse_object_mods st o "object"
  | Ident s -> (
      match lookup st s with
      | Some (V.Object o) -> advance st; { o with oloc = loc }
      | _ -> unexpected st "an object")
  | _ -> unexpected st "an object"

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
                if peek st == Comma && (match peek2 st with Num _ -> true | _ -> false) then begin
                  advance st;
                  let tl = peek_loc st in
                  let t = parse_float st in
                  if peek st == Comma && (match peek2 st with Num _ -> true | _ -> false) then
                    not_supported tl "three texture indices per face (interpolated textures)";
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
let finish_object (o : V.obj) : Scene.obj =
  let texture = match o.texture with Some t -> t | None -> Defaults.texture in
  let interior = match o.interior with Some i -> i | None -> Defaults.interior in
  let interior = match texture.finish.legacy_ior with Some ior -> { interior with ior } | None -> interior in
  let interior = if interior.ior = 0. then { interior with ior = 1. } else interior in
  { Scene.shape = o.shape; texture; interior; no_shadow = o.no_shadow; loc = o.oloc }

(* ---------------------------------------------------------------------------------------------- *)
(* Camera, lights, settings *)

let empty_camera =
  { c_location = None; c_direction = None; c_up = None; c_right = None; c_sky = None; c_look_at = None; c_angle = None; c_translate = Vec.zero }

let parse_camera st =
  open_block st "camera";
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
    | Ident "translate" -> advance st; loop { c with c_translate = Vec.add c.c_translate (parse_vector st) }
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in a camera" s)
    | _ -> unexpected st "a camera keyword or '}'"
  in
  st.camera <- Some (loop empty_camera)

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
  { Scene.location = Vec.add location c.c_translate; direction; up; right }

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
    | Ident "translate" -> advance st; loop { l with position = Vec.add l.position (parse_vector st) }
    | Ident ("color" | "colour" | "rgb") -> loop { l with colour = parse_rgb st "a light colour" }
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in a light_source" s)
    | _ -> unexpected st "a light_source keyword or '}'"
  in
  let l = loop { Scene.position; colour; shadowless = false; fade_distance = 0.; fade_power = 0. } in
  st.lights <- l :: st.lights

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
    | Ident s when List.mem s unsupported -> not_supported loc (Printf.sprintf "'%s' in global_settings" s)
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
    | Ident s when List.mem s unsupported -> not_supported l (Printf.sprintf "'%s' in a sky_sphere" s)
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

let parse_declare st =
  let dloc = peek_loc st in
  advance st;
  let nloc = peek_loc st in
  let name =
    match peek st with
    | Ident s when is_keyword s -> Error.raise_at nloc "'%s' is a keyword and cannot be declared" s
    | Ident s -> advance st; s
    | _ -> unexpected st "an identifier to declare"
  in
  ignore dloc;
  expect st Eq (Printf.sprintf "'=' after '%s'" name);
  let rloc = peek_loc st in
  let value, needs_semi =
    match peek st with
    | Ident ("sphere" | "plane" | "object" | "triangle" | "smooth_triangle" | "mesh" | "mesh2") -> (V.Object (parse_object st), false)
    | Ident "pigment" -> advance st; (V.Pigment (parse_pigment st (Scene.Solid Colour.black)), false)
    | Ident "finish" -> advance st; (V.Finish (parse_finish st Defaults.finish), false)
    | Ident "texture" -> advance st; (V.Texture (parse_texture st Defaults.texture), false)
    | Ident "interior" -> advance st; (V.Interior (parse_interior st Defaults.interior), false)
    | Ident s -> (
        match lookup st s with
        | Some (V.Object o) -> advance st; (V.Object { o with oloc = rloc }, false)
        | Some ((V.Pigment _ | V.Finish _ | V.Texture _ | V.Interior _) as v) -> advance st; (v, false)
        | _ -> (parse_expr st, true))
    | _ -> (parse_expr st, true)
  in
  if needs_semi && not (accept st Semi) then
    if st.version >= 350 then
      warn st (peek_loc st) "all #declares of float, vector, and color require semicolon ';' at end if the language version is 3.5 or higher"
    else ()
  else ignore (accept st Semi);
  Hashtbl.replace st.table name value

let rec parse_statements st =
  let loc = peek_loc st in
  match peek st with
  | Eof -> ()
  | Directive "version" ->
      advance st;
      let v = parse_float st in
      ignore (accept st Semi);
      st.version <- int_of_float ((v *. 100.) +. 0.5);
      st.version_set <- true;
      parse_statements st
  | Directive ("declare" | "local") -> parse_declare st; parse_statements st
  | Directive d when List.mem d unsupported_directives -> not_supported loc (Printf.sprintf "'#%s'" d)
  | Directive d -> Error.raise_at loc "unknown directive '#%s'" d
  | Ident "camera" ->
      advance st;
      if st.camera <> None then warn st loc "more than one camera in scene; ignoring previous camera(s)";
      parse_camera st;
      parse_statements st
  | Ident "light_source" -> parse_light st; parse_statements st
  | Ident "background" -> parse_background st; parse_statements st
  | Ident "sky_sphere" -> parse_sky_sphere st; parse_statements st
  | Ident "global_settings" -> advance st; parse_global_settings st; parse_statements st
  | Ident ("sphere" | "plane" | "object" | "triangle" | "smooth_triangle" | "mesh" | "mesh2") ->
      st.objects <- finish_object (parse_object st) :: st.objects;
      parse_statements st
  | Ident s when (match lookup st s with Some (V.Object _) -> true | _ -> false) ->
      st.objects <- finish_object (parse_object st) :: st.objects;
      parse_statements st
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

let load_string opts ~file text =
  let lexer = Lexer.create ~file text in
  let cur = Lexer.next lexer in
  let st =
    {
      lexer; cur; ahead = None; opts; table = Hashtbl.create 64; version = 370; version_set = false; warnings = [];
      objects = []; lights = []; camera = None; background = None; sky = None;
      assumed_gamma = None; max_trace_level = 5; adc_bailout = 1. /. 255.; ambient_light = Rgb.white;
    }
  in
  parse_statements st;
  let scene = finish_scene st in
  (scene, List.rev st.warnings)

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

let load_file opts path = load_string opts ~file:path (read_file path)
