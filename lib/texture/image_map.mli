(** Images mapped onto pattern space (POV-Ray 3.7's backend/support/imageutil.cpp), operation for
    operation: the four map types, [once], the interpolations, filter and transmit all, and what
    image_map, image_pattern and bump_map make of the pixel found. *)

val colour : Scene.bitmap -> Vec.t -> Colour.t * bool
(** [colour b q] is image_map's colour at the pattern-space point [q], and whether there is
    one: off a [once] image (or where the map type finds no point) it is POV-Ray's clear
    colour <1,1,1,0,1>, and false. *)

val value : Scene.bitmap -> Vec.t -> float
(** [value b q] is image_pattern's value at [q], in [0, 1]: the pixel's grey (or its transmit
    with [use_alpha], or index/255 where POV-Ray takes the index); 0 off a [once] image. *)

val bump : Scene.bitmap -> float -> Vec.t -> Vec.t -> Vec.t
(** [bump b amount q n] is bump_map's normal at [q]: [n] (pattern space) bent by the slope of
    the triangle through the pixel at [q] and its neighbours below left and below right, their
    heights the grey (or the palette index) times [amount]; [n] itself off a [once] image. *)

val opaque : Scene.bitmap -> bool
(** [opaque b] holds when an image_map of [b] never lets light through: not [once], no
    transparent pixel, no [filter] or [transmit] written (Post_Pigment's HAS_FILTER test). *)

val material : Scene.bitmap -> Vec.t -> int -> int
(** [material b q count] is the index, below [count], of the material a material_map of [b] picks
    at the pattern-space point [q] (imageutil.cpp's material_map): 0 off the image, else the
    pixel's palette index, or its red times 255 truncated; an index above [count] is taken modulo
    [count], and one at [count] or above stays on the last material. *)
