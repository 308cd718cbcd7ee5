(** The compile step: looks at the immutable scene once and builds what the tracer calls. *)

val scene : Scene.t -> Compiled.t
(** [scene s] is [s] compiled: flat shapes, constant surfaces, the shadow strategy this scene needs,
    and the camera's starting interior list. *)

val inside_member : float array -> Compiled.obj -> Vec.t -> bool
(** [inside_member stack m p] is the Inside test of the CSG member [m]: a primitive's negated when
    it is inverted, an inverted (morphed) CSG's as it is (§16.3). *)

val inside : float array -> Compiled.shape -> Vec.t -> bool
(** [inside stack shape p] is POV-Ray's Inside test (§2.2, §2.3, §2.6, §15.1); [stack] is traversal room
    for meshes (512 floats). *)
