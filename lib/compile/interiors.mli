(** The interiors a ray starts in (docs/povray-rules.md §6.4, §18.4). *)

val at : Compiled.obj array -> float array -> Vec.t -> int list
(** [at holders stack p] is the interiors of the objects of [holders] (top-level objects, such as
    [Compiled.t.screen_holders]) whose POV-Ray box and Inside test both hold [p], the last one
    first: the interior list of a ray starting at [p]. POV-Ray asks the box (Inside_BBox, faces
    included) before the object's own inside test, so a camera behind a disc is inside the disc's
    half-space only within the disc's thin box (§15.4). [stack] is traversal room for meshes. *)

val holds : float array -> Compiled.obj -> Vec.t -> bool
(** [holds stack o p] is whether [o]'s POV-Ray box and Inside test both hold [p]. *)

val innermost_first : Compiled.obj array -> int list -> int list
(** [innermost_first objects l] is the interior list [l] in the robust mode's order, which does not
    depend on where the scene lies: the interior of the smallest box first, as entered last (an
    interior list holding one another, a ball in a room); POV-Ray's order follows its bounding
    tree, whose shape follows the single-precision rounding of the boxes. *)
