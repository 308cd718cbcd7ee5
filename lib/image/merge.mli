(** Partial renders (+SR/+ER/+SC/+EC: full-size files, the rest black) put back together into the
    image one render writes. Each PNG povml writes records the area it rendered in a tEXt chunk
    ([key]); the parts must have one size, and their areas must cover the image without overlap.
    Since POV-Ray renders in 32-pixel blocks whose antialiasing does not look outside the block, a part made of whole render blocks has the pixels of the whole render: the merge is
    exact. *)

type area = { left : int; top : int; right : int; bottom : int; block : int }
(** 0-based columns and rows, inclusive, and the render block size (+BS). *)

val key : string
(** [key] is ["povml-area"], the tEXt keyword. *)

val to_text : area -> string
(** [to_text a] is "left top right bottom block". *)

val of_text : string -> area option
(** [of_text s] reads [to_text]'s form back. *)

val merge : ?warn:(string -> unit) -> string list -> (Encode.t, string) result
(** [merge ?warn paths] is the image the parts [paths] make up, or a message naming the part (or
    pixel, counted from 1) that does not fit: a file that cannot be read or records no area, sizes
    that differ, two parts that render one pixel, a pixel no part renders. A part whose area ends
    inside the image off a render block's edge is told to [warn]: antialiasing compares a pixel
    with its neighbours within its block (POV-Ray's 32-pixel blocks by default), so only areas
    made of whole blocks merge into exactly one render's image. *)
