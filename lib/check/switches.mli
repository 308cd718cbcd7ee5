(** POV-Ray command-line switches as [povml check] and [povml report] pass them to both renderers. *)

val key : string -> string option
(** [key s] is the name of the switch [s] in upper case ("W" for [+W640], "AM" for [+AM2], "A" for
    [-A], "WT" for [+WT2]), or [None] when [s] is not a [+]/[-] switch. *)

val value : string -> string
(** [value s] is what follows the switch's name ("640" for [+W640], "" for [-D]). *)

val mem : string -> string list -> bool
(** [mem k switches] tells whether a switch named [k] is among [switches]. *)

val shown : string list -> string list
(** [shown switches] is [switches] followed by those of [+W160 +H120 +WT2] they do not set: the
    switches as reports show them. *)

val system_include : string option
(** [system_include] is POV-Ray's standard include directory when it is installed where Debian puts it. *)

val for_renderers : cwd:string -> scene:string -> string list -> string list
(** [for_renderers ~cwd ~scene switches] is the switch list both renderers get besides [+I] and [+O]:
    [+W160 +H120 +WT2] unless given, [+L] the scene's directory and [cwd] (the renderers run in a
    private directory), [switches] with relative [+L] directories made absolute, [+L] the standard
    include directory, then [-D -V +FN]. *)
