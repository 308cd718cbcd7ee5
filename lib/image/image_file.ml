(* Image files as POV-Ray 3.7's readers store them. Each reader follows its POV-Ray namesake: which
   container it creates, which gamma curve it assumes, and which values it stores. Nearly all
   store the file's integers untouched (the curve kept as a lookup table for evaluation, POV-Ray's
   TryDeferDecoding); palettes hold decoded single-precision colours; 8-bit grey PNG files go
   through a palette into an 8-bit grey image, truncating the decoded values (png.cpp). *)

type format = Png | Jpeg | Gif | Ppm | Pgm | Tga | Iff | Tiff | Bmp | Exr | Hdr

type options = {
  gamma_correct : bool;
  default_gamma : Gamma_curve.t option;
  working_gamma : Gamma_curve.t;
  gamma_override : bool;
  premultiply : bool option;
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

let format_name = function
  | Png -> "png"
  | Jpeg -> "jpeg"
  | Gif -> "gif"
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

let u8 s i = Char.code (String.unsafe_get s i)
let u16be s i = (u8 s i lsl 8) lor u8 s (i + 1)
let u32be s i = (u16be s i lsl 16) lor u16be s (i + 2)

let need s n what = if String.length s < n then bad "the file ends inside its %s" what

(* ---------------------------------------------------------------------------------------------- *)
(* PNG (png.cpp with libpng: no transformations but the unpacking of small palette indices) *)

(* Adam7's passes: first column, first row, column step, row step *)
let adam7 = [| (0, 0, 8, 8); (4, 0, 8, 8); (0, 4, 4, 8); (2, 0, 4, 4); (0, 2, 2, 4); (1, 0, 2, 2); (0, 1, 1, 2) |]

(* the samples of the image, [channels] per pixel, unpacked to one int each, row-major *)
let png_samples data ~width ~height ~depth ~channels ~interlaced =
  let samples = Array.make (width * height * channels) 0 in
  let bits_pp = depth * channels in
  let bpp = max 1 (bits_pp / 8) in
  let pos = ref 0 in
  let pass (x0, y0, dx, dy) =
    let pw = if width > x0 then (width - x0 + dx - 1) / dx else 0 in
    let ph = if height > y0 then (height - y0 + dy - 1) / dy else 0 in
    if pw > 0 && ph > 0 then begin
      let stride = ((pw * bits_pp) + 7) / 8 in
      let prev = Bytes.make stride '\000' and row = Bytes.make stride '\000' in
      for r = 0 to ph - 1 do
        if !pos + 1 + stride > String.length data then bad "the image data ends early";
        let ftype = u8 data !pos in
        Bytes.blit_string data (!pos + 1) row 0 stride;
        pos := !pos + 1 + stride;
        let get b i = Char.code (Bytes.unsafe_get b i) in
        for i = 0 to stride - 1 do
          let a = if i >= bpp then get row (i - bpp) else 0 in
          let b = get prev i in
          let c = if i >= bpp then get prev (i - bpp) else 0 in
          let x = get row i in
          let v =
            match ftype with
            | 0 -> x
            | 1 -> x + a
            | 2 -> x + b
            | 3 -> x + ((a + b) / 2)
            | 4 ->
                let p = a + b - c in
                let pa = abs (p - a) and pb = abs (p - b) and pc = abs (p - c) in
                x + if pa <= pb && pa <= pc then a else if pb <= pc then b else c
            | _ -> bad "an invalid row filter"
          in
          Bytes.unsafe_set row i (Char.unsafe_chr (v land 255))
        done;
        let y = y0 + (r * dy) in
        for k = 0 to pw - 1 do
          let x = x0 + (k * dx) in
          for ch = 0 to channels - 1 do
            let s =
              match depth with
              | 16 -> (get row ((((k * channels) + ch) * 2)) lsl 8) lor get row ((((k * channels) + ch) * 2) + 1)
              | 8 -> get row ((k * channels) + ch)
              | _ ->
                  (* 1, 2 or 4 bits: one channel, the leftmost pixel in the high bits *)
                  let bit = k * depth in
                  (get row (bit / 8) lsr (8 - depth - (bit mod 8))) land ((1 lsl depth) - 1)
            in
            samples.((((y * width) + x) * channels) + ch) <- s
          done
        done;
        Bytes.blit row 0 prev 0 stride
      done
    end
  in
  if interlaced then Array.iter pass adam7 else pass (0, 0, 1, 1);
  samples

let read_png (o : options) s =
  need s 8 "signature";
  if String.sub s 0 8 <> "\137PNG\r\n\026\n" then bad "not a PNG file";
  let ihdr = ref None and plte = ref "" and trns = ref None and gama = ref None and srgb = ref false in
  let idat = Buffer.create (String.length s) in
  let rec chunks pos =
    if pos + 8 > String.length s then bad "the file ends before its IEND chunk";
    let len = u32be s pos and kind = String.sub s (pos + 4) 4 in
    if pos + 12 + len > String.length s then bad "the %s chunk ends early" kind;
    let body = String.sub s (pos + 8) len in
    match kind with
    | "IEND" -> ()
    | _ ->
        (match kind with
        | "IHDR" -> ihdr := Some body
        | "PLTE" -> plte := body
        | "tRNS" -> trns := Some body
        | "gAMA" -> if len >= 4 then gama := Some (float_of_int (u32be body 0) *. 0.00001)
        | "sRGB" -> srgb := true
        | "IDAT" -> Buffer.add_string idat body
        | _ -> ());
        chunks (pos + 12 + len)
  in
  chunks 8;
  let h = match !ihdr with Some h when String.length h >= 13 -> h | Some _ | None -> bad "no IHDR chunk" in
  let width = u32be h 0 and height = u32be h 4 and depth = u8 h 8 and ctype = u8 h 9 and interlaced = u8 h 12 = 1 in
  if width <= 0 || height <= 0 || width > 1 lsl 24 || height > 1 lsl 24 then bad "invalid dimensions";
  (* the file's curve: the user's, else sRGB by its chunk, else the gAMA power law, else the
     default (sRGB) *)
  let curve =
    if not o.gamma_correct then Gamma_curve.Neutral
    else
      let working = o.working_gamma in
      match (o.default_gamma, !gama) with
      | Some d, _ when o.gamma_override -> Gamma_curve.transcoding ~working ~encoding:d
      | _ when !srgb -> Gamma_curve.transcoding ~working ~encoding:Srgb
      | _, Some g -> Gamma_curve.transcoding ~working ~encoding:(Gamma_curve.by_encoding_gamma g)
      | Some d, None -> Gamma_curve.transcoding ~working ~encoding:d
      | None, None -> Gamma_curve.transcoding ~working ~encoding:Srgb
  in
  let premultiplied = Option.value o.premultiply ~default:false in
  let channels =
    match ctype with 0 -> 1 | 2 -> 3 | 3 -> 1 | 4 -> 2 | 6 -> 4 | _ -> bad "unsupported color type in PNG image"
  in
  let data = try Inflate.zlib (Buffer.contents idat) with Inflate.Corrupt m -> bad "%s" m in
  let samples = png_samples data ~width ~height ~depth ~channels ~interlaced in
  let n = width * height in
  let pixels =
    match ctype with
    | 3 ->
        let pal = !plte in
        let count = String.length pal / 3 in
        let trans = Option.value !trns ~default:"" in
        let map =
          Array.init count (fun i ->
              let alpha = if i < String.length trans then linear 255 (u8 trans i) else 1. in
              {
                red = int_decode curve (u8 pal (3 * i)) 255;
                green = int_decode curve (u8 pal ((3 * i) + 1)) 255;
                blue = int_decode curve (u8 pal ((3 * i) + 2)) 255;
                filter = alpha;
                transm = 0.;
              })
        in
        (* an index past the palette reads an entry POV-Ray's vector does not hold; povml refuses *)
        Array.iter (fun v -> if v >= count then bad "a palette index beyond the palette") samples;
        Indexed { kind = Rgba_map; map; index = Bytes.init n (fun i -> Char.chr samples.(i)) }
    | 0 when depth <= 8 ->
        (* a palette of the decoded grey levels; stored through it into an 8-bit grey image, the
           level truncated; libpng gives the tRNS chunk's first byte as entry 0's alpha *)
        let levels = (1 lsl depth) - 1 in
        let alpha0 = match !trns with Some t when String.length t > 0 -> Some (linear 255 (u8 t 0)) | Some _ | None -> None in
        let grey_of v =
          let g = int_decode curve v levels in
          int_of_float (f (rgb2gray g g g *. 255.))
        in
        let table = Array.init (levels + 1) grey_of in
        let alpha =
          Option.map
            (fun a0 ->
              let a i = if i = 0 then a0 else 1. in
              Array.map (fun v -> int_of_float (f (a v *. 255.))) samples)
            alpha0
        in
        Grey { max = 255; grey = Array.map (fun v -> table.(v)) samples; alpha; lut = None }
    | 0 -> Grey { max = 65535; grey = samples; alpha = None; lut = lut_of curve 65535 }
    | 4 ->
        let max = if depth > 8 then 65535 else 255 in
        Grey { max; grey = Array.init n (fun i -> samples.(2 * i)); alpha = Some (Array.init n (fun i -> samples.((2 * i) + 1))); lut = lut_of curve max }
    | 2 ->
        let max = if depth > 8 then 65535 else 255 in
        Colour { max; rgb = samples; alpha = None; lut = lut_of curve max }
    | _ ->
        let max = if depth > 8 then 65535 else 255 in
        Colour
          {
            max;
            rgb = Array.init (3 * n) (fun k -> samples.(((k / 3) * 4) + (k mod 3)));
            alpha = Some (Array.init n (fun i -> samples.((4 * i) + 3)));
            lut = lut_of curve max;
          }
  in
  { width; height; pixels; premultiplied }

(* ---------------------------------------------------------------------------------------------- *)
(* PPM and PGM (ppm.cpp, pgm.cpp): P3/P6 and P2/P5, 8 or 16 bits, the depth folded into the curve *)

(* the header's lines, as POV-Ray's getline reads them: comments cut, empty lines skipped *)
let netpbm_header s =
  let pos = ref 2 in
  let line () =
    let rec next () =
      if !pos >= String.length s then bad "the header ends early";
      let e = match String.index_from_opt s !pos '\n' with Some e -> e | None -> String.length s in
      let l = String.sub s !pos (e - !pos) in
      pos := e + 1;
      let l = match String.index_opt l '#' with Some c -> String.sub l 0 c | None -> l in
      if l = "" then next () else l
    in
    next ()
  in
  let wh = line () in
  let width, height = try Scanf.sscanf wh " %d %d" (fun w h -> (w, h)) with _ -> bad "cannot read width and height" in
  if width <= 0 || height <= 0 then bad "invalid width or height";
  let depth = try Scanf.sscanf (line ()) " %u" Fun.id with _ -> bad "cannot read the color depth" in
  if depth > 65535 || depth < 1 then bad "unsupported number of colors";
  (width, height, depth, !pos)

(* Read_ASCII_File_Number *)
let ascii_numbers s start =
  let pos = ref start in
  fun () ->
    let is_space c = c = ' ' || c = '\t' || c = '\n' || c = '\r' || c = '\011' || c = '\012' in
    while !pos < String.length s && is_space s.[!pos] do incr pos done;
    if !pos >= String.length s then bad "unexpected end of file";
    let b = !pos in
    while !pos < String.length s && s.[!pos] >= '0' && s.[!pos] <= '9' do incr pos done;
    if !pos = b || (!pos < String.length s && not (is_space s.[!pos])) then bad "invalid data";
    int_of_string (String.sub s b (!pos - b))

let read_netpbm ~colour (o : options) s =
  need s 2 "header";
  let ascii, binary = if colour then ('3', '6') else ('2', '5') in
  if s.[0] <> 'P' || (s.[1] <> ascii && s.[1] <> binary) then bad "not a %s file" (if colour then "PPM" else "PGM");
  let width, height, depth, start = netpbm_header s in
  let max = if depth < 256 then 255 else 65535 in
  let curve = Gamma_curve.scaled_by_decoding (f (float_of_int max /. float_of_int depth)) (given_curve o) in
  let count = width * height * if colour then 3 else 1 in
  let values =
    if s.[1] = ascii then
      let next = ascii_numbers s start in
      Array.init count (fun _ -> next ())
    else begin
      let size = if max = 255 then 1 else 2 in
      need s (start + (count * size)) "pixels";
      Array.init count (fun i -> if size = 1 then u8 s (start + i) else u16be s (start + (2 * i)))
    end
  in
  let lut = lut_of curve max in
  let pixels = if colour then Colour { max; rgb = values; alpha = None; lut } else Grey { max; grey = values; alpha = None; lut } in
  { width; height; pixels; premultiplied = false }

(* ---------------------------------------------------------------------------------------------- *)
(* Targa (targa.cpp): colour-mapped, true-colour and grey, raw or run-length encoded *)

let read_tga (o : options) s =
  need s 18 "header";
  let idlen = u8 s 0 and ftype = u8 s 2 in
  let cmlen = u8 s 5 + (u8 s 6 lsl 8) and cmsiz = u8 s 7 in
  let width = u8 s 12 + (u8 s 13 lsl 8) and height = u8 s 14 + (u8 s 15 lsl 8) in
  let psize = u8 s 16 and top_first = u8 s 17 land 0x20 <> 0 in
  let cmsizb = (cmsiz + 7) / 8 and psizeb = (psize + 7) / 8 in
  let opaque = psize <= 24 && psize <> 16 in
  let compressed = ftype = 9 || ftype = 10 || ftype = 11 in
  if ftype < 1 || ftype > 11 || (ftype > 3 && ftype < 9) then bad "unsupported file type in targa image";
  if not (List.mem psize [ 8; 15; 16; 24; 32 ]) then bad "unsupported pixel size in targa image";
  if cmlen > 256 then bad "unsupported color map length in targa image";
  if width = 0 || height = 0 then bad "invalid dimensions";
  let curve = assumed_curve o in
  let premultiplied = Option.value o.premultiply ~default:false in
  let pos = ref (18 + idlen) in
  let byte () =
    if !pos >= String.length s then bad "cannot read data from targa image";
    let b = u8 s !pos in
    incr pos;
    b
  in
  (* ConvertColor: r, g, b, a from the bytes of one pixel *)
  let convert size (b : int array) =
    match size with
    | 8 -> (b.(0), b.(0), b.(0), 255)
    | 15 | 16 ->
        let r = (b.(1) land 0x7c) lsl 1 in
        let g = ((((b.(1) land 0x03) lsl 3) lor ((b.(0) land 0xe0) lsr 5)) lsl 3) land 255 in
        let bl = (b.(0) land 0x1f) lsl 3 in
        (r, g, bl, if size = 16 then (if b.(1) land 0x80 <> 0 then 255 else 0) else 255)
    | 24 -> (b.(2), b.(1), b.(0), 255)
    | _ -> (b.(2), b.(1), b.(0), b.(3))
  in
  let map =
    if cmlen > 0 then begin
      if psize <> 8 then bad "unsupported color map bit depth in targa image";
      Some
        (Array.init cmlen (fun _ ->
             let b = Array.init (max cmsizb 4) (fun j -> if j < cmsizb then byte () else 0) in
             let r, g, bl, a = convert cmsiz b in
             { red = int_decode curve r 255; green = int_decode curve g 255; blue = int_decode curve bl 255; filter = linear 255 a; transm = 0. }))
    end
    else None
  in
  let n = width * height in
  let index = Bytes.make n '\000' and rgb = Array.make (3 * n) 0 and alpha = Array.make n 255 in
  let store x y =
    let line = if top_first then y else height - y - 1 in
    let i = x + (line * width) in
    match map with
    | Some m ->
        let v = byte () in
        if v >= Array.length m then bad "invalid color map index in targa image";
        fun () -> Bytes.set index i (Char.chr v)
    | None ->
        let b = Array.init (max psizeb 4) (fun j -> if j < psizeb then byte () else 0) in
        let r, g, bl, a = convert psize b in
        fun () ->
          rgb.(3 * i) <- r;
          rgb.((3 * i) + 1) <- g;
          rgb.((3 * i) + 2) <- bl;
          alpha.(i) <- a
  in
  (* [store x y] reads one pixel's bytes and returns how to store them at (x, y) *)
  if not compressed then
    for y = 0 to height - 1 do
      for x = 0 to width - 1 do (store x y) () done
    done
  else begin
    let x = ref 0 and y = ref 0 in
    let advance () =
      incr x;
      if !x = width then begin
        x := 0;
        incr y
      end
    in
    while !y < height do
      let h = byte () in
      let count = (h land 0x7f) + 1 in
      if h land 0x80 <> 0 then begin
        (* one pixel repeated: its bytes are read once *)
        let at = !pos in
        let rec go k =
          if k < count && !y < height then begin
            pos := at;
            (store !x !y) ();
            advance ();
            go (k + 1)
          end
        in
        go 0
      end
      else
        for _ = 1 to count do
          if !y < height then begin
            (store !x !y) ();
            advance ()
          end
        done
    done
  end;
  let pixels =
    match map with
    | Some m -> Indexed { kind = Rgba_map; map = m; index }
    | None -> Colour { max = 255; rgb; alpha = (if opaque then None else Some alpha); lut = lut_of curve 255 }
  in
  { width; height; pixels; premultiplied }

(* ---------------------------------------------------------------------------------------------- *)
(* GIF (gif.cpp, gifdecod.cpp): the global colour table and the first image's LZW data *)

let lzw_decode s start min_size out =
  (* the data sub-blocks joined *)
  let buf = Buffer.create 4096 in
  let pos = ref start in
  let rec blocks () =
    if !pos >= String.length s then bad "unexpected end of the image data";
    let len = u8 s !pos in
    if len > 0 then begin
      need s (!pos + 1 + len) "image data";
      Buffer.add_substring buf s (!pos + 1) len;
      pos := !pos + 1 + len;
      blocks ()
    end
  in
  blocks ();
  let data = Buffer.contents buf in
  let clear = 1 lsl min_size in
  let eoi = clear + 1 in
  let prefix = Array.make 4096 0 and suffix = Array.make 4096 0 and first = Array.make 4096 0 and len = Array.make 4096 0 in
  for i = 0 to clear - 1 do
    suffix.(i) <- i;
    first.(i) <- i;
    len.(i) <- 1
  done;
  let n = Bytes.length out in
  let written = ref 0 in
  let emit code =
    let l = len.(code) in
    let rec go c k =
      if k >= 0 then begin
        if !written + k < n then Bytes.set out (!written + k) (Char.chr suffix.(c));
        go prefix.(c) (k - 1)
      end
    in
    go code (l - 1);
    written := !written + l
  in
  let bitpos = ref 0 and size = ref (min_size + 1) and next = ref (clear + 2) and old = ref (-1) in
  let read_code () =
    if (!bitpos + !size) > 8 * String.length data then -1
    else begin
      let v = ref 0 in
      for k = 0 to !size - 1 do
        let b = !bitpos + k in
        if (u8 data (b / 8) lsr (b mod 8)) land 1 = 1 then v := !v lor (1 lsl k)
      done;
      bitpos := !bitpos + !size;
      !v
    end
  in
  let fin = ref false in
  while (not !fin) && !written < n do
    let code = read_code () in
    if code < 0 || code = eoi then fin := true
    else if code = clear then begin
      size := min_size + 1;
      next := clear + 2;
      old := -1
    end
    else begin
      if !old < 0 then begin
        if code >= !next then bad "an invalid LZW code";
        emit code
      end
      else begin
        let add fst =
          if !next < 4096 then begin
            prefix.(!next) <- !old;
            suffix.(!next) <- fst;
            first.(!next) <- first.(!old);
            len.(!next) <- len.(!old) + 1;
            incr next
          end
        in
        if code < !next then begin
          add first.(code);
          emit code
        end
        else if code = !next then begin
          add first.(!old);
          emit code
        end
        else bad "an invalid LZW code"
      end;
      old := code;
      if !next = 1 lsl !size && !size < 12 then incr size
    end
  done

let read_gif (o : options) s =
  need s 13 "header";
  if String.sub s 0 3 <> "GIF" then bad "not a GIF file";
  if s.[3] <> '8' || (s.[4] <> '7' && s.[4] <> '9') then bad "unsupported GIF version";
  let flags = u8 s 10 in
  if flags land 0x80 = 0 then bad "no global color map";
  let size = 1 lsl ((flags land 0x07) + 1) in
  let curve = assumed_curve o in
  need s (13 + (3 * size)) "color map";
  let map =
    Array.init size (fun i ->
        let b = 13 + (3 * i) in
        { red = int_decode curve (u8 s b) 255; green = int_decode curve (u8 s (b + 1)) 255; blue = int_decode curve (u8 s (b + 2)) 255; filter = 1.; transm = 0. })
  in
  let rec objects pos =
    if pos >= String.length s then bad "no image data";
    match s.[pos] with
    | ';' -> bad "no image data"
    | '!' ->
        need s (pos + 3) "extension";
        let label = u8 s (pos + 1) in
        let pos = pos + 2 in
        (* a graphic control extension can make one entry transparent *)
        let pos =
          if label = 0xF9 then begin
            let len = u8 s pos in
            need s (pos + 1 + len) "extension";
            if len >= 4 && u8 s (pos + 1) land 1 = 1 then begin
              let t = u8 s (pos + 4) in
              if t < size then map.(t) <- { (map.(t)) with filter = 0. }
            end;
            pos + 1 + len
          end
          else pos
        in
        let rec skip p =
          need s (p + 1) "extension";
          let l = u8 s p in
          if l = 0 then p + 1 else skip (p + 1 + l)
        in
        objects (skip pos)
    | ',' ->
        need s (pos + 11) "image descriptor";
        let width = u8 s (pos + 5) lor (u8 s (pos + 6) lsl 8) and height = u8 s (pos + 7) lor (u8 s (pos + 8) lsl 8) in
        let iflags = u8 s (pos + 9) in
        if iflags land 0x40 <> 0 then bad "interlacing in GIF image unsupported";
        let pos = pos + 10 + if iflags land 0x80 <> 0 then 3 * (1 lsl ((iflags land 7) + 1)) else 0 in
        let index = Bytes.make (width * height) '\000' in
        lzw_decode s (pos + 1) (u8 s pos) index;
        { width; height; pixels = Indexed { kind = Rgba_map; map; index }; premultiplied = false }
    | _ -> bad "cannot find GIF image data block"
  in
  objects (13 + (3 * size))

(* ---------------------------------------------------------------------------------------------- *)
(* JPEG (jpeg.cpp): libjpeg's 8-bit samples through camlimages, sRGB unless told otherwise *)

let read_jpeg (o : options) path =
  let curve = assumed_curve o in
  let img = try Jpeg.load path [] with Failure m -> bad "%s" m | Images.Wrong_file_type -> bad "not a JPEG file" in
  let rgb24 = match img with Images.Rgb24 b -> b | _ -> bad "unsupported color format in JPEG image" in
  let width = rgb24.Rgb24.width and height = rgb24.Rgb24.height in
  let rgb = Array.make (3 * width * height) 0 in
  for y = 0 to height - 1 do
    for x = 0 to width - 1 do
      let c = Rgb24.get rgb24 x y in
      let i = 3 * (x + (y * width)) in
      rgb.(i) <- c.Color.r;
      rgb.(i + 1) <- c.Color.g;
      rgb.(i + 2) <- c.Color.b
    done
  done;
  { width; height; pixels = Colour { max = 255; rgb; alpha = None; lut = lut_of curve 255 }; premultiplied = false }

(* ---------------------------------------------------------------------------------------------- *)

let read fmt o path =
  let contents () =
    let ic = open_in_bin path in
    Fun.protect ~finally:(fun () -> close_in ic) (fun () -> really_input_string ic (in_channel_length ic))
  in
  try
    match fmt with
    | Png -> Ok (read_png o (contents ()))
    | Ppm -> Ok (read_netpbm ~colour:true o (contents ()))
    | Pgm -> Ok (read_netpbm ~colour:false o (contents ()))
    | Tga -> Ok (read_tga o (contents ()))
    | Gif -> Ok (read_gif o (contents ()))
    | Jpeg -> Ok (read_jpeg o path)
    | Iff | Tiff | Bmp | Exr | Hdr -> Error (Printf.sprintf "not supported yet: '%s' images" (format_name fmt))
  with
  | Bad m -> Error m
  | Sys_error m -> Error m
  | Invalid_argument m | Failure m -> Error m
