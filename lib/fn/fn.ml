(* User functions: the types the parser, the folding, the compiler and the renderer share. *)

type binop = Or | And | Eq | Ne | Lt | Le | Gt | Ge | Add | Sub | Mul | Div | Pow

type builtin =
  | Sin | Cos | Tan | Asin | Acos | Atan | Sinh | Cosh | Tanh | Asinh | Acosh | Atanh
  | Abs | Radians | Degrees | Int | Floor | Ceil | Sqrt | Exp | Ln | Log
  | Min | Max | Atan2 | Pow_call | Mod | Div_call | Select | Sqr | Sum | Prod

type expr =
  | Const of float
  | Var of string * Loc.t
  | Paren of expr
  | Chain of expr * (binop * expr) list
  | Neg of expr
  | Builtin of builtin * expr list * Loc.t
  | Call of t * expr list * Loc.t
  | Member of t * expr list * int * Loc.t

and t = {
  name : string;
  params : string array;
  frame : int;
  size : int;
  eval : float array -> float;
  veval : float array -> float array;
  counted : (float array -> float) Lazy.t;
  floc : Loc.t;
}

let arity f = Array.length f.params

let frame f =
  let fr = Array.create_float (max f.frame 3) in
  Array.fill fr 0 (Array.length fr) 0.;
  fr

let fill f args =
  let fr = frame f in
  Array.blit args 0 fr 0 (min (Array.length args) (Array.length fr));
  fr

let call f args = (Lazy.force f.counted) (fill f args)

let call_vector f args = f.veval (fill f args)

let at_point f x y z =
  if f.frame <= 3 then f.eval [| x; y; z |]
  else begin
    let fr = frame f in
    fr.(0) <- x;
    fr.(1) <- y;
    fr.(2) <- z;
    f.eval fr
  end

let red_to_gray = 0.297
let green_to_gray = 0.589
let blue_to_gray = 0.114
