(** The reader of [height_field { … }] (POV-Ray's Parse_HField). *)

val parse : Reader.st -> Scene.shape
(** [parse st] reads [{] and the items before the modifiers: the image (a file type keyword and
    name, or a name whose extension gives the type; [gamma], [premultiplied]), then [water_level L]
    (the field's heights below L·65536 raised to it; L/256 before #version 2.0) and [smooth], in
    any order. The heights are taken from the image as POV-Ray takes them, the field set up with
    POV-Ray's bounding hierarchy on ([Objects] reads [hierarchy] among the modifiers), and placed
    by Parse_HField's scaling to the unit cube. The function form [height_field { function W, H
    { … } }] is "not supported yet: 'function'". *)

val heights_of_image : Image_file.t -> int array
(** [heights_of_image img] is the field's heights, [width·height] of them row by row from z = 0
    (the image's bottom row), as POV-Ray's image_height_at takes them: a palette image's index
    times 256; a grey image's value (a float in [0, 1]) times 65535 in single precision; a 16-bit
    colour image's grey (0.297 r + 0.589 g + 0.114 b) times 65535; an 8-bit colour image's
    (r·256 + g)·255, red the high byte and green the low one; each truncated. *)
