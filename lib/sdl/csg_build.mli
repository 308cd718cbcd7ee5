(** CSG as POV-Ray builds it: inversion by De Morgan's rule (§16.3), and how an object as read
    enters the scene: a union dissolved into its members, any other CSG kept whole (POVRAY-3.7
    §16.4, §16.5). *)

val invert : Value.obj -> Value.obj
(** [invert o] is [o] under [inverse]: a plane turned over, another primitive flagged inverted, a
    CSG with every member inverted and its kind morphed (a union or merge to an intersection, an
    intersection to a merge); a clipped object's clip objects are left as they are. *)

val add_object : Reader.st -> Value.obj -> unit
(** [add_object st o] adds [o] to the scene's objects and lights: a union that may be split is
    dissolved, its texture, interior and flags going to the members that lack them; any other CSG
    enters whole; an inverted primitive enters as an intersection of itself alone. *)

val scene_obj :
  Value.obj -> ?no_shadow:bool -> ?interior_texture:Scene.texture option -> Scene.shape -> Scene.texture -> Scene.interior -> Scene.obj
(** [scene_obj o shape texture interior] is the scene object of [o] with [shape], [texture] and
    [interior]; its flags, place, interior texture (unless given) and no_shadow (unless given) are
    [o]'s. *)
