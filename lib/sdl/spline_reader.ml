(* Readers of prism, lathe and sor (parse.cpp: Parse_Prism, Parse_Lathe, Parse_Sor): their items
   after the keyword and '{', with POV-Ray's checks, errors and warnings. *)

open Reader
module V = Value

(* Parse_UV_Vect: a float stands for both terms; more than two terms is an error *)
let uv_vector st =
  let loc = peek_loc st in
  match Expr.parse_expr st with
  | V.Float f -> (f, f)
  | V.Vector [| u; v |] -> (u, v)
  | v -> Error.raise_at loc "expected a UV vector <u, v> but found %s" (V.kind_name v)

let points st n =
  read_items n (fun _ ->
      skip_comma st;
      uv_vector st)

(* the spline keywords (and, for a prism, the sweep ones), in any order, any number of times *)
let rec options st ~sweep (spline, conic) =
  let next v = advance st; options st ~sweep v in
  match peek st with
  | Token.Ident "linear_spline" -> next (Prism.Linear, conic)
  | Token.Ident "quadratic_spline" -> next (Prism.Quadratic, conic)
  | Token.Ident "cubic_spline" -> next (Prism.Cubic, conic)
  | Token.Ident "bezier_spline" -> next (Prism.Bezier, conic)
  | Token.Ident "linear_sweep" when sweep -> next (spline, false)
  | Token.Ident "conic_sweep" when sweep -> next (spline, true)
  | _ -> (spline, conic)

let count st = int_of_float (Expr.c_int (Expr.parse_float st))

(* the fewest points a spline needs ([linear], [quadratic], [cubic]: the count and its word), a
   Bezier one four per segment (and not fewer than none), as fatal errors at [nloc] in POV-Ray's
   words; its lathe calls itself a prism in the cubic message, hence [cubic_shape] *)
let check_count nloc n (spline : Prism.spline) ~shape ~cubic_shape linear quadratic cubic =
  let least name kind (k, word) =
    if n < k then Error.raise_at nloc "%s with %s splines must have at least %s points." name kind word
  in
  match spline with
  | Linear -> least shape "linear" linear
  | Quadratic -> least shape "quadratic" quadratic
  | Cubic -> least cubic_shape "cubic" cubic
  | Bezier ->
      if n land 3 <> 0 then Error.raise_at nloc "%s with Bezier splines must have four points per segment." shape
      else if n < 0 then
        (* a negative multiple of four passes POV-Ray's check; its array of n + 1 points is then
           one of an enormous size, whose allocation fails *)
        Error.raise_at nloc "%s with %d points: POV-Ray's array of its points cannot be allocated." shape n

let prism st loc =
  let spline, conic = options st ~sweep:true (Prism.Linear, false) in
  let h1 = Expr.parse_float st in
  skip_comma st;
  let h2 = Expr.parse_float st in
  skip_comma st;
  let height1, height2 = if h1 > h2 then (h2, h1) else (h1, h2) in
  let nloc = peek_loc st in
  let n = count st in
  check_count nloc n spline ~shape:"Prism" ~cubic_shape:"Prism" (3, "three") (5, "five") (6, "six");
  let pts = points st n in
  let closed = not (accept_ident st "open") in
  let pts, state = Prism.close spline pts in
  (match state with
  | `Closed -> ()
  | `Closing -> warn st loc "Linear prism not closed. Closing it."
  | `Open -> warn st loc "Prism not closed. Ignoring it.");
  match Prism.make ~spline ~conic ~height1 ~height2 ~closed ~sturm:false ~degenerate:(state = `Open) pts with
  | Ok p -> Scene.Prism p
  | Error msg -> Error.raise_at loc "%s" msg

let lathe st loc =
  ignore loc;
  let spline, _ = options st ~sweep:false (Prism.Linear, false) in
  let nloc = peek_loc st in
  let n = count st in
  check_count nloc n spline ~shape:"Lathe" ~cubic_shape:"Prism" (2, "two") (3, "three") (4, "four");
  let pts =
    read_items n (fun i ->
        skip_comma st;
        let ploc = peek_loc st in
        let ((x, _) as p) = uv_vector st in
        if i > 0 && i < n - 1 && x < 0. then Error.raise_at ploc "Incorrect point in lathe.";
        p)
  in
  Scene.Lathe (Lathe.make ~spline ~sturm:false pts)

let sor st loc =
  let nloc = peek_loc st in
  let n = count st in
  if n < 4 then Error.raise_at nloc "Surface of revolution must have at least four points.";
  let last_y = ref 0. in
  let pts =
    read_items n (fun i ->
        skip_comma st;
        let ploc = peek_loc st in
        let ((x, y) as p) = uv_vector st in
        if x < 0. || (i > 1 && i < n - 1 && y <= !last_y) then Error.raise_at ploc "Incorrect point in surface of revolution.";
        last_y := y;
        p)
  in
  let closed = not (accept_ident st "open") in
  match Sor.make ~closed ~sturm:false pts with Ok s -> Scene.Sor s | Error msg -> Error.raise_at loc "%s" msg
