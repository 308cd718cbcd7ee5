(** GIF files as POV-Ray 3.7 reads them (gif.cpp, gifdecod.cpp). *)

val read_gif : Image_file.options -> string -> Image_file.t
(** [read_gif o data] decodes the first image of a GIF file (LZW, its palette, the transparency
    extension). Raises {!Image_file.Bad} on a malformed file or one POV-Ray could not read. *)
