(** PNG tEXt chunks (keyword, NUL, Latin-1 text; ISO/IEC 15948 §11.3.4.3): povml records in each
    image it writes the area that was rendered, so that partial renders can be merged. *)

val area_key : string
(** [area_key] is ["povml-area"]: the chunk that records the area of the image a render drew
    ("left top right bottom", 0-based, inclusive; see Merge). *)

val whole : string -> bool
(** [whole png] is whether [png] is a whole PNG file: the signature, then chunks whose CRCs match,
    the last an IEND chunk that ends it. *)

val add : string -> key:string -> value:string -> string
(** [add png ~key ~value] is the PNG file [png] with a tEXt chunk [key]=[value] before its IEND
    chunk.
    @raise Invalid_argument unless [png] is [whole]. *)

val find : string -> key:string -> string option
(** [find path ~key] is the text of the first tEXt chunk named [key] in the PNG file [path], or
    None (no such chunk, not a PNG, unreadable). *)

val read_all : string -> string
(** [read_all path] is the file's bytes.
    @raise Sys_error when it cannot be read. *)

val crc : string -> int
(** [crc s] is the CRC-32 PNG computes over a chunk's type and data ([s]). *)
