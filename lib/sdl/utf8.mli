(** UTF-8 decoding, for the strings of text objects read with charset utf8 (docs/povray-rules.md §15.9). *)

val decode : invalid:(int -> unit) -> string -> int array
(** [decode ~invalid s] is the character codes of the UTF-8 text [s], in order. A character beyond
    0xFFFF (a four-byte sequence) is dropped, as POV-Ray keeps UCS-2 only; a byte that starts no
    valid sequence is left out, and [invalid] is called with it first. *)
