(** User functions: the small language compiled inside the scene language (POV-Ray 3.7's
    [function { … }], backend/parser/fnsyntax.cpp and backend/vm/fncode.cpp).

    A function is parsed once into {!expr}, folded by POV-Ray's rules ({!Fn_optimise}) and compiled
    into a tree of closures ({!Fn_compile}); evaluating it never looks at tokens again. This module
    holds the types every stage shares and the calls the renderer makes. *)

(** The binary operators of a function body, by precedence level as POV-Ray groups them: [|],
    [&], comparisons, [+ -], [* /], and [Pow] (only made from [pow(a, b)]). *)
type binop = Or | And | Eq | Ne | Lt | Le | Gt | Ge | Add | Sub | Mul | Div | Pow

(** The float functions a body may call (POV-Ray's tokens that compile to VM code). *)
type builtin =
  | Sin | Cos | Tan | Asin | Acos | Atan | Sinh | Cosh | Tanh | Asinh | Acosh | Atanh
  | Abs | Radians | Degrees | Int | Floor | Ceil | Sqrt | Exp | Ln | Log
  | Min | Max | Atan2 | Pow_call | Mod | Div_call | Select | Sqr | Sum | Prod

(** A function body as POV-Ray's expression parser builds it: each precedence level is a chain of
    operands joined left to right ([Chain]), as fnsyntax.cpp keeps it, because POV-Ray's constant
    folding works on those chains. *)
type expr =
  | Const of float
  | Var of string * Loc.t  (** a parameter, a [sum]/[prod] counter, or x y z u v *)
  | Paren of expr  (** a parenthesised expression (POV-Ray never folds it into a constant) *)
  | Chain of expr * (binop * expr) list  (** one precedence level: the first operand, then operators *)
  | Neg of expr  (** unary minus *)
  | Builtin of builtin * expr list * Loc.t
  | Call of t * expr list * Loc.t  (** a call of a float function *)
  | Member of t * expr list * int * Loc.t
      (** [F(…).m] of a vector function: the term read (0…4), or -1 for [gray], -2 for [hf] *)

(** A compiled function. Its frame holds the parameters at 0 … [arity − 1], then the counters of
    its [sum] and [prod] loops; a call fills a fresh frame. *)
and t = {
  name : string;  (** the declared name ("" for an anonymous function) *)
  params : string array;  (** the parameters; [x y z] when none were written *)
  frame : int;  (** frame size: parameters and loop counters *)
  size : int;  (** 0 for a float function, else the terms of a vector function (3 or 5, or a spline's) *)
  eval : float array -> float;  (** the value of a float function, given a frame *)
  veval : float array -> float array;  (** the terms of a vector function, given a frame *)
  counted : (float array -> float) Lazy.t;
      (** [eval] taking its steps from {!Fn_budget}, for the calls made while the scene is read
          (compiled when first needed); [eval] itself for functions that are not compiled bodies *)
  floc : Loc.t;  (** where the function was written *)
}

val arity : t -> int
(** [arity f] is the number of parameters of [f]. *)

val frame : t -> float array
(** [frame f] is a fresh frame for one call of [f], all zeros. *)

val call : t -> float array -> float
(** [call f args] is [f]'s value for the parameters [args] (as many as [arity f]), as the scene
    language calls it: its steps are taken from {!Fn_budget}, which raises [Fn_budget.Exhausted]
    when they run out. *)

val call_vector : t -> float array -> float array
(** [call_vector f args] is the terms of vector function [f] for [args]. *)

val at_point : t -> float -> float -> float -> float
(** [at_point f x y z] is [f] called with [x y z] as its first three parameters and zeros for the
    rest, as patterns and isosurfaces call it (POV-Ray's SetLocal of X, Y and Z). *)

val red_to_gray : float
(** The grey weights of a colour's red, green and blue (POV-Ray's GREY_SCALE). *)

val green_to_gray : float

val blue_to_gray : float
