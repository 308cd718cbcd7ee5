(** zlib decompression (RFC 1950 and RFC 1951), for the image data of PNG files: camlimages hands
    PNG files to libpng, which drops what POV-Ray keeps (16-bit samples, palette indices, the gAMA
    and sRGB chunks), so povml reads PNG files itself. *)

exception Corrupt of string
(** Raised by {!zlib} with a sentence saying what is wrong with the data. *)

val zlib : ?limit:int -> string -> string
(** [zlib ?limit s] is the data the zlib stream [s] holds (its two-byte header, deflate blocks, and
    Adler-32 check, which is read but not verified), or its first [limit] bytes: decompression
    stops there, so that a small stream that inflates to gigabytes takes no more than [limit]
    bytes and a block (64 KiB) of memory. Raises {!Corrupt} on malformed data. *)
