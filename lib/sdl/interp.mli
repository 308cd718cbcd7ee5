(** The scene-language interpreter: text to an immutable [Scene.t] (docs/povray-rules.md §11). *)

(** What the scene can see of the command line. *)
type options = {
  width : int;  (** [image_width] *)
  height : int;  (** [image_height] *)
  clock : float;  (** [clock], from +K or the animation's frame *)
  animation : Animation.values;  (** [clock_on], [clock_delta], [frame_number] and the other animation identifiers *)
  declares : (string * Value.t) list;  (** Declare=NAME=VALUE: global identifiers set before the scene is read, later ones winning *)
  library_paths : string list;  (** +L directories, searched for include files after the scene's *)
  debug : string -> unit;  (** receives the text of [#debug] as it is read *)
  included : string -> depth:int -> float -> unit;
      (** told of each include file when it has been read: its path, its nesting (1 for a file the
          scene includes) and the seconds it took, nested includes included *)
  limits : Scene_limits.t;  (** what the scene may ask for (loop iterations, nesting, memory …) *)
  access : Access.t;
      (** the files the scene may read and write; the scene's directory and the library paths are
          added to the readable ones when it is loaded *)
}

val default_options : width:int -> height:int -> options
(** [default_options ~width ~height] has clock 0, no library paths, [#debug] text on stderr, no
    include report, [Scene_limits.default] and [Access.default]. *)

val load_string : options -> file:string -> string -> Scene.t * Error.t list
(** [load_string opts ~file text] interprets [text] (named [file] in locations) and returns the scene
    and the warnings in the order they arose. Raises [Error.Scene_error] on the first error. *)

val reader_state : options -> file:string -> string -> Reader.st
(** [reader_state opts ~file text] is the reader's state before the first token of [text] (named
    [file] in locations), as [load_string] starts: for tests of one reader on a piece of text. *)

val load_file : options -> string -> Scene.t * Error.t list
(** [load_file opts path] reads and interprets the file [path], as [load_string]. *)

val keywords : string list
(** [keywords] are the keywords povml reads (used for "did you mean"). *)
