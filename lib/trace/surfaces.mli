(** The texture shaded at a hit. *)

val at : Compiled.obj -> int -> Compiled.texture
(** [at obj part] is the object's texture, or the texture of the mesh face [part] when the face
    carries its own. *)

val seen : Compiled.obj -> int -> inside:bool -> Compiled.texture
(** [seen obj part ~inside] is the texture a ray sees at the hit: the interior texture when the ray
    meets the surface from [inside] (its normal, inverse taken into account, points along the ray)
    and the object has one, else {!at}. *)

val around : float array -> float -> int * int
(** [around values v] is the pair of entries (previous, current) of a texture map whose [values]
    (in the order written, not empty) surround the pattern value [v], as POV-Ray's
    Search_Blend_Map finds them: the last entry alone from its value on, else the first entry whose
    value is not below [v] and the one before it, or that entry alone when [v] equals its value or
    it is the first. *)

val cutaway : float array -> Compiled.t -> Compiled.obj -> Vec.t -> (float * Compiled.texture) list
(** [cutaway stack sc obj p] is what a member [obj] with a [Cutaway] texture shows at [p] (POV-Ray's
    Determine_Textures on the hit's top-level CSG): the textures of the members [p] lies in, in
    member order, a CSG member's found the same way, each weighed 1/n for the n found at its level;
    in a difference only its first member's. [stack] is traversal room for the Inside tests. A
    blob with textured components has a [Cutaway] texture too: its components' textures (the
    blob's own, the last of [obj.face_texs], for those without one) weighed by their fields at
    [p] (Blob::Determine_Textures). *)
