(* The reader of isosurface { function { … } … } (POV-Ray's Parse_Isosurface). *)

open Token
open Reader

(* contained_by { box { A, B } } (corners sorted per axis) or { sphere { C, R } }; an empty block
   keeps the container *)
let container st (c : Isosurface.container) : Isosurface.container =
  match Container_reader.read st with
  | Some (Box (a, b)) ->
      let lo p q = if p > q then q else p and hi p q = if p > q then p else q in
      Isosurface.Box_container { lo = Vec.make (lo a.x b.x) (lo a.y b.y) (lo a.z b.z); hi = Vec.make (hi a.x b.x) (hi a.y b.y) (hi a.z b.z) }
  | Some (Sphere (centre, radius)) -> Isosurface.Sphere_container { centre; radius }
  | None -> c

(* (short)Parse_Float(): C's conversion to int, then its low 16 bits as a signed number *)
let short v =
  let n = int_of_float (Expr.c_int v) land 0xFFFF in
  if n >= 0x8000 then n - 0x10000 else n

let rec items st (s : Isosurface.t) : Isosurface.t =
  match peek st with
  | Ident "contained_by" -> advance st; items st { s with container = container st s.container }
  | Ident "threshold" -> advance st; items st { s with threshold = Expr.parse_float st }
  | Ident "accuracy" -> advance st; items st { s with accuracy = Expr.parse_float st }
  | Ident "max_gradient" -> advance st; items st { s with max_gradient = Expr.parse_float st }
  | Ident "max_trace" -> advance st; items st { s with max_trace = short (Expr.parse_float st) }
  | Ident "all_intersections" -> advance st; items st { s with max_trace = Isosurface.max_trace_limit }
  | Ident "open" -> advance st; items st { s with closed = false }
  | Ident "evaluate" ->
      advance st;
      let p0 = Expr.parse_float st in
      skip_comma st;
      let p1 = Expr.parse_float st in
      skip_comma st;
      let p2 = Expr.parse_float st in
      items st { s with evaluate = Some { p0; p1; p2 } }
  | _ -> s

(* POV-Ray's checks after the items: each replaces a bad value with a warning *)
let checked st (s : Isosurface.t) =
  let loc = peek_loc st in
  let s =
    if s.accuracy <= 0. then begin
      warn st loc "Isosurface 'accuracy' is not positive. Using 0.001 (default).";
      { s with accuracy = Isosurface.accuracy_default }
    end
    else s
  in
  let s =
    if s.max_gradient <= 0. then begin
      warn st loc "Isosurface 'max_gradient' is not positive. Using 1.1 (default).";
      { s with max_gradient = Isosurface.max_gradient_default }
    end
    else s
  in
  if s.max_trace > Isosurface.max_trace_limit then begin
    warn st loc "Isosurface 'max_trace' exceeds maximum of %d. Using maximum." Isosurface.max_trace_limit;
    { s with max_trace = Isosurface.max_trace_limit }
  end
  else if s.max_trace < 1 then begin
    warn st loc "Isosurface 'max_trace' is not positive. Using 1 (default).";
    { s with max_trace = 1 }
  end
  else s

let isosurface st : Scene.shape =
  (match peek st with Ident "function" -> advance st | _ -> unexpected st "'function' (an isosurface starts with its function)");
  let fn = Fn_reader.anonymous st in
  let key = st.isosurfaces in
  st.isosurfaces <- key + 1;
  Isosurface (checked st (items st (Isosurface.make ~fn ~key)))
