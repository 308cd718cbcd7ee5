(** Pattern functions (function.cpp's [function { pattern { … } }], fnintern.cpp's f_pattern):
    the float function of x y z giving the pattern's value with its modifiers (warps, frequency,
    phase, wave) as Evaluate_TPat makes it. *)

val pattern : Reader.st -> Loc.t -> Fn.t
(** [pattern st loc] reads [{ PATTERN modifiers }] after the [pattern] keyword
    (Parse_PatternFunction) and is its float function; the scene's noise generator is read when
    the function runs, as POV-Ray reads it at render time. *)
