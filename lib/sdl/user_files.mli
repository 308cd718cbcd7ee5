(** The scene's own files: [#fopen], [#read], [#write] and [#fclose] (docs/povray-rules.md §11.3), through
    the access policy of [Reader.options]. *)

val fopen : Reader.st -> unit
(** [fopen st] reads [IDENT "file" read|write|append] after [#fopen] and opens the file; the
    identifier, global, is the open file. *)

val fclose : Reader.st -> Loc.t -> unit
(** [fclose st loc] reads the identifier after [#fclose] (at [loc]) and closes the file it names,
    if any; a file written to that cannot be closed whole (a full disk) is an error at [loc]. *)

val read : Reader.st -> Loc.t -> unit
(** [read st loc] runs [#read (FILE, IDENT, …)] read at [loc]: each identifier takes the next
    float, vector or string of the file; at the end of the data the file is closed and [FILE]
    becomes undefined. *)

val write : Reader.st -> Loc.t -> unit
(** [write st loc] runs [#write (FILE, item, …)] at [loc]: strings, floats and vectors as text, and integers in
    binary after [uint8], [sint8], [uint16be], [uint16le], [sint16be], [sint16le], [sint32be] or
    [sint32le]. The file is flushed at the end; a write that fails (a full disk, a device) is an
    error at [loc] naming the file and the system's reason. *)

val text : Value.t -> string option
(** [text v] is what [#write] writes for [v], as POV-Ray writes it (C's %g): a string as it is, a
    float alone, a vector as "<x,y,z> "; [None] for other values. *)

val data_value : Lexer.t -> Value.t option * bool
(** [data_value lx] is the next value of a data file (a float, a vector of 2 to 4 terms, a colour
    for 5 terms, or a string; [None] at the end) and whether the data ends just after it. *)

val close_all : Reader.st -> unit
(** [close_all st] closes every file the scene left open. *)
