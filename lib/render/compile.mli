(** The compile step: looks at the immutable scene once and builds what the tracer calls. *)

val scene : Scene.t -> Compiled.t
(** [scene s] is [s] compiled: flat shapes, constant surfaces, the shadow strategy this scene needs,
    and the camera's starting interior list (the objects whose bounding box and Inside test both
    contain the camera, §6.4). *)

val inside_member : float array -> Compiled.obj -> Vec.t -> bool
(** [inside_member stack m p] is the Inside test of the CSG member [m]: a primitive's negated when
    it is inverted, an inverted (morphed) CSG's as it is (§16.3). *)

val inside : float array -> Compiled.shape -> Vec.t -> bool
(** [inside stack shape p] is POV-Ray's Inside test (§2.2, §2.3, §2.6, §15.1–§15.4: a closed cylinder
    or cone shrunk by 1e-10, an open one grown by it, a disc the half-space behind its normal,
    negated by [inverse]); [stack] is traversal room for meshes (512 floats). *)

val interiors_at : Compiled.obj array -> float array -> Vec.t -> int list
(** [interiors_at holders stack p] is the interiors of the objects of [holders] (top-level objects,
    such as [Compiled.t.screen_holders]) whose bounding box and inside hold [p], the last one
    first: the interior list of a ray starting at [p] (§6.4, §18.4); [stack] as for [inside]. *)
