(** The image blocks of POV-Ray 3.7's parser (parstxtr.cpp's Parse_Image, Parse_Image_Map,
    Parse_Bump_Map and Parse_Image_Pattern): the file type and name, [gamma] and
    [premultiplied], then each block's modifiers. The file is searched like an include file,
    must be readable under the file-access policy, and is decoded as POV-Ray decodes it in the
    scene's gamma mode at that point of the scene. *)

val parse : Reader.st -> string -> Scene.pattern
(** [parse st keyword] reads the block after [keyword] ("image_map", "bump_map" or
    "image_pattern", already read), from its '{' to its '}': a [Bitmap] for the first two, an
    [Image_pattern] for the third. A missing, unreadable or undecodable file is a located error
    naming it; file types and options povml lacks are [not supported yet]. *)

val parse_material_map : Reader.st -> Scene.bitmap
(** [parse_material_map st] reads a [material_map] block after the keyword, from its '{' up to its
    first [texture] (not read): the file, read without gamma correction (its pixels choose the
    textures), and the modifiers [once], [interpolate], [map_type], [repeat], [offset]. *)

val height_field_image : Reader.st -> Image_file.t * string
(** [height_field_image st] reads the file of a [height_field] (its type keyword or a name whose
    extension gives it, then [gamma] and [premultiplied]) and decodes it as POV-Ray's Parse_Image
    does for a height field: without gamma correction unless [gamma] is given. It is the image and
    its name as written; errors as for [parse]. *)
