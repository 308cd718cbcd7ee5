(** POV-Ray's .ini files (POVRAY's processoptions.cpp, ParseFile): [Key=Value] options,
    command-line switches, comments after [;] or [#], sections ([\[Name\]]), further ini files
    and the scene named on a line of their own. Each option becomes the POV-Ray switch it stands
    for, so an ini file and the command line mix in one list, later ones winning. *)

val is_ini : string -> bool
(** [is_ini name] is whether [name] (perhaps with a [\[Section\]] after it) names an ini file: it
    ends in [.ini], in any case. *)

val switches : warn:(Error.t -> unit) -> string -> string list
(** [switches ~warn spec] reads the ini file [spec] ([file.ini] or [file.ini\[Section\]]) into
    switches, in the file's order: [Width=640] is ["+W640"], [Antialias=on] ["+A"], a switch line
    itself, [Include_Ini] and a plain ini file name the switches of that file, a plain other name
    ["+I"] of it. The lines before the first section always count; a named section only when it is
    [spec]'s. [Declare=NAME=VALUE] is ["--declare=NAME=VALUE"]. POV-Ray's options whose value is
    what povml does anyway (its defaults: [Bounding_Method=1], [Split_Unions=off]; console and
    display settings) are dropped silently; other values of them, and the options povml does not
    read yet (file outputs, histograms, shell-outs …), are passed to [warn], located, and dropped.
    [Antialias_Threshold], [Jitter_Amount] and [Bounding_Threshold] set the value without turning
    the feature on, as ["--antialias-threshold=T"], ["--jitter-amount=J"] and
    ["--bounding-threshold=N"]; [Output_File_Type] sets the format alone, as ["--format=png"].
    @raise Error.Scene_error on a file that cannot be read, a key POV-Ray does not have, a value
    an option cannot take, or a line that is none of the above. *)

val is_option : string -> bool
(** [is_option arg] is whether a command-line argument is an ini option ([Width=640],
    [Declare=Size=2]): POV-Ray takes those on the command line too. *)

val option : warn:(Error.t -> unit) -> string -> string list
(** [option ~warn arg] is the switches of the ini option [arg], as [switches] reads a line. *)

val declaration : string -> (string * Value.t) option
(** [declaration "NAME=VALUE"] is the identifier and value POV-Ray's front end declares for
    Declare=NAME=VALUE: a string when VALUE is quoted, else C's atof of it in single precision,
    written with six significant digits and read back ({!Animation.declared}); None without a name. *)

val default_file : getenv:(string -> string option) -> readable:(string -> bool) -> string option * Error.t list
(** [default_file ~getenv ~readable] is the ini file POV-Ray's Unix front end reads before the
    command line, and the warnings of the search: the file the [POVINI] environment variable
    names, else the first [readable] of ./povray.ini, ~/.povray/3.7/povray.ini,
    /etc/povray/3.7/povray.ini, ~/.povrayrc and /etc/povray.ini; None when there is none. A
    [POVINI] that names no readable file is a warning, and the search goes on. *)
