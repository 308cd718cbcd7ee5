(** PNG files as POV-Ray 3.7 reads them (png.cpp through libpng), read by povml itself: camlimages
    loses 16-bit samples, palette indices and the gAMA chunk. *)

val read_png : Image_file.options -> string -> Image_file.t
(** [read_png o data] decodes the PNG file whose bytes are [data]: every colour type and depth,
    Adam7 interlacing, tRNS, and its curve from sRGB, gAMA or the default, in POV-Ray's order.
    Raises {!Image_file.Bad} on a malformed file. *)
