(* colourspace.cpp's gamma curves. Every operation rounds to single precision, as POV-Ray's
   float arithmetic does; powf is the double-precision power rounded once. *)

type t = Neutral | Srgb | Power of float | Scaled of t * float | Transcoding of { working : t; encoding : t }

let f = Precision.f32
let powf a b = f (Float.pow a b)

(* PowerLawGammaCurve::IsNeutral and ScaledGammaCurve::IsNeutral (double comparisons) *)
let power_is_neutral g = Float.abs (1. -. g) <= 0.01
let scale_is_neutral s = Float.abs (1. -. s) <= 1e-6

let by_encoding_gamma g =
  let g = f g in
  if power_is_neutral g then Neutral else Power g

let by_decoding_gamma g = by_encoding_gamma (f (1. /. f g))

let is_neutral c = match c with Neutral -> true | Srgb | Power _ | Scaled _ | Transcoding _ -> false

let scaled_by_decoding factor c =
  let enc = f (1. /. f factor) in
  if scale_is_neutral enc then c
  else
    match c with
    | Scaled (base, e) -> Scaled (base, f (e *. enc))
    | Neutral | Srgb | Power _ | Transcoding _ -> Scaled (c, enc)

(* the curves' Matches: the same kind with the same parameters *)
let rec matches a b =
  match (a, b) with
  | Neutral, _ -> is_neutral b
  | Srgb, Srgb -> true
  | Power x, Power y -> power_is_neutral (f (x /. y))
  | Scaled (ba, x), Scaled (bb, y) -> ba = bb && scale_is_neutral (f (x /. y))
  | Transcoding a, Transcoding b -> matches a.encoding b.encoding && matches a.working b.working
  | (Srgb | Power _ | Scaled _ | Transcoding _), _ -> false

(* ApproximateDecodingGamma of a power law *)
let decoding_gamma g = f (1. /. g)

let transcoding ~working ~encoding =
  if is_neutral working then encoding
  else if matches working encoding then Neutral
  else
    match (working, encoding) with
    | Power w, Neutral -> by_encoding_gamma (decoding_gamma w)
    | Power w, Power e -> by_encoding_gamma (f (decoding_gamma w /. decoding_gamma e))
    | _ -> Transcoding { working; encoding }

let rec decode c x =
  match c with
  | Neutral -> x
  | Srgb -> if x < f 0.04045 then f (x /. f 12.92) else powf (f (f (x +. f 0.055) /. f 1.055)) (f 2.4)
  | Power g -> powf (Float.max x 0.) (f (1. /. g))
  | Scaled (base, e) -> decode base (f (x /. e))
  | Transcoding { working; encoding } -> encode working (decode encoding x)

and encode c x =
  match c with
  | Neutral -> x
  | Srgb -> if x <= f 0.0031308 then f (x *. f 12.92) else f (f (f 1.055 *. powf x (f (1. /. f 2.4))) -. f 0.055)
  | Power g -> powf (Float.max x 0.) g
  | Scaled (base, e) -> f (encode base x *. e)
  | Transcoding { working; encoding } -> encode encoding (decode working x)

let lookup_table c max =
  let m = float_of_int max in
  Array.init (max + 1) (fun i -> decode c (f (float_of_int i /. m)))
