(* The reader of julia_fractal { <a, b, c, d> … } (POV-Ray's Parse_Julia_Fractal and SetUp_Fractal). *)

open Token
open Reader

(* Parse_Vector4D: a float stands for all four terms, a shorter vector is padded with 0 *)
let vector4 st =
  let loc = peek_loc st in
  match Expr.parse_expr st with
  | V.Float f -> [| f; f; f; f |]
  | V.Vector a when Array.length a <= 4 -> Array.init 4 (fun i -> if i < Array.length a then a.(i) else 0.)
  | V.Vector _ | V.Colour _ -> Error.raise_at loc "Vector expected but color expression found."
  | v -> Error.raise_at loc "a 4-D vector expected, not %s" (V.kind_name v)

let complex_function = function
  | "exp" -> Some Julia_algebra.Exp
  | "ln" -> Some Ln
  | "sin" -> Some Sin
  | "asin" -> Some Asin
  | "cos" -> Some Cos
  | "acos" -> Some Acos
  | "tan" -> Some Tan
  | "atan" -> Some Atan
  | "cosh" -> Some Cosh
  | "sinh" -> Some Sinh
  | "tanh" -> Some Tanh
  | "atanh" -> Some Atanh
  | "acosh" -> Some Acosh
  | "asinh" -> Some Asinh
  | _ -> None

let julia st =
  let parm = vector4 st in
  let slice = ref [| 0.; 0.; 0.; 1. |] and slice_dist = ref 0. in
  let iterations = ref 20 and precision = ref (1.0 /. 20.0) in
  let algebra = ref Julia.Quaternion and func = ref Julia.Sqr and exponent = ref (0., 0.) in
  let rec loop () =
    match peek st with
    | Ident "max_iteration" ->
        advance st;
        let n = Expr.c_int (floor (Expr.parse_float st)) in
        iterations := if n <= 0. then 1 else int_of_float n;
        loop ()
    | Ident "slice" ->
        advance st;
        let loc = peek_loc st in
        let s = vector4 st in
        skip_comma st;
        slice_dist := Expr.parse_float st;
        let p = (s.(0) *. s.(0)) +. (s.(1) *. s.(1)) +. (s.(2) *. s.(2)) +. (s.(3) *. s.(3)) in
        if Float.abs p < Precision.epsilon then Error.raise_at loc "Slice vector is zero.";
        if Float.abs s.(3) < Precision.epsilon then Error.raise_at loc "Slice t component is zero.";
        let k = 1.0 /. sqrt p in
        slice := Array.map (fun c -> c *. k) s;
        loop ()
    | Ident "precision" ->
        advance st;
        let p = Expr.parse_float st in
        precision := 1.0 /. (if p < 1.0 then 1.0 else p);
        loop ()
    | Ident "sqr" -> advance st; func := Sqr; loop ()
    | Ident "cube" -> advance st; func := Cube; loop ()
    | Ident "reciprocal" -> advance st; func := Reciprocal; loop ()
    | Ident "hypercomplex" -> advance st; algebra := Hypercomplex; loop ()
    | Ident "quaternion" -> advance st; algebra := Quaternion; loop ()
    | Ident "pwr" ->
        advance st;
        expect st LParen "'(' after 'pwr'";
        let ex = Expr.parse_float st in
        skip_comma st;
        let ey = Expr.parse_float st in
        expect st RParen "')' closing 'pwr'";
        func := Func Pwr;
        exponent := (ex, ey);
        loop ()
    | Ident s when List.mem s Expr.function_names -> (
        match complex_function s with
        | Some f -> advance st; func := Func f; loop ()
        | None -> Error.raise_at (peek_loc st) "fractal keyword expected, but '%s' found instead" s)
    | _ -> ()
  in
  loop ();
  Scene.Julia
    (Julia.make ~parm ~slice:!slice ~slice_dist:!slice_dist ~iterations:!iterations ~precision:!precision ~algebra:!algebra
       ~func:!func ~exponent:!exponent)

(* SetUp_Fractal after the object's modifiers: the map must suit the algebra, and its
   Compute_BBox clears the inverted flag (an [inverse] inside the block has no effect) *)
let rec set_up loc (o : V.obj) : V.obj =
  match o.shape with
  | Prim (Julia f) ->
      if not (Julia.supported f.algebra f.func) then Error.raise_at loc "Illegal function: quaternion only supports sqr and cube";
      { o with shape = Prim (Julia (Julia.set_up f)) }
  | Csg { kind = Clipped; members = V.Member_obj c :: clips; split; box } -> { o with shape = Csg { kind = Clipped; members = V.Member_obj (set_up loc c) :: clips; split; box } }
  | Prim _ | Csg _ -> o
