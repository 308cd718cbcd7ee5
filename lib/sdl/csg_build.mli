(** CSG as POV-Ray builds it: inversion by De Morgan's rule (§16.3), and how an object as read
    enters the scene: a union dissolved into its members, any other CSG kept whole (docs/povray-rules.md
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

val textured : Value.obj -> bool
(** [textured o] is POV-Ray's TEXTURED_OBJECT: [o] or a member of it at any depth has a texture. *)

val core : Value.obj -> Value.obj
(** [core o] is [o] under its clipped_by and bounded_by wrappers: the object POV-Ray's type tests see. *)

val clip_objects : Value.obj -> Value.member list
(** [clip_objects o] is [o]'s clip objects ([] without clipped_by). *)

val bound_objects : Value.obj -> Value.member list
(** [bound_objects o] is [o]'s bounding objects ([] without bounded_by). *)

val wrap : Scene.csg_kind -> Value.obj -> Value.member list -> Value.obj
(** [wrap kind o objs] is [o] clipped ([Clipped]) or bounded ([Bounded]) by [objs] as well: added
    to its wrapper of that kind when it is one, else a new wrapper holding [o] first, which takes
    [o]'s texture, interior and flags. [o] itself when [objs] is empty. *)

val patch : Value.obj -> bool
(** [patch o] is POV-Ray's PATCH_OBJECT: [o] has no inside (a triangle, a mesh without
    inside_vector, or a CSG with such a member). *)

val resolved : Reader.st -> Value.obj -> Scene.texture * Scene.interior
(** [resolved st o] is [o]'s texture (the default texture without one) and interior (the default
    interior without one, a legacy finish ior and caustics moved into it) (§2.7). *)

val kept_obj :
  Reader.st -> texture:Scene.texture option -> cut_parent:bool -> ?interior_texture:Scene.texture -> interior:Scene.interior -> Value.obj -> Scene.obj
(** [kept_obj st ~texture ~cut_parent ~interior o] is [o] as a CSG kept whole enters the scene, its
    textures passed down as Post_Process passes them ([texture]: the parent's, [cut_parent]: the
    parent is an intersection with cutaway_textures); the lights among its members join the
    scene's lights. *)
