(** The scene-language interpreter: text to an immutable [Scene.t] (POVRAY-3.7 §11). *)

type options = { width : int; height : int }
(** What the scene can see of the command line: [image_width] and [image_height]. *)

val load_string : options -> file:string -> string -> Scene.t * Error.t list
(** [load_string opts ~file text] interprets [text] (named [file] in locations) and returns the scene
    and the warnings in the order they arose. Raises [Error.Scene_error] on the first error. *)

val load_file : options -> string -> Scene.t * Error.t list
(** [load_file opts path] reads and interprets the file [path], as [load_string]. *)

val keywords : string list
(** [keywords] are the keywords povml reads (used for "did you mean"). *)
