(** Which files a scene may read and write: scenes come from strangers, so [#include], [#fopen] and
    [file_exists] see only the directories the user allowed. Paths are compared after resolving
    [..] and symbolic links, so neither can lead out of an allowed directory. *)

type t
(** A policy: the directories whose files may be read, and those whose files may be written. *)

val standard_include_dir : string
(** [standard_include_dir] is where POV-Ray's include files are installed
    ([/usr/share/povray-3.7/include]). *)

val standard_font_dir : string
(** [standard_font_dir] is where the standard include directory's font links lead on Debian
    ([/usr/share/fonts/truetype/povray]); it is readable by default, like the include directory. *)

val default : t
(** [default] reads under the working directory and [standard_include_dir], and writes nowhere. *)

val allow_read : t -> string -> t
(** [allow_read t dir] is [t] that also reads the files under [dir]. *)

val allow_write : t -> string -> t
(** [allow_write t dir] is [t] that also writes (and so reads) the files under [dir]. *)

val readable : t -> string -> bool
(** [readable t path] tells whether the existing file [path] lies under a readable directory. *)

val writable : t -> string -> bool
(** [writable t path] tells whether [path], existing or to be created, lies under a writable directory. *)

val check_read : t -> Loc.t -> string -> unit
(** [check_read t loc path] raises an [Error.Access] error at [loc] naming [path] and [--allow-read]
    unless [readable t path]. *)

val check_write : t -> Loc.t -> string -> unit
(** [check_write t loc path] raises an [Error.Access] error at [loc] naming [path] and
    [--allow-write] unless [writable t path]. *)
