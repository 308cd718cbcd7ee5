(** JPEG files as POV-Ray 3.7 reads them (jpeg.cpp): libjpeg's 8-bit grey or RGB samples, sRGB
    unless told otherwise, through a binding of povml's own (lib/image_files/jpeg_stubs.c) whose error manager
    returns libjpeg's message instead of printing it. *)

val read_jpeg : Image_file.options -> string -> Image_file.t
(** [read_jpeg o data] decodes the JPEG file whose bytes are [data]: a grey image for a one-channel
    file, RGB otherwise. Raises {!Image_file.Bad} with libjpeg's message on a malformed file, one
    that ends early (as POV-Ray's reader refuses it) or a CMYK one, and {!Image_file.Over_limit}
    when its size is above the caps of [o]; the size is checked before the samples are
    allocated. *)
