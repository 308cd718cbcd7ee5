(** The vector functions made of other values (function.cpp's pigment, transform and spline
    functions, fnintern.cpp's f_pigment, f_transform and f_spline): [function { pigment { … } }]
    is a vector function of x y z giving the pigment's five colour terms,
    [function { transform { … } }] one giving the transformed point. *)

val spline : Spline.t -> Loc.t -> Fn.t
(** [spline s loc] is the vector function of one parameter, the time, whose terms are [s]'s
    value then. *)

val spline_value : Spline.t -> float -> Value.t
(** [spline_value s t] is [s]'s value at [t] as the scene language sees it: a vector of the
    spline's terms (a colour for five). *)

val pigment : Reader.st -> Scene.pigment -> Loc.t -> Fn.t
(** [pigment st p loc] is the vector function of pigment [p] (its colour at the point, without a
    surface, each term in single precision as POV-Ray's colours are), with the scene's noise
    generator when it runs. *)

val transform : Transform.t -> Loc.t -> Fn.t
(** [transform t loc] is the vector function of x y z giving the point moved by [t]. *)

val special : Reader.st -> parse_transform:(Reader.st -> Transform.t) -> string -> Loc.t -> Fn.t option
(** [special st ~parse_transform kw loc] reads the pigment or transform function after its keyword [kw] (the
    declaration's [special] for {!Fn_reader.declaration}); None for other keywords. *)

val spline_call : Reader.st -> Spline.t -> parse_float:(Reader.st -> float) -> Value.t
(** [spline_call st s ~parse_float] reads [S(t)] or [S(t, kind)] after the spline's identifier
    (Parse_Spline_Call) and is the spline's value there. *)
