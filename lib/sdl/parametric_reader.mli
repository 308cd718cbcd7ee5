(** The reader of [parametric] (POV-Ray's Parse_Parametric). *)

type precompute
(** A [precompute] request, run once the object's modifiers are read (as POV-Ray runs it). *)

val parametric : Reader.st -> Scene.shape * precompute option
(** [parametric st] reads, after the block's ['{'], the three functions (each [function { … }]
    or a bare expression, which as in POV-Ray starts after its first token; commas optional), the corners [<u1, v1>, <u2, v2>] and the surface's
    own items in any order ([accuracy], [max_gradient], [precompute depth [x] [, y] [, z]],
    [contained_by { box { … } | sphere { … } }]), with POV-Ray's defaults (accuracy 0.001,
    max_gradient 1, the container [box { -1, 1 }]). An accuracy that is not positive is an
    error: POV-Ray's subdivision would never end. *)

val finish : precompute option -> Reader.V.obj -> Reader.V.obj
(** [finish p o] is the surface [o] (or the surface clipped in [o]) with its bounds precomputed as
    [p] asks, with its final accuracy and max_gradient; "Precompute: invalid depth" for a depth
    outside 1 … 20 when any of x, y, z was chosen. *)
