(** "Did you mean …" for misspelt identifiers and keywords. *)

val nearest : string -> string list -> string list
(** [nearest name candidates] is up to three candidates closest to [name] by edit distance,
    closest first, and only those close enough to be a plausible typo. *)
