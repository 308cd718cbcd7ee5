(** The evaluated scene as readable text, for [povml --dump]. *)

val scene : Scene.t -> string
(** [scene s] lists the settings, camera, lights and every object of [s] with its final shape,
    transform, texture (finish values that differ from the default) and interior, one object per
    block, each followed by the place where it was written. *)

val obj : Scene.obj -> string
(** [obj o] is [o] as {!scene} lists it: its shape, texture, interior and flags, then where it was
    written. *)

val num : float -> string
(** [num x] prints [x] as the dump does: integers without a point, others with up to 10 significant
    digits. *)

val pigment : Scene.pigment -> string
(** [pigment p] is the body of [p] as {!scene} lists it (without [pigment { }]). *)
