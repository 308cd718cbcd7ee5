(** The reader of [height_field { … }] (POV-Ray's Parse_HField). *)

val parse : Reader.st -> Scene.shape
(** [parse st] reads [{] and the items before the modifiers: the image (a file type keyword and
    name, or a name whose extension gives the type; [gamma], [premultiplied]), then [water_level L]
    (the field's heights below L·65536 raised to it; L/256 before #version 2.0) and [smooth], in
    any order. The heights are taken from the image as POV-Ray takes them, the field set up with
    POV-Ray's bounding hierarchy on ([Objects] reads [hierarchy] among the modifiers), and placed
    by Parse_HField's scaling to the unit cube. The function form [height_field { function W, H
    { … } }] is "not supported yet: 'function'". *)
