(** The [contained_by] block of isosurfaces and parametric surfaces (Parse_Isosurface,
    Parse_Parametric). *)

(** A container as written: a box's two corners (unsorted), or a sphere's centre and radius. *)
type t = Box of Vec.t * Vec.t | Sphere of Vec.t * float

val read : Reader.st -> t option
(** [read st] reads [{ box { A, B } }] or [{ sphere { C, R } }] after [contained_by]; None for an
    empty block or anything else, which leaves the container as it was. *)
