(** Writing encoded images: PNG (camlimages) and PPM, whole or not at all. *)

type format = Png | Ppm

val write : format -> string -> Encode.t -> (unit, string) result
(** [write fmt path img] writes [img] to a temporary file beside [path] and renames it over [path],
    so a failed or interrupted write never leaves a partial file. *)

val read_png : string -> (Encode.t, string) result
(** [read_png path] loads an 8-bit RGB (or RGBA, alpha dropped) PNG. *)
