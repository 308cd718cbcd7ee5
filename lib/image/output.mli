(** Writing images as PNG (camlimages) or PPM, whole or not at all; and reading PNGs back. *)

type format = Png | Ppm

val png_max_side : int
(** [png_max_side] is the widest and highest PNG libpng writes (its default user limits, which
    POV-Ray does not raise: its render of a wider PNG fails at the end): 1,000,000 pixels. *)

val write : ?area:string -> format -> string -> Encode.t -> (unit, string) result
(** [write ?area fmt path img] encodes [img] and writes it to [path] whole or not at all
    ([Whole_file.write]: a temporary file beside [path], checked to the last byte, synced and
    renamed over it; a device, a pipe or povml's own output is written into, never replaced).
    On [Error reason] the file at [path] is as it was. SIGINT and SIGTERM are held back
    meanwhile ([Interrupt.hold]): one that has arrived, before or during the write, raises
    [Interrupt.Interrupted] instead, and nothing is written. A PNG gets [area], when given, as its
    "povml-area" tEXt chunk (Merge). *)

val read_png : string -> (Encode.t, string) result
(** [read_png path] loads an 8-bit RGB (or RGBA, alpha dropped) PNG. *)
