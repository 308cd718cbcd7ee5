(** A ray against a blob (POV-Ray's Blob::All_Intersections and determine_influences). *)

val intersect : Scratch.t -> Blob.compiled -> child:bool -> Vec.t -> Vec.t -> int
(** [intersect w c ~child o d] is All_Intersections of the ray from [o] along the unit [d]: the
    number n of depths found, in [w.blob.found.(0 … n−1)]. The elements' spans along the ray
    (entry and exit, clamped to 0 below the depth tolerance) are merged into one sorted list;
    over each stretch between two bounds the active elements' quartics are summed, the
    stretch skipped when its Bézier control values all have one sign, and the quartic solved
    (Solve_Polynomial, root elimination below 1e-11), keeping the roots within the stretch
    whose depth is in (1e-2, 1e7). A CSG member ([child]) takes every stretch, a blob on its own
    stops after the first with a root. Counted: "Blob", "Blob Component", "Blob Bound", "Roots
    tested". *)

val depth : Scratch.t -> Blob.compiled -> Vec.t -> Vec.t -> float -> float
(** [depth w c o d lo] is the nearest depth of [intersect] (as a blob on its own) at least [lo],
    or infinity. A blob whose box is empty (no component of positive strength, and no transform,
    which would map that box to the whole space) is never hit on its own, as POV-Ray's bounding
    box test never lets a ray reach it; as a CSG member it is intersected all the same. *)

val hits : Scratch.t -> Blob.compiled -> int -> Vec.t -> Vec.t -> float -> int -> int
(** [hits w c id o d lo n] pushes every depth of [intersect] (as a CSG member) at least [lo] as a
    hit of the member [id]; it is the new count. *)
