(** The reader of blob (POV-Ray's Parse_Blob and Parse_Blob_Element_Mods) and the blob's own
    object modifiers. *)

val parse : Reader.st -> Scene.shape
(** [parse st] reads, after [blob {], the threshold (1 unless written) and the components:
    [sphere { C, r, [strength] s … }], [cylinder { B, A, r, [strength] s … }] and the old
    [component s, r, C], each with its transforms and texture; it stops at the first other word.
    Errors: no component ("Need at least one component in a blob."), a cylinder whose ends are
    within 1e-10 ("Degenerate cylindrical component in blob."). *)

val set_hierarchy : bool -> Value.obj -> Value.obj
(** [set_hierarchy on o] is the blob [o] with or without its bounding sphere hierarchy, while its
    own block is read; a blob already set up keeps the hierarchy it was built with. *)

val finish : Value.obj -> Value.obj
(** [finish o] sets up the blob [o] (or the blob a [clipped_by] wraps) once its modifiers are
    read: its box as POV-Ray's Make_Blob computes it, which later transforms only map. *)
