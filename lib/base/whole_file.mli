(** Files written whole or not at all: every byte written and checked, synced to the disk, and only
    then put at the file's name, so that a full disk, a failing device or a missing permission
    never leaves a half-written file nor loses the file that was there. *)

val write : string -> string -> (unit, string) result
(** [write path data] puts [data] at [path]. The bytes go to a new temporary file
    [.povml-XXXXXX.part] beside [path]; each write is checked to the last byte, the file is synced
    ([fsync]) and closed, and only then renamed onto [path] (and the directory synced). A symbolic
    link to a regular file keeps its name: the file it points to is replaced. A [path] that is a
    device, a pipe, a socket or povml's own standard output or error (+O/dev/null, /dev/stdout) is
    never replaced: the bytes are written into it, checked the same way.

    [Error reason] says why in plain words (the system's own text, "No space left on device",
    "Permission denied"), followed for a regular file by what became of it: "; the old file is
    kept" or "; nothing was written". No temporary file is left behind, except under SIGKILL.

    SIGINT and SIGTERM are held back meanwhile ([Interrupt.hold]): one that has arrived, before or
    during the write, removes the temporary file and raises [Interrupt.Interrupted] instead of
    the rename. *)

val write_parts : string -> string list -> (unit, string) result
(** [write_parts path parts] is [write path (String.concat "" parts)], without making the
    concatenation (a large image's header and pixels). *)

val temp_file : string -> (string, string) result
(** [temp_file dir] is [Ok path] for a new empty file [.povml-XXXXXX.part] in [dir], private to its
    owner, or [Error reason] naming [dir] ("/tmp: No space left on device"). *)
