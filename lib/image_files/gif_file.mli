(** GIF files as POV-Ray 3.7 reads them (gif.cpp, gifdecod.cpp). *)

val read_gif : Image_file.options -> string -> Image_file.t
(** [read_gif o data] decodes the first image of a GIF file (LZW, its palette, the transparency
    extension). Raises {!Image_file.Bad} on a malformed file or one POV-Ray could not read. *)

val read_pot : Image_file.options -> string -> Image_file.t
(** [read_pot o data] decodes a POT file (Fractint's continuous potential): a GIF twice as wide as
    its heights, the right half holding the low byte of each index on the left; the result is a
    16-bit grey image of the combined indices, its palette ignored and no gamma applied. Raises
    {!Image_file.Bad} on an odd width. *)
