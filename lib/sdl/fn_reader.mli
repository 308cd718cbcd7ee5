(** Reading functions (POV-Ray's function parser, fnsyntax.cpp, and its declarations,
    function.cpp): the body's own grammar, [#declare F = function(…) { … }], the anonymous
    [function { … }] of patterns and shapes, and calls of functions in the scene language.

    The grammar is POV-Ray's: [|] below [&] below the comparisons below [+ -] below [* /] below
    the signs; operands are numbers, declared floats (read as constants), parameters, x y z u v,
    [pi], [clock], parenthesised expressions, calls of the built-in float functions, of
    [sum]/[prod], and of declared functions; a vector function's call must be followed by a member
    ([.x], [.red], [.gray] …). *)

val body : Reader.st -> name:string -> Fn.expr
(** [body st ~name] reads one expression of a function body; [name] is the function being
    declared ("" if none), which the body may not call (POV-Ray: no recursive calls). *)

val anonymous : Reader.st -> Fn.t
(** [anonymous st] reads [{ body }] after a [function] keyword where no parameters may be written
    (a pattern, an isosurface): a function of x y z. *)

val params : Reader.st -> string array
(** [params st] reads an optional parameter list [(a, b, …)]: none gives [x y z]. A parameter may
    not be a declared float (POV-Ray: "Expected 'parameter identifier'"). *)

val declaration : Reader.st -> name:string -> special:(string -> Loc.t -> Fn.t option) -> Value.t
(** [declaration st ~name ~special] reads what follows [function] in a declaration: parameters,
    then a block holding [internal(k)], or a keyword for which [special kw loc] reads the rest
    (pigment, transform, pattern, spline: the declaring module knows those), or an expression. *)

val sdl_call : Reader.st -> Fn.t -> Loc.t -> parse_float:(Reader.st -> float) -> Value.t
(** [sdl_call st f loc ~parse_float] reads the parenthesised arguments of a call of [f] in the
    scene language (the identifier consumed) and evaluates it: a float, or the terms of a vector
    function (a colour for a pigment's five). *)

val noise_generator : Reader.st -> int
(** [noise_generator st] is the scene's noise generator as internal functions see it. *)
