(* The reader of [spline { … }] (Parse_Spline of parser/express.cpp, between the Parse_Begin and
   Parse_End of its callers in parse.cpp and function.cpp). *)

open Reader
module V = Value

let kind_of = function
  | Token.Ident "linear_spline" -> Some Spline.Linear
  | Token.Ident "quadratic_spline" -> Some Spline.Quadratic
  | Token.Ident "cubic_spline" -> Some Spline.Cubic
  | Token.Ident "natural_spline" -> Some Spline.Natural
  | _ -> None

(* the type keywords, any number of them, the last one counting *)
let rec kind_keywords st kind =
  match kind_of (peek st) with
  | Some k ->
      advance st;
      kind_keywords st k
  | None -> kind

(* The words POV-Ray's tokenizer makes float-function tokens (reswords.h, before
   FLOAT_FUNCT_TOKEN), and the float identifiers it declares itself. *)
let float_words =
  set_of
    [ "abs"; "atan"; "atan2"; "ceil"; "clock_on"; "clock"; "cos"; "degrees"; "div"; "exp"; "floor"; "inside"; "int";
      "ln"; "log"; "max"; "min"; "mod"; "now"; "pi"; "pow"; "radians"; "select"; "sin"; "sqrt"; "vdot"; "vlength";
      "version"; "on"; "off"; "true"; "false"; "yes"; "no"; "acos"; "asin"; "tan"; "asc"; "strlen"; "val";
      "file_exists"; "strcmp"; "seed"; "rand"; "dimensions"; "dimension_size"; "defined"; "cosh"; "sinh"; "tanh";
      "atanh"; "acosh"; "asinh"; "sum"; "prod"; "bitwise_and"; "bitwise_xor"; "bitwise_or";
      "image_width"; "image_height"; "clock_delta"; "frame_number"; "initial_clock"; "final_clock";
      "initial_frame"; "final_frame" ]

(* CASE_FLOAT (parse.h): whether an entry's time comes next, which decides whether the entries go
   on; a vector ('<', a vector identifier, …) does not start one *)
let time_follows st =
  match peek st with
  | Token.Num _ | LParen | Plus | Minus | Bang -> true
  | Ident s -> ( match cur_value st s with Some (V.Float _) -> true | Some _ -> false | None -> Names.mem float_words s)
  | _ -> false

(* the colour keywords, which Parse_Express does not read (a colour identifier it does) *)
let colour_words =
  set_of
    [ "color"; "colour"; "rgb"; "rgbf"; "rgbt"; "rgbft"; "srgb"; "srgbf"; "srgbt"; "srgbft"; "red"; "green"; "blue";
      "filter"; "transmit"; "gray"; "alpha" ]

(* Parse_Express: a float (one term) or a vector or colour of its terms *)
let entry_value st =
  let loc = peek_loc st in
  (match peek st with
  | Token.Ident s when Names.mem colour_words s ->
      Error.raise_at loc "expected a numeric expression but found the colour keyword '%s' (a spline entry's value may be a colour identifier, not a colour)" s
  | _ -> ());
  match Expr.parse_expr st with
  | V.Float f -> [| f |]
  | V.Vector a | V.Colour a -> a
  | v -> Error.raise_at loc "expected a float or a vector as the value of a spline entry but found %s" (V.kind_name v)

(* the entries in the order written: time [,] value [,] … *)
let rec entries st acc =
  if time_follows st then begin
    let time = Expr.parse_float st in
    skip_comma st;
    let value = entry_value st in
    skip_comma st;
    entries st ((time, value) :: acc)
  end
  else List.rev acc

let read_block_with ~named st =
  open_block st "spline";
  let base =
    match peek st with
    | Token.Ident s -> (
        match named st s with
        | Some spline ->
            advance st;
            Some spline
        | None -> None)
    | _ -> None
  in
  let kind = kind_keywords st (match base with Some s -> Spline.kind s | None -> Spline.Linear) in
  let written = entries st [] in
  let spline =
    match (base, written) with
    | Some s, _ -> Spline.add (Spline.with_kind s kind) written
    | None, _ :: _ -> Spline.make kind written
    | None, [] -> Error.raise_at (peek_loc st) "Spline must have at least one entry."
  in
  close_block st "spline";
  spline

let read_block st = read_block_with ~named:(fun _ _ -> None) st
