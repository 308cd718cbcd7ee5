(** PPM and PGM files as POV-Ray 3.7 reads them (ppm.cpp). *)

val read_netpbm : colour:bool -> Image_file.options -> string -> Image_file.t
(** [read_netpbm ~colour o data] decodes a PPM ([colour]) or PGM file, ASCII or binary, 8 or 16
    bit, linear unless a gamma is given. Raises {!Image_file.Bad} on a malformed file. *)
