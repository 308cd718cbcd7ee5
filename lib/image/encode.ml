(* From linear working colours to 8-bit file values, in POV-Ray's precision (docs/povray-rules.md §8.1). *)

type t = { width : int; height : int; pixels : Bytes.t }

type gamma = Gamma_off | Working of float

(* The sRGB curve with single-precision constants and arithmetic, as POV-Ray evaluates it: it keeps
   colours and gamma curves in single precision (§8.3). *)

let c_threshold = Precision.f32 0.0031308
let c_linear = Precision.f32 12.92
let c_scale = Precision.f32 1.055
let c_offset = Precision.f32 0.055
let c_exponent = Precision.(f32 (1. /. f32 2.4))

let srgb_encode x =
  let open Precision in
  if x <= c_threshold then f32 (c_linear *. x) else f32 (f32 (c_scale *. f32 (Float.pow x c_exponent)) -. c_offset)

let channel gamma x =
  let x = Precision.f32 x in
  let e =
    match gamma with
    | Gamma_off -> x
    | Working g -> srgb_encode (if g = 1. then Float.max x 0. else Precision.(f32 (Float.pow (Float.max x 0.) (f32 g))))
  in
  let c = if e < 0. then 0. else if e > 1. then 1. else e in
  (* §8.1: floor(clip(v)·255 + 0.5), the product in single precision *)
  int_of_float (Float.floor (Precision.f32 (c *. 255.) +. 0.5))

let image gamma (img : Image.t) =
  let n = img.width * img.height in
  let pixels = Bytes.create (3 * n) in
  for i = 0 to (3 * n) - 1 do
    Bytes.unsafe_set pixels i (Char.unsafe_chr (channel gamma (Image.channel img i)))
  done;
  { width = img.width; height = img.height; pixels }
