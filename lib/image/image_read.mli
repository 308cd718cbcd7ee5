(** Reading an image file of any format povml reads, each by its module (PNG, PPM/PGM, TGA, GIF;
    JPEG through camlimages). *)

val read : Image_file.format -> Image_file.options -> string -> (Image_file.t, string) result
(** [read fmt opts path] decodes the file [path] as [fmt] under [opts], or says why it cannot
    (unreadable, malformed, or a format or variant povml does not read yet). *)
