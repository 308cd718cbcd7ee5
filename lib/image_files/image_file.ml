(* Image files as POV-Ray 3.7's readers store them. Each reader follows its POV-Ray namesake: which
   container it creates, which gamma curve it assumes, and which values it stores. Nearly all
   store the file's integers untouched (the curve kept as a lookup table for evaluation, POV-Ray's
   TryDeferDecoding); palettes hold decoded single-precision colours; 8-bit grey PNG files go
   through a palette into an 8-bit grey image, truncating the decoded values (png.cpp). *)

type format = Png | Jpeg | Gif | Pot | Ppm | Pgm | Tga | Iff | Tiff | Bmp | Exr | Hdr

type options = {
  gamma_correct : bool;
  default_gamma : Gamma_curve.t option;
  working_gamma : Gamma_curve.t;
  gamma_override : bool;
  premultiply : bool option;
  max_pixels : int;
  max_memory_mb : int;
}

type map_kind = Rgb_map | Rgba_map | Rgbft_map
type entry = { red : float; green : float; blue : float; filter : float; transm : float }

type pixels =
  | Indexed of { kind : map_kind; map : entry array; index : Bytes.t }
  | Grey of { max : int; grey : int array; alpha : int array option; lut : float array option }
  | Colour of { max : int; rgb : int array; alpha : int array option; lut : float array option }

type t = { width : int; height : int; pixels : pixels; premultiplied : bool }

let f = Precision.f32

exception Bad of string

let bad fmt = Printf.ksprintf (fun s -> raise (Bad s)) fmt

exception Over_limit of { msg : string; option : string }

let over_limit option fmt = Printf.ksprintf (fun msg -> raise (Over_limit { msg; option })) fmt

let mul a b = if a = 0 || b = 0 then 0 else if a > max_int / b then max_int else a * b

let commas n =
  let s = string_of_int n in
  let len = String.length s in
  String.concat "" (List.init len (fun i -> (if i > 0 && (len - i) mod 3 = 0 && s.[i - 1] <> '-' then "," else "") ^ String.make 1 s.[i]))

let check_size o ~format ~width ~height ~samples =
  if width < 0 || height < 0 then bad "the %s's size %d×%d is negative" format width height;
  let pixels = mul width height in
  if pixels > o.max_pixels then
    over_limit "--max-pixels N" "the %s's size %d×%d is above povml's limit of %s pixels" format width height (commas o.max_pixels);
  (* each sample is one OCaml int, 8 bytes; a colour-mapped image ([samples] 0) has a byte per pixel *)
  let mib = (if samples = 0 then pixels else mul (mul pixels samples) 8) / 1048576 in
  if mib >= o.max_memory_mb then
    over_limit "--max-memory MIB" "the %s's %d×%d pixels need %s MiB once decoded, more than povml's memory limit of %s MiB" format width
      height (commas mib) (commas o.max_memory_mb)

let check_data ~format ~width ~height ~have ~need_per_pixel =
  let needed = mul (mul width height) need_per_pixel in
  if needed > have then
    bad "the %s's size %d×%d needs at least %s bytes of pixel data, but the file holds %s" format width height (commas needed) (commas have)

let format_name = function
  | Png -> "png"
  | Jpeg -> "jpeg"
  | Gif -> "gif"
  | Pot -> "pot"
  | Ppm -> "ppm"
  | Pgm -> "pgm"
  | Tga -> "tga"
  | Iff -> "iff"
  | Tiff -> "tiff"
  | Bmp -> "bmp"
  | Exr -> "exr"
  | Hdr -> "hdr"

(* fileutil.cpp's extension table, compared without case *)
let format_of_extension name =
  match String.rindex_opt name '.' with
  | None -> None
  | Some i -> (
      match String.lowercase_ascii (String.sub name i (String.length name - i)) with
      | ".tga" -> Some Tga
      | ".png" -> Some Png
      | ".ppm" -> Some Ppm
      | ".pgm" -> Some Pgm
      | ".gif" -> Some Gif
      | ".iff" -> Some Iff
      | ".jpg" | ".jpeg" -> Some Jpeg
      | ".tif" | ".tiff" -> Some Tiff
      | ".bmp" -> Some Bmp
      | ".exr" -> Some Exr
      | ".hdr" -> Some Hdr
      | _ -> None)

(* ---------------------------------------------------------------------------------------------- *)
(* Reading the stored values *)

let linear max p = f (float_of_int p /. float_of_int max)
let value lut max p = match lut with Some l -> l.(p) | None -> linear max p

let rgbft img x y =
  let i = x + (y * img.width) in
  match img.pixels with
  | Indexed { kind; map; index } -> (
      let e = map.(Char.code (Bytes.get index i)) in
      match kind with
      | Rgb_map -> (e.red, e.green, e.blue, 0., 0.)
      | Rgba_map -> (e.red, e.green, e.blue, 0., f (1. -. e.filter))
      | Rgbft_map -> (e.red, e.green, e.blue, e.filter, e.transm))
  | Grey { max; grey; alpha; lut } ->
      let v = value lut max grey.(i) in
      let t = match alpha with None -> 0. | Some a -> f (1. -. linear max a.(i)) in
      (v, v, v, 0., t)
  | Colour { max; rgb; alpha; lut } ->
      let t = match alpha with None -> 0. | Some a -> f (1. -. linear max a.(i)) in
      (value lut max rgb.(3 * i), value lut max rgb.((3 * i) + 1), value lut max rgb.((3 * i) + 2), 0., t)

let index img i = match img.pixels with Indexed { index; _ } -> Char.code (Bytes.get index i) | Grey _ | Colour _ -> 0
let is_indexed img = match img.pixels with Indexed _ -> true | Grey _ | Colour _ -> false

let has_transparency img =
  match img.pixels with
  | Indexed { kind = Rgb_map; _ } -> false
  | Indexed { kind = Rgba_map | Rgbft_map; _ } -> true
  | Grey { alpha; _ } | Colour { alpha; _ } -> alpha <> None

(* IsOpaque: a palette image is opaque when no used entry is transparent (alpha below 1 in an
   RGBA palette, transmit above 0 in an RGBFT one; filter does not count) *)
let is_opaque img =
  match img.pixels with
  | Indexed { kind = Rgb_map; _ } -> true
  | Indexed { kind; map; index } ->
      let transparent (e : entry) = match kind with Rgba_map -> e.filter < 1. | Rgbft_map | Rgb_map -> e.transm > 0. in
      if not (Array.exists transparent map) then true
      else
        let rec go i = i >= Bytes.length index || ((not (transparent map.(Char.code (Bytes.get index i)))) && go (i + 1)) in
        go 0
  | Grey { alpha = None; _ } | Colour { alpha = None; _ } -> true
  | Grey { alpha = Some a; max; _ } | Colour { alpha = Some a; max; _ } -> Array.for_all (fun v -> v >= max) a

let colour_map_size img = match img.pixels with Indexed { map; _ } -> Array.length map | Grey _ | Colour _ -> 0

let with_filter_transmit img ?entry ~filter ~transmit () =
  match img.pixels with
  | Grey _ | Colour _ -> img
  | Indexed { kind; map; index } ->
      (* GetColourMap as RGBFT, then SetColourMap: alpha becomes transmit 1 − alpha *)
      let map =
        Array.map
          (fun (e : entry) ->
            match kind with
            | Rgbft_map -> e
            | Rgb_map -> { e with filter = 0.; transm = 0. }
            | Rgba_map -> { e with filter = 0.; transm = f (1. -. e.filter) })
          map
      in
      let edit (e : entry) =
        let e = match filter with Some v -> { e with filter = f v } | None -> e in
        match transmit with Some v -> { e with transm = f v } | None -> e
      in
      let map = Array.mapi (fun i e -> match entry with Some k when k <> i -> e | Some _ | None -> edit e) map in
      { img with pixels = Indexed { kind = Rgbft_map; map; index } }

(* ---------------------------------------------------------------------------------------------- *)
(* What the readers share *)

(* Image::RGB2Gray, in single precision *)
let rgb2gray r g b = f (f (f (r *. f 0.297) +. f (g *. f 0.589)) +. f (b *. f 0.114))

(* a file's curve as a lookup table, or none when it is neutral (a linear container) *)
let lut_of curve max = if Gamma_curve.is_neutral curve then None else Some (Gamma_curve.lookup_table curve max)

(* IntDecode with a curve *)
let int_decode curve v max = Gamma_curve.decode curve (linear max v)

(* the curve a format with no gamma information of its own assumes: the default, else sRGB *)
let assumed_curve (o : options) =
  if not o.gamma_correct then Gamma_curve.Neutral
  else
    match o.default_gamma with
    | Some d -> Gamma_curve.transcoding ~working:o.working_gamma ~encoding:d
    | None -> Gamma_curve.transcoding ~working:o.working_gamma ~encoding:Gamma_curve.Srgb

(* PPM and PGM assume no curve unless one is given *)
let given_curve (o : options) =
  match o.default_gamma with
  | Some d when o.gamma_correct -> Gamma_curve.transcoding ~working:o.working_gamma ~encoding:d
  | Some _ | None -> Gamma_curve.Neutral

let u8 s i = if i < 0 || i >= String.length s then bad "the file ends early" else Char.code (String.unsafe_get s i)
let u16be s i = (u8 s i lsl 8) lor u8 s (i + 1)
let u32be s i = (u16be s i lsl 16) lor u16be s (i + 2)

let need s n what = if String.length s < n then bad "the file ends inside its %s" what
