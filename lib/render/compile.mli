(** The compile step: looks at the immutable scene once and builds what the tracer calls. *)

val scene : Scene.t -> Compiled.t
(** [scene s] is [s] compiled: flat shapes, constant surfaces, the shadow strategy this scene needs,
    and the camera's starting interior list (the objects whose bounding box and Inside test both
    contain the camera, §6.4). *)

