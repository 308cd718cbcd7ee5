(** Image files decoded as POV-Ray 3.7 keeps them (base/image/image.cpp and the readers png.cpp,
    jpeg.cpp, gif.cpp, ppm.cpp, pgm.cpp, targa.cpp): the container POV-Ray's reader picks
    (palette, grey, grey and alpha, RGB, RGBA; 8 or 16 bits), the values as it stores them (raw
    integers, with the file's gamma curve kept for decoding at evaluation, or a palette of decoded
    single-precision colours), and whether the colour is premultiplied by alpha. The values are
    immutable; the parser's per-index filter and transmit make new images. *)

(** The file formats POV-Ray 3.7 names ([sys] is PNG on Unix; [pot], for height fields only, is
    a GIF holding 16-bit heights). *)
type format = Png | Jpeg | Gif | Pot | Ppm | Pgm | Tga | Iff | Tiff | Bmp | Exr | Hdr

(** How the parser asks for the image to be decoded (Image::ReadOptions). *)
type options = {
  gamma_correct : bool;  (** decode to linear at all; otherwise the raw values are used *)
  default_gamma : Gamma_curve.t option;  (** the curve assumed where the file says nothing *)
  working_gamma : Gamma_curve.t;  (** the scene's working curve ([Neutral] for none) *)
  gamma_override : bool;  (** [default_gamma] even where the file names its own *)
  premultiply : bool option;  (** the [premultiplied] keyword, where the format has alpha *)
  max_pixels : int;  (** the most pixels a file may declare (the +W×+H cap, [--max-pixels]) *)
  max_memory_mb : int;  (** the most memory, in MiB, the decoded samples may take ([--max-memory]) *)
}

(** What a palette entry holds: POV-Ray's colour maps are RGB, RGBA (the filter field holding
    alpha) or RGBFT. *)
type map_kind = Rgb_map | Rgba_map | Rgbft_map

(** One palette entry, single precision ([filter] is alpha in an [Rgba_map]). *)
type entry = { red : float; green : float; blue : float; filter : float; transm : float }

(** The stored pixels, row-major from the top row. *)
type pixels =
  | Indexed of { kind : map_kind; map : entry array; index : Bytes.t }  (** ColourMapImage *)
  | Grey of { max : int; grey : int array; alpha : int array option; lut : float array option }
      (** Gray/GrayA images of 8 ([max] 255) or 16 bits (65535); [lut]: the file's curve
          (a Nonlinear image), else the values are linear *)
  | Colour of { max : int; rgb : int array; alpha : int array option; lut : float array option }
      (** RGB/RGBA images, three values per pixel in [rgb] *)

(** A decoded image. *)
type t = { width : int; height : int; pixels : pixels; premultiplied : bool }

val format_of_extension : string -> format option
(** [format_of_extension name] is the format POV-Ray infers from the extension of [name]
    (InferFileTypeFromExt), None without a known one. *)

val format_name : format -> string
(** [format_name f] is the keyword of [f] ("png", "jpeg", …). *)

val rgbft : t -> int -> int -> float * float * float * float * float
(** [rgbft img x y] is POV-Ray's GetRGBFTValue of the pixel at column [x], row [y] (0 the top):
    red, green, blue, filter and transmit in single precision, alpha turned into transmit
    [1 − alpha]. *)

val index : t -> int -> int
(** [index img i] is the palette index of pixel [i] (x + y·width) of an indexed image, 0 for others. *)

val is_indexed : t -> bool
(** [is_indexed img] holds for a palette image. *)

val has_transparency : t -> bool
(** [has_transparency img] is HasTransparency: an alpha channel, an RGBA or an RGBFT palette. *)

val is_opaque : t -> bool
(** [is_opaque img] is IsOpaque: no pixel lets light through. *)

val colour_map_size : t -> int
(** [colour_map_size img] is the number of palette entries (0 without a palette). *)

val with_filter_transmit : t -> ?entry:int -> filter:float option -> transmit:float option -> unit -> t
(** [with_filter_transmit img ?entry ~filter ~transmit ()] is [img] with its palette made RGBFT
    (alpha becoming transmit) and the filter or transmit of one entry, or of all without
    [entry], replaced (single precision), as the image_map's [filter]/[transmit] do.
    [img] is returned as it is when it has no palette. *)

(** {1 What the format readers share} *)

exception Bad of string
(** A malformed or unsupported file, with the reason. *)

val bad : ('a, unit, string, 'b) format4 -> 'a
(** [bad fmt …] raises {!Bad} with the message. *)

exception Over_limit of { msg : string; option : string }
(** A well-formed file declaring more than the caps of {!options} allow: the reason, and the
    command-line option that raises the cap ("--max-pixels N"). *)

val over_limit : string -> ('a, unit, string, 'b) format4 -> 'a
(** [over_limit option fmt …] raises {!Over_limit} with the message and [option]. *)

val mul : int -> int -> int
(** [mul a b] is [a × b] for non-negative [a] and [b], or [max_int] when the product overflows:
    sizes declared by a file are multiplied with it, so that a product is never wrapped round to
    a small number. *)

val commas : int -> string
(** [commas n] is [n] written with thousands separators (67,108,864). *)

val check_size : options -> format:string -> width:int -> height:int -> samples:int -> unit
(** [check_size o ~format ~width ~height ~samples] raises {!Bad} when a dimension is negative, and
    {!Over_limit} when the [width × height] pixels the [format] file declares are more than
    [o.max_pixels], or when their [samples] values per pixel (one OCaml int each; 0 for a palette
    image's one byte) need more than [o.max_memory_mb]. Every reader calls it before it allocates anything of the image's size. *)

val check_data : format:string -> width:int -> height:int -> have:int -> need_per_pixel:int -> unit
(** [check_data ~format ~width ~height ~have ~need_per_pixel] raises {!Bad} unless [have] bytes of
    data can hold [width × height] pixels of at least [need_per_pixel] bytes each (a minimum the
    format cannot do without): a file's length bounds what it may ask for. *)

val f : float -> float
(** [f x] is [x] rounded to single precision ({!Precision.f32}). *)

val linear : int -> int -> float
(** [linear max p] is the integer sample [p] of a container with maximum [max] as a float in
    [0, 1], single precision. *)

val rgb2gray : float -> float -> float -> float
(** [rgb2gray r g b] is POV-Ray's Image::RGB2Gray, in single precision. *)

val lut_of : Gamma_curve.t -> int -> float array option
(** [lut_of curve max] is [curve] as a lookup table over [0, max], or None when it is neutral. *)

val int_decode : Gamma_curve.t -> int -> int -> float
(** [int_decode curve v max] is POV-Ray's IntDecode: the sample [v] of [max] decoded by [curve]. *)

val assumed_curve : options -> Gamma_curve.t
(** [assumed_curve o] is the curve of a format without gamma information of its own: the default
    gamma when one is set, else sRGB; neutral without gamma correction. *)

val given_curve : options -> Gamma_curve.t
(** [given_curve o] is PPM's and PGM's curve: the one given, else neutral. *)

val u8 : string -> int -> int
(** [u8 s i] is the byte of [s] at [i].
    @raise Bad when [i] is outside [s] (the file ends early). *)

val u16be : string -> int -> int
(** [u16be s i] is the big-endian 16-bit number at [i]. *)

val u32be : string -> int -> int
(** [u32be s i] is the big-endian 32-bit number at [i]. *)

val need : string -> int -> string -> unit
(** [need s n what] raises {!Bad} unless [s] holds at least [n] bytes ([what]: the part read). *)
