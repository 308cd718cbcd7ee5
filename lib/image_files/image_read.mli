(** Reading an image file of any format povml reads, each by its module (PNG, PPM/PGM, TGA, GIF,
    JPEG). *)

(** Why a file was not read. *)
type failure =
  | Unreadable of string  (** unreadable, malformed, or a format or variant povml does not read yet *)
  | Over_limit of { msg : string; option : string }
      (** well-formed but larger than the caps of {!Image_file.options} allow; [option] raises the cap *)

val message : failure -> string
(** [message f] is the reason, a sentence about the file. *)

val read : Image_file.format -> Image_file.options -> string -> (Image_file.t, failure) result
(** [read fmt opts path] decodes the file [path] as [fmt] under [opts], or says why it cannot.
    No other exception escapes for any content of the file: every count, size and index the file
    declares is checked against its length and the caps before anything is allocated or read. *)

val of_string : Image_file.format -> Image_file.options -> string -> (Image_file.t, failure) result
(** [of_string fmt opts data] decodes the file contents [data] as {!read} decodes a file. *)
