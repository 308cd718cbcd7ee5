(** POV-Ray's bounding-slab tree (Build_BBox_Tree; docs/povray-rules.md §15.8), built for the order in which it
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

type room
(** What a walk of a tree writes: its heap and the ray's slab data. A render worker owns one
    ({!Context.t.pov_room}) and lends it to each walk in turn; the tree itself is never written. *)

val room : unit -> room
(** [room ()] is an empty room, fitted to a tree when a walk first needs it. *)

val search : t -> room -> Vec.t -> Vec.t -> (unit -> float) -> (int -> unit) -> unit
(** [search t room o d limit test] is POV-Ray's search of the ray from [o] along [d] through its
    bounding tree [t] (Intersect_BBox_Tree), in [room]: [test id] for every object whose leaf it
    pops, nodes popped nearest entry first (unbounded ones first), until the heap is empty or the
    node popped is entered beyond [limit ()], the best depth so far. *)
