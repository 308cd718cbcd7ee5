(* Readers of polygon (docs/povray-rules.md §15.7, Parse_Polygon), quadric (Parse_Quadric), and poly, cubic,
   quartic (Parse_Poly) and polynomial (Parse_Polynom). *)

open Token
open Reader

(* C's (int) cast on x86: truncation, and −2147483648 for what does not fit *)
let c_int x = if Float.is_nan x || Float.abs x >= 2147483648. then -2147483648. else Float.trunc x

let polygon st loc =
  let nloc = peek_loc st in
  let n = c_int (Expr.parse_float st) in
  if n < 3. then Error.raise_at nloc "a polygon needs at least three points, not %g" n;
  let n = int_of_float n in
  let points = ref [] in
  for k = 1 to n do
    ignore (accept st Comma);
    if peek st == RBrace then Error.raise_at (peek_loc st) "the polygon has %d points but only %d are written" n (k - 1);
    points := Expr.parse_vector st :: !points
  done;
  let closed, appended = Polygon.close (Array.of_list (List.rev !points)) in
  if appended then warn st loc "polygon not closed: POV-Ray closes it with the first point of its last outline";
  let p = Polygon.make closed in
  if p.degenerate then warn st loc "degenerate polygon (its points are collinear or not in one plane): POV-Ray never shows it";
  Scene.Polygon p

let quadric st =
  let square = Expr.parse_vector st in
  ignore (accept st Comma);
  let mixed = Expr.parse_vector st in
  ignore (accept st Comma);
  let linear = Expr.parse_vector st in
  ignore (accept st Comma);
  let j = Expr.parse_float st in
  Scene.Quadric (Quadric.make ~square ~mixed ~linear j)

(* the order written first in poly and polynomial: (int)Parse_Float, then within 2 … MAX_ORDER *)
let order st what =
  let loc = peek_loc st in
  let n = c_int (Expr.parse_float st) in
  ignore (accept st Comma);
  if n < 2. || n > float_of_int Poly.max_order then
    Error.raise_at loc "Order of %s is out of range: %g (it must be 2 to %d)" what n Poly.max_order;
  int_of_float n

let poly st ~order:given =
  let order = if given = 0 then order st "poly" else given in
  (* Parse_Coeffs: '<', exactly term_counts(order) floats, the commas optional, '>' *)
  let n = Poly.term_count order in
  expect st Lt (Printf.sprintf "'<' starting the %d coefficients" n);
  let c = Array.make n 0. in
  for k = 0 to n - 1 do
    if k > 0 then ignore (accept st Comma);
    c.(k) <- Expr.parse_float st
  done;
  expect st Gt (Printf.sprintf "'>' after the %d coefficients of an order %d polynomial" n order);
  Scene.Poly (Poly.make ~order c)

let polynomial st =
  let order = order st "polynomial" in
  let c = Array.make (Poly.term_count order) 0. in
  (* xyz(x, y, z): value, each power truncated as (unsigned int)Parse_Float, the comma after the
     value optional; a later term for the same powers replaces the earlier one *)
  while accept_ident st "xyz" do
    expect st LParen "'(' after 'xyz'";
    let power () = let p = c_int (Expr.parse_float st) in if p < 0. then max_int else int_of_float p in
    let ploc = peek_loc st in
    let x = power () in
    ignore (accept st Comma);
    let y = power () in
    ignore (accept st Comma);
    let z = power () in
    expect st RParen "')' after the three powers of 'xyz'";
    expect st Colon "':' after 'xyz(…)'";
    let v = Expr.parse_float st in
    (match Poly.index order x y z with
    | Some i -> c.(i) <- v
    | None -> Error.raise_at ploc "Coefficient of polynom is out of range: the powers add up to more than the order %d" order);
    ignore (accept st Comma)
  done;
  Scene.Poly (Poly.make ~order c)
