(** The interiors a ray starts in (POVRAY-3.7 §6.4, §18.4). *)

val at : Compiled.obj array -> float array -> Vec.t -> int list
(** [at holders stack p] is the interiors of the objects of [holders] (top-level objects, such as
    [Compiled.t.screen_holders]) whose POV-Ray box and Inside test both hold [p], the last one
    first: the interior list of a ray starting at [p]. POV-Ray asks the box (Inside_BBox, faces
    included) before the object's own inside test, so a camera behind a disc is inside the disc's
    half-space only within the disc's thin box (§15.4). [stack] is traversal room for meshes. *)

val holds : float array -> Compiled.obj -> Vec.t -> bool
(** [holds stack o p] is whether [o]'s POV-Ray box and Inside test both hold [p]. *)
