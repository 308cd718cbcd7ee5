(* Expressions (docs/povray-rules.md §11.2): floats, vectors, colours, strings, the built-in functions and
   the transformations. *)

open Token
open Reader


let component_index = function
  | "x" | "u" | "red" -> Some 0
  | "y" | "v" | "green" -> Some 1
  | "z" | "blue" -> Some 2
  | "t" | "filter" -> Some 3
  | "transmit" -> Some 4
  | _ -> None

let colour_keywords =
  [ "color"; "colour"; "rgb"; "rgbf"; "rgbt"; "rgbft"; "srgb"; "srgbf"; "srgbt"; "srgbft"; "red"; "green"; "blue"; "filter"; "transmit";
    "alpha" ]
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
    "seed"; "rand"; "bitwise_and"; "bitwise_or"; "bitwise_xor"; "vturbulence"; "vrotate"; "vaxis_rotate"; "str"; "vstr";
    "concat"; "substr"; "chr"; "asc"; "strlen"; "strupr"; "strlwr"; "val"; "strcmp"; "file_exists" ]

let unsupported_functions = [ "datetime" ]

let function_set = set_of function_names
let object_set = set_of (Keywords.words (fun s -> s = Keywords.Object))

let truth x = Float.abs x > 1e-10

(* sRGB colours (srgb, srgbf, srgbt, srgbft): POV-Ray 3.7 decodes the red, green and blue terms
   from sRGB into the working colour space of assumed_gamma, in single precision (Parse_Colour in
   express.cpp with workingGammaToSRGB, the gamma curves of base/image/colourspace.cpp). *)
let srgb_to_linear x =
  let f = Precision.f32 in
  (* SRGBGammaCurve::Decode *)
  if x < f 0.04045 then f (x /. f 12.92) else f (Float.pow (f (f (x +. f 0.055) /. f 1.055)) (f 2.4))

(* The working gamma's curve, as TranscodingGammaCurve::Get builds it for assumed_gamma G: the
   power law of encoding exponent 1/G (in single precision) is neutral within 1% of 1
   (PowerLawGammaCurve::IsNeutral), and then the sRGB value is only made linear; otherwise the
   linear value is encoded with x^(1/G). *)
let srgb_decode ~assumed_gamma x =
  let f = Precision.f32 in
  let enc = f (1. /. f assumed_gamma) in
  let linear = srgb_to_linear (f x) in
  if Float.abs (1. -. enc) <= 0.01 then linear else f (Float.pow (Float.max linear 0.) enc)

(* C's (double)(int)x on x86 (checked with POV-Ray) *)
let c_int = C_float.int_cast

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
  | Minus -> let loc = peek_loc st in advance st; numeric_map loc (fun x -> -.x) (nest st loc (fun () -> parse_unary st))
  | Plus -> let loc = peek_loc st in advance st; nest st loc (fun () -> parse_unary st)
  | Bang -> let loc = peek_loc st in advance st; numeric_map loc (fun x -> if truth x then 0. else 1.) (nest st loc (fun () -> parse_unary st))
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
    | Le -> rel (fun a b -> a < b || Float.abs (a -. b) < Precision.epsilon)
    | Gt -> rel (fun a b -> a > b)
    | Ge -> rel (fun a b -> a > b || Float.abs (a -. b) < Precision.epsilon)
    | Eq -> rel (fun a b -> Float.abs (a -. b) < Precision.epsilon)
    | Ne -> rel (fun a b -> Float.abs (a -. b) >= Precision.epsilon)
    | _ -> lhs
  in
  loop (parse_expr st)

and parse_primary st =
  let loc = peek_loc st in
  match peek st with
  | Num f -> advance st; V.Float f
  | LParen ->
      advance st;
      let v = nest st loc (fun () -> parse_full st) in
      expect st RParen "')'";
      v
  | Lt -> nest st loc (fun () -> parse_vector_literal st loc)
  | Str s -> advance st; V.String s
  | Ident name -> parse_ident_value st loc name
  | k -> ignore k; unexpected st "a numeric expression"

and parse_vector_literal st loc =
      advance st;
      let first = parse_float st in
      (* the commas between terms are optional, as everywhere in POV-Ray: <0 20 0> is <0,20,0>
         (and <1 -2 3> is <1-2, 3>) *)
      let rec terms acc n =
        let comma = accept st Comma in
        (* a comma may also follow the second, third or fourth term: <1,0,0,> is <1,0,0> (POV-Ray's
           Parse_Num_Factor, express.cpp: Parse_Comma after each of those terms, none after the fifth) *)
        let term_follows () = match peek st with Num _ | LParen | Ident _ | Plus | Minus | Lt -> true | _ -> false in
        if comma && n >= 2 && n <= 4 && peek st == Gt then acc
        else if n >= 5 && (not comma) && term_follows () then
          (* no comma is looked for after the fifth term, and a term after it replaces it:
             <1,2,3,4,5 6> is <1,2,3,4,6> (checked with POV-Ray) *)
          terms (parse_float st :: List.tl acc) n
        else if comma || term_follows () then begin
          if n >= 5 then Error.raise_at (peek_loc st) "a vector has at most 5 terms";
          terms (parse_float st :: acc) (n + 1)
        end
        else acc
      in
      let ts = List.rev (terms [ first ] 1) in
      if List.length ts < 2 then Error.raise_at loc "a vector needs at least 2 terms";
      expect st Gt "',' or '>' in a vector";
      V.Vector (Array.of_list ts)

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
  | "clock_on" -> advance st; V.Float (if st.opts.animation.clock_on then 1. else 0.)
  | "clock_delta" | "frame_number" | "initial_clock" | "final_clock" | "initial_frame" | "final_frame" ->
      advance st;
      (* POV-Ray's front end declares them for every render; a still's are 0 *)
      let a = st.opts.animation in
      V.Float
        (match name with
        | "clock_delta" -> a.clock_delta
        | "frame_number" -> float_of_int a.frame_number
        | "initial_clock" -> a.initial_clock
        | "final_clock" -> a.final_clock
        | "initial_frame" -> float_of_int a.initial_frame
        | _ -> float_of_int a.final_frame)
  | "version" -> advance st; V.Float (float_of_int st.version /. 100.)
  | "now" ->
      advance st;
      (* days since 2000-01-01 00:00 UTC *)
      V.Float ((Unix.gettimeofday () -. 946684800.) /. 86400.)
  | "input_file_name" -> advance st; V.String (main_file st)
  | _ when Names.mem colour_set name -> V.Colour (colour_array (parse_colour st))
  | _ when Names.mem function_set name -> parse_function st loc name
  | "trace" | "inside" | "min_extent" | "max_extent" when cur_value st name = None -> parse_probe st name
  | _ -> (
      match cur_value st name with
      | Some ((V.Float _ | V.Vector _ | V.Colour _ | V.String _) as v) -> advance st; v
      | Some (V.Unsupported u) -> unsupported_use loc name u.what u.at
      | Some (V.Function f) -> Fn_reader.sdl_call st f loc ~parse_float
      | Some (V.Spline sp) -> Fn_special.spline_call st sp ~parse_float
      | Some v -> Error.raise_at loc "expected a numeric expression but '%s' is %s" name (V.kind_name v)
      | None ->
          if List.mem name unsupported_functions then not_supported loc (Printf.sprintf "the function '%s'" name)
          else if is_unsupported name then not_supported loc (Printf.sprintf "'%s'" name)
          else if is_keyword name then Error.raise_at loc "expected a numeric expression but found '%s'" name
          else unknown_identifier st loc name)

(* trace(), inside(), min_extent(), max_extent(): Probe reads them, its vectors read here *)
and parse_probe st name = Probe.parse st name ~vector:parse_vector

(* The argument of defined(…) and #ifdef: an identifier (or array element) that is not evaluated. *)
and parse_defined_arg st =
  let k = peek_name st in
  match k with
  | Ident s ->
      let d =
        match st.cur_elem with
        | Some (a, i) -> a.cells.(i) <> None
        | None ->
            lookup st s <> None
            || List.mem s [ "x"; "y"; "z"; "t"; "u"; "v"; "pi"; "clock"; "version" ]
            (* the identifiers POV-Ray's front end declares for every render *)
            || List.mem s [ "image_width"; "image_height"; "clock_delta"; "frame_number"; "initial_frame"; "final_frame"; "initial_clock"; "final_clock" ]
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
  (* str and vstr pad each number to |L| characters and print P digits after the point, so a
     string of about |L| + P bytes a number; it must fit in the memory limit before it is made (a width
     of 2^31 took 12 s and 2 GiB; found by fuzzing). POV-Ray prints into a fixed buffer. *)
  let string_room terms l p =
    let mib = float_of_int terms *. (Float.abs (float_of_int l) +. float_of_int (max 0 p)) /. 1048576. in
    if mib >= float_of_int st.opts.limits.memory_mb then
      Error.limit_at loc "'%s' would make a string of %.0f MiB, more than povml's memory limit of %s MiB (raise it with --max-memory MIB)"
        name mib (commas st.opts.limits.memory_mb)
  in
  let value =
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
    | "vturbulence" ->
        (* express.cpp: DTurbulence at the vector, with lambda and omega stored in single precision
           and the octaves clipped to 1…10 *)
        arity 4;
        let octaves = max 1 (min 10 (int_of_float (float_arg (arg 2)))) in
        let turb = { Scene.turbulence = Vec.zero; octaves; omega = Precision.f32 (float_arg (arg 1)); lambda = Precision.f32 (float_arg (arg 0)) } in
        of_vec (Noise.dturbulence turb (vec_arg (arg 3)))
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
            (* a dimension the array does not have has size 0 (checked with POV-Ray) *)
            V.Float (if d < 1 || d > Array.length a.dims then 0. else float_of_int a.dims.(d - 1))
        | _ -> Error.raise_at loc "'dimension_size' takes an array and a dimension number")
    | "str" ->
        arity 3;
        let l = int_arg (arg 1) and p = int_arg (arg 2) in
        string_room 1 l p;
        V.String (Strfmt.str (float_arg (arg 0)) l p)
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
        let l = int_arg (arg 3) and p = int_arg (arg 4) in
        string_room k l p;
        V.String (Strfmt.vstr terms (string_arg (arg 2)) l p)
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
    | "file_exists" ->
        (* POV-Ray opens the file through its I/O restrictions, so a file it may not read is not there *)
        arity 1;
        let found = match find_file ~inc:false st (string_arg (arg 0)) with Some p -> Access.readable st.opts.access p | None -> false in
        V.Float (if found then 1. else 0.)
    | _ -> Error.raise_at loc "unknown function '%s'" name
  in
  (match value with V.String s -> count_string st loc (String.length s) | _ -> ());
  value

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
  (* one body (rgb…, a colour identifier or an expression) per colour: a second 'color' or rgb…
     keyword starts the next colour, as in [checker rgb 1 rgb 0] or the old color_map entry
     [a b color C1 color C2] (checked against POV-Ray) *)
  let body_seen = ref false in
  let body () = keyword_seen := true; body_seen := true in
  let rec loop () =
    let loc = peek_loc st in
    match peek st with
    | Ident ("color" | "colour") when not !keyword_seen -> advance st; keyword_seen := true; loop ()
    | Ident "rgb" when not !body_seen -> advance st; body (); ignore (set_terms loc 3 (parse_expr st)); loop ()
    | Ident "rgbf" when not !body_seen ->
        advance st; body ();
        let a = set_terms loc 4 (parse_expr st) in
        c.(3) <- a.(3); loop ()
    | Ident "rgbt" when not !body_seen ->
        advance st; body ();
        let a = set_terms loc 4 (parse_expr st) in
        c.(3) <- 0.; c.(4) <- a.(3); loop ()
    | Ident "rgbft" when not !body_seen -> advance st; body (); ignore (set_terms loc 5 (parse_expr st)); loop ()
    | Ident (("red" | "green" | "blue" | "filter" | "transmit") as k) ->
        advance st; keyword_seen := true;
        let i = match component_index k with Some i -> i | None -> assert false in
        c.(i) <- parse_float st;
        loop ()
    | Ident "alpha" ->
        (* the old name of filter, still read with POV-Ray's warning *)
        advance st; keyword_seen := true;
        warn st loc "Keyword ALPHA discontinued. Use FILTER instead.";
        c.(3) <- parse_float st;
        loop ()
    | Ident ("srgb" | "srgbf" | "srgbt" | "srgbft" as k) when not !body_seen ->
        (* as the rgb forms, then red, green and blue decoded; POV-Ray refuses them before
           assumed_gamma is known *)
        let assumed_gamma =
          match st.assumed_gamma with
          | Some g -> g
          | None ->
              Error.raise_at loc "the sRGB colour '%s' needs assumed_gamma, and none has been set yet (POV-Ray refuses it too: set it in global_settings before the first sRGB colour)" k
        in
        advance st; body ();
        (match k with
        | "srgb" -> ignore (set_terms loc 3 (parse_expr st))
        | "srgbf" -> let a = set_terms loc 4 (parse_expr st) in c.(3) <- a.(3)
        | "srgbt" -> let a = set_terms loc 4 (parse_expr st) in c.(3) <- 0.; c.(4) <- a.(3)
        | _ -> ignore (set_terms loc 5 (parse_expr st)));
        for i = 0 to 2 do c.(i) <- srgb_decode ~assumed_gamma c.(i) done;
        loop ()
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
      | _ -> let loc = peek_loc st in ignore (set_terms loc 5 (parse_expr st)); body ())
  | Ident s when not (Names.mem colour_set s) -> (
      match cur_value st s with
      | Some (V.Colour _) -> let loc = peek_loc st in ignore (set_terms loc 5 (parse_expr st)); body ()
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

(* Does the next token start a float expression (for optional values such as [metallic [M]])?
   POV-Ray's CASE_FLOAT: a number, '(', '+', '-', '!', a float identifier or built-in, a function
   identifier; not a vector identifier. *)
let float_follows st =
  match peek st with
  | Num _ | LParen | Minus | Plus | Bang -> true
  | Ident s -> ( match cur_value st s with Some (V.Float _ | V.Function _) -> true | _ -> Names.mem function_set s || List.mem s [ "pi"; "true"; "false"; "yes"; "no"; "on"; "off"; "clock"; "version"; "image_width"; "image_height" ])
  | _ -> false

let parse_bool_opt st = if float_follows st then truth (parse_float st) else true

(* ---------------------------------------------------------------------------------------------- *)
(* Transformations (§14.2, §14.3) *)

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

