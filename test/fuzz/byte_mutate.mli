(** Mutations of binary files for the deterministic decoder fuzz run: bit flips, bytes and 16- or
    32-bit words set to awkward values (0, 1, 0x7f, 0x80, 0xff, 0xffff, 0x7fffffff …), deletions,
    duplicated and spliced runs, truncation. *)

val mutate : Random.State.t -> seeds:string array -> string -> string
(** [mutate rng ~seeds data] is [data] changed by one to four random mutations; [seeds] are other
    files a splice may take a run from. *)
