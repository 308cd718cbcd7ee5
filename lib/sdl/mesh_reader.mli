(** The corners of triangles, and the mesh and mesh2 objects (docs/povray-rules.md §2.4–§2.6): vectors
    written as plain numbers are read straight from the text, vertices are kept in single
    precision, and equal vertices of a mesh are merged. *)

val triangle_corners : Reader.st -> smooth:bool -> Vec.t * Vec.t * Vec.t * (Vec.t * Vec.t * Vec.t) option
(** [triangle_corners st ~smooth] reads the corners of a triangle (P1, P2, P3) or, when [smooth],
    of a smooth_triangle (P1, N1, P2, N2, P3, N3): the points, and the normals normalised (a zero
    one replaced by <1,0,0> with a warning). *)

val mesh : Reader.st -> Loc.t -> Scene.shape
(** [mesh st loc] reads the block of a mesh written at [loc] (after the keyword) up to its
    modifiers. *)

val mesh2 : Reader.st -> Loc.t -> Scene.shape
(** [mesh2 st loc] reads the block of a mesh2 written at [loc] (after the keyword) up to its
    modifiers. *)
