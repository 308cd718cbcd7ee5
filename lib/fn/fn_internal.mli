(** POV-Ray 3.7's internal functions, [internal(k)] in a function body: the ones functions.inc
    declares, f_algbr_cyl1 (0) … f_noise_generator (78), as fnintern.cpp computes them (its
    POVFPU_TrapTable gives the index, the function and the parameter count). Every function
    follows POV-Ray's double-precision order of operations, so that its values are POV-Ray's. A
    function reads its arguments from a float array: x, y and z at 0, 1 and 2 (PARAM_X,
    PARAM_Y, PARAM_Z), then the parameters (PARAM(0) …) from 3, in the order a call passes
    them. *)

val count : int
(** [count] is the number of internal functions, 79 (POVFPU_TrapTableSize): [k] runs from 0 to
    [count − 1]. *)

val arity : int -> int
(** [arity k] is the parameter count of [internal(k)], x, y and z included (3 for the functions
    of x, y, z only). Raises [Invalid_argument] for [k] outside 0 … [count − 1]: the caller
    checks the index first (and reports a located error for a scene's). *)

val name : int -> string
(** [name k] is functions.inc's name of [internal(k)], e.g. [name 61] is ["f_sphere"]; for 77,
    which functions.inc does not declare, it is fnintern.cpp's ["f_pattern"]. Raises
    [Invalid_argument] for [k] outside 0 … [count − 1]. *)

val loop_parameter : int -> int option
(** [loop_parameter k] is where in the argument array [internal(k)] reads how many times it loops,
    for the functions whose work a parameter sets: the octaves of f_hetero_mf (5), f_ridge (4) and
    f_ridged_mf (5), the tubes of f_polytubes (3); [None] for the others, whose work is bounded. *)

val make : noise_generator:int -> int -> (float array -> float) option
(** [make ~noise_generator k] is the implementation of [internal(k)]: a function reading its
    arguments from the array at 0 … [arity k − 1] (the array may be longer; it is not written).
    It is [None] for 77 (f_pattern, which evaluates a pattern) and for a [k] out of range.
    [noise_generator] is the scene's global_settings noise_generator (1, 2 or 3; 2 by default):
    f_noise3d (76) uses it; f_hetero_mf, f_ridge, f_ridged_mf and f_noise_generator take theirs
    from a parameter. Make one function per declaration: f_ridged_mf keeps the octave weights of
    its first call for all later calls, as POV-Ray keeps them in the function's private data. *)
