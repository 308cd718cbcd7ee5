(** Writing encoded images: PNG (camlimages) and PPM, whole or not at all; and reading PNGs back. *)

type format = Png | Ppm

val write : ?area:string -> format -> string -> Encode.t -> (unit, string) result
(** [write ?area fmt path img] writes [img] to a temporary file [.povml-XXXXXX.part] beside [path] and
    renames it over [path]; an existing file at [path] stays as it was unless the rename succeeds.
    A [path] that is a device, a pipe, a socket or a symbolic link (+O/dev/null, /dev/stdout) is
    never replaced: the temporary file, in the system's temporary directory, is copied into it.
    SIGINT and SIGTERM are held back meanwhile ([Interrupt.hold]): one that has arrived, before or
    during the write, removes the temporary file and raises [Interrupt.Interrupted] instead.
    Only SIGKILL during these milliseconds can leave the temporary file behind (a partial image,
    under its temporary name, never at [path]). A PNG gets [area], when given, as its
    "povml-area" tEXt chunk (Merge). *)

val read_png : string -> (Encode.t, string) result
(** [read_png path] loads an 8-bit RGB (or RGBA, alpha dropped) PNG. *)
