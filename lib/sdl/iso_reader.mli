(** The reader of [isosurface { … }] (POV-Ray's Parse_Isosurface): the function first, then
    [contained_by { box { A, B } }] or [contained_by { sphere { C, R } }], [threshold],
    [accuracy], [max_gradient], [max_trace], [all_intersections], [evaluate P0, P1, P2] and
    [open], in any order and as often as wanted; the object's modifiers follow. *)

val isosurface : Reader.st -> Scene.shape
(** [isosurface st] reads the items after [isosurface {] (the identifier case done by
    [Reader.open_shape]) and gives the shape, numbered by [st.isosurfaces]. POV-Ray's
    warnings, and its replacement values, for an accuracy or max_gradient that is not
    positive and a max_trace outside 1 … 10. *)
