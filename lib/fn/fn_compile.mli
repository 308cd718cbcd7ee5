(** Compiling a folded function body into closures, with the code POV-Ray's compiler chooses
    (fncode.cpp): a constant operand is folded into the operation ([x / c] is [x * (1/c)], [x + 0]
    and [x * 1] vanish, [pow(x, n)] for n = 2 … 8 is a fixed sequence of products), variables are
    resolved once, and every call gets a fresh frame. Nothing is looked up while the function runs. *)

val compile :
  name:string -> params:string array -> loc:Loc.t -> warn:(Loc.t -> string -> unit) -> Fn.expr -> Fn.t
(** [compile ~name ~params ~loc ~warn body] is the float function [name] of [params] (the x y z
    registers are read from the parameters of those names, u and v standing for x and y; 0 when
    absent). Errors (an unknown variable, division by the constant 0) are raised located; [warn]
    receives POV-Ray's compile warnings. *)

val c_int : float -> float
(** [c_int x] is C's [(int)] cast of [x] on x86, back as a float: truncation, and −2147483648 for
    NaN and what does not fit. *)
