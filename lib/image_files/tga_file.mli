(** Targa files as POV-Ray 3.7 reads them (targa.cpp). *)

val read_tga : Image_file.options -> string -> Image_file.t
(** [read_tga o data] decodes a Targa file: raw or run-length, palette, 15/16/24/32 bit, its origin
    as its header says. Raises {!Image_file.Bad} on a malformed file. *)
