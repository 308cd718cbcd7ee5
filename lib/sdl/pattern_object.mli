(** The object of an [object] pattern (parstxtr.cpp, OBJECT_TOKEN in Parse_Pattern, and
    Parse_Bound_Clip): read inside the pattern's block, before its list of colours, pigments or
    normals. *)

val parse : Reader.st -> Loc.t -> Scene.object_test
(** [parse st loc] reads, after the '{' of an [object] pattern written at [loc], the objects
    (identifiers or object blocks, textures allowed) and then the transforms that move them all;
    exactly one object must have been written ("object or object identifier expected" otherwise).
    The object is kept whole (a union is never split), its lights are not the scene's, and its
    Inside test is built once. *)
