(** POV-Ray's bounding-slab tree (Build_BBox_Tree; POVRAY-3.7 §15.8), built for the order in which it
    lists objects: POV-Ray fills the camera's starting interior list by walking it (§6.4). *)

type t
(** The tree over a scene's objects. *)

val build : (int * float array) list -> int list -> t
(** [build finite infinite] is POV-Ray's tree over the bounded objects [finite] (id and POV-Ray's
    single-precision box [| llx; lly; llz; lx; ly; lz |], in scene order) and the unbounded ones
    [infinite] (ids in scene order), which POV-Ray puts in a first node of the root. *)

val walk : t -> (float array -> bool) -> int list
(** [walk t in_box] is the ids met by POV-Ray's depth-first walk that enters a node only when
    [in_box] holds for its box (InitRayContainerStateTree): the unbounded objects first, then the
    bounded ones whose box and ancestors' boxes pass, in tree order. *)
