(** The surface shaded at a hit. *)

val at : Compiled.obj -> int -> Compiled.surface
(** [at obj part] is the object's surface, or the surface of the texture of the mesh face [part]
    when the face carries its own. *)
