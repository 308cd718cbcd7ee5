(* Readers of superellipsoid (Parse_Superellipsoid), ovus (Parse_Ovus) and sphere_sweep
   (Parse_Sphere_Sweep), after the keyword and its '{'. *)

open Reader
module V = Value

(* Parse_UV_Vect: <u, v>, or a float standing for both *)
let uv_vector st =
  let loc = peek_loc st in
  match Expr.parse_expr st with
  | V.Float f -> (f, f)
  | V.Vector [| u; v |] -> (u, v)
  | v -> Error.raise_at loc "expected a UV vector <u, v> but found %s" (V.kind_name v)

let superellipsoid st =
  let e, n = uv_vector st in
  Scene.Superellipsoid (Superellipsoid.make e n)
