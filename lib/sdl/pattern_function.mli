(** The functions made of pigments, transforms and patterns (function.cpp's declarations,
    fnintern.cpp's f_pigment, f_transform and f_pattern): [function { pigment { … } }] is a vector
    function of x y z giving the pigment's five colour terms, [function { transform { … } }] one
    giving the transformed point, and [function { pattern { … } }] the float function giving the
    pattern's value with its modifiers (warps, frequency, phase, wave) as Evaluate_TPat makes it. *)

val pigment : Reader.st -> Scene.pigment -> Loc.t -> Fn.t
(** [pigment st p loc] is the vector function of pigment [p] (its colour at the point, without a
    surface, each term in single precision as POV-Ray's colours are). *)

val transform : Transform.t -> Loc.t -> Fn.t
(** [transform t loc] is the vector function of x y z giving the point moved by [t]. *)

val pattern : Reader.st -> Loc.t -> Fn.t
(** [pattern st loc] reads [{ PATTERN modifiers }] after the [pattern] keyword (Parse_PatternFunction)
    and is its float function. *)
