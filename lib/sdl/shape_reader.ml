(* Readers of polygon (POVRAY-3.7 §15.7, Parse_Polygon) and quadric (Parse_Quadric). *)

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
