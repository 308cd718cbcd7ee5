(** The decoder fuzz target: one file through one of povml's decoders (PNG, GIF, POT, JPEG, PPM,
    PGM, Targa, TrueType), then every pixel read back (or a string laid out in the font), and
    whether what happened is allowed. Shared by the AFL++ executable [afl_image] and the
    deterministic run of the tests ([test_fuzz_images]). *)

type kind =
  | Image of Image_file.format  (** an image format Image_read reads *)
  | Font  (** a TrueType font, as the text object reads it *)

val kinds : (string * kind) list
(** [kinds] are the targets by name: "png", "gif", "pot", "jpeg", "ppm", "pgm", "tga", "ttf". *)

val options : Image_file.options
(** [options] decode to linear sRGB with small caps (2²⁰ pixels, 64 MiB), so that a file that
    declares a large image is refused at once rather than taking seconds. *)

type outcome =
  | Decoded  (** read, and every pixel (glyph) read back *)
  | Refused of string  (** refused with the decoder's own message ([Image_file.Bad], a limit, [Font.parse]'s error) *)
  | Bug of string  (** anything else: an exception escaped; described, with its backtrace when recorded *)

val run : ?fix_png_crcs:bool -> kind -> string -> outcome
(** [run ?fix_png_crcs kind data] decodes [data]. With [fix_png_crcs] (for "png", default false)
    every chunk's CRC is first made right, so that a mutated file reaches the code past the CRC
    check. *)

val fix_png_crcs : string -> string
(** [fix_png_crcs data] is [data] with the CRC of every whole chunk after the signature
    recomputed. *)
