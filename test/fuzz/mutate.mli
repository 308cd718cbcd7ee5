(** Mutations of scene text for the deterministic fuzz run: byte changes, deletions, duplicated and
    spliced runs, inserted keywords, directives, punctuation and numbers, truncation. *)

val tokens : string list
(** [tokens] are the words the mutator inserts and the AFL++ dictionary holds: the keywords,
    functions and directives of the language, punctuation, awkward numbers and short snippets. *)

val mutate : Random.State.t -> seeds:string array -> string -> string
(** [mutate rng ~seeds text] is [text] changed by one to four random mutations; [seeds] are other
    texts a splice may take a run from. *)
