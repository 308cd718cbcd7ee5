(** The reader of [julia_fractal] (POV-Ray's Parse_Julia_Fractal). *)

val julia : Reader.st -> Scene.shape
(** [julia st] reads, after the block's ['{'], the julia parameter [<a, b, c, d>] and the
    fractal's own items ([max_iteration], [slice <n>, d], [precision], the algebra
    [quaternion]/[hypercomplex], the map [sqr], [cube], [reciprocal], [pwr(x, y)], [exp] … [atanh]),
    with POV-Ray's defaults, clamps and errors. *)

val set_up : Loc.t -> Reader.V.obj -> Reader.V.obj
(** [set_up loc o] is SetUp_Fractal on the fractal [o] (or the fractal clipped in [o]) once its
    modifiers are read: the error "Illegal function: quaternion only supports sqr and cube" at [loc]
    for a map the quaternions lack, and its inverted flag cleared. *)
