(** POV-Ray's defaults for reflection, finishes, textures and interiors (docs/povray-rules.md §10). *)

val reflection : Scene.reflection
(** [reflection] is no reflection: min = max = 0, falloff 1, exponent 1. *)

val finish : Scene.finish
(** [finish] is the default finish (§10.1). *)

val layer : Scene.layer
(** [layer] is black pigment with the default finish. *)

val texture : Scene.texture
(** [texture] is the plain texture of {!layer}. *)

val interior : Scene.interior
(** [interior] is ior 1, no fade. *)
