(* PNG files as POV-Ray 3.7 reads them (png.cpp): every colour type and depth, interlacing, tRNS,
   and the gAMA and sRGB chunks. *)
open Image_file

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

(* libpng's default user limit on either dimension (png.h, PNG_USER_WIDTH_MAX and
   PNG_USER_HEIGHT_MAX), which POV-Ray's png.cpp does not change *)
let libpng_max_dimension = 1_000_000

(* png_check_IHDR (png.c): the bit depths each colour type allows *)
let depth_allowed ctype depth =
  match ctype with
  | 0 -> List.mem depth [ 1; 2; 4; 8; 16 ]
  | 3 -> List.mem depth [ 1; 2; 4; 8 ]
  | 2 | 4 | 6 -> depth = 8 || depth = 16
  | _ -> false

(* The image data's length once inflated: each pass's rows, a filter byte and the row's bytes. *)
let inflated_size ~width ~height ~bits_pp ~interlaced =
  let passes = if interlaced then Array.to_list adam7 else [ (0, 0, 1, 1) ] in
  List.fold_left
    (fun acc (x0, y0, dx, dy) ->
      let pw = if width > x0 then (width - x0 + dx - 1) / dx else 0 in
      let ph = if height > y0 then (height - y0 + dy - 1) / dy else 0 in
      if pw = 0 || ph = 0 then acc
      else
        let stride = (mul pw bits_pp + 7) / 8 in
        let rows = mul ph (stride + 1) in
        if acc > max_int - rows then max_int else acc + rows)
    0 passes

let read_png (o : options) s =
  need s 8 "signature";
  if String.sub s 0 8 <> "\137PNG\r\n\026\n" then bad "not a PNG file";
  let ihdr = ref None and plte = ref None and trns = ref None and gama = ref None and srgb = ref false in
  let idat = Buffer.create (min (String.length s) 65536) in
  let rec chunks pos =
    if pos + 8 > String.length s then bad "the file ends before its IEND chunk";
    let len = u32be s pos and kind = String.sub s (pos + 4) 4 in
    if len > 0x7fffffff then bad "the PNG's %S chunk has a length above 2³¹ − 1" kind;
    if pos + 12 + len > String.length s then bad "the %s chunk ends early" kind;
    let body = String.sub s (pos + 8) len in
    (* png_crc_finish (pngrutil.c): a critical chunk (its first letter upper-case) with a bad CRC
       is an error, an ancillary one is ignored *)
    let critical = kind.[0] >= 'A' && kind.[0] <= 'Z' in
    let crc_ok = Png_crc.crc (kind ^ body) = u32be s (pos + 8 + len) in
    if critical && not crc_ok then bad "the PNG's %s chunk is damaged (its CRC does not match its data)" kind;
    if !ihdr = None && kind <> "IHDR" then bad "the PNG does not begin with its IHDR chunk";
    match kind with
    | "IEND" -> ()
    | _ ->
        (match kind with
        | "IHDR" -> if !ihdr <> None then bad "the PNG has two IHDR chunks" else ihdr := Some body
        | "PLTE" -> plte := Some body
        | "tRNS" -> if crc_ok then trns := Some body
        | "gAMA" -> if len >= 4 && crc_ok then gama := Some (float_of_int (u32be body 0) *. 0.00001)
        | "sRGB" -> if crc_ok then srgb := true
        | "IDAT" -> Buffer.add_string idat body
        | _ -> ());
        chunks (pos + 12 + len)
  in
  chunks 8;
  let h = match !ihdr with Some h when String.length h = 13 -> h | Some _ -> bad "the PNG's IHDR chunk is not 13 bytes long" | None -> bad "no IHDR chunk" in
  let width = u32be h 0 and height = u32be h 4 and depth = u8 h 8 and ctype = u8 h 9 and interlace = u8 h 12 in
  (* png_check_IHDR (png.c): the errors libpng raises, in its order *)
  if width = 0 || height = 0 then bad "the PNG's size %d×%d has no pixels" width height;
  if width > 0x7fffffff || height > 0x7fffffff then bad "the PNG's size %d×%d is above 2³¹ − 1" width height;
  if width > libpng_max_dimension || height > libpng_max_dimension then
    bad "the PNG's size %d×%d is above libpng's limit of %s pixels a side" width height (commas libpng_max_dimension);
  if not (List.mem depth [ 1; 2; 4; 8; 16 ]) then bad "the PNG's bit depth %d is not 1, 2, 4, 8 or 16" depth;
  if not (List.mem ctype [ 0; 2; 3; 4; 6 ]) then bad "the PNG's colour type %d is not 0, 2, 3, 4 or 6" ctype;
  if not (depth_allowed ctype depth) then bad "the PNG's bit depth %d is not allowed with its colour type %d" depth ctype;
  if u8 h 10 <> 0 then bad "the PNG's compression method %d is unknown" (u8 h 10);
  if u8 h 11 <> 0 then bad "the PNG's filter method %d is unknown" (u8 h 11);
  if interlace > 1 then bad "the PNG's interlace method %d is unknown" interlace;
  let interlaced = interlace = 1 in
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
  if ctype = 3 && !plte = None then bad "the PNG has colour type 3 (a palette) but no PLTE chunk";
  (* the unpacked samples, and the arrays made from them *)
  check_size o ~format:"PNG" ~width ~height ~samples:(2 * channels);
  (* decompression stops at the size the header promises: extra data is ignored, as libpng does *)
  let limit = inflated_size ~width ~height ~bits_pp:(depth * channels) ~interlaced in
  (* deflate inflates at most 1,032 bytes from one (two-bit codes for a 258-byte copy), so the
     compressed data bounds the image: libpng would run out of data ("Not enough image data") *)
  let compressed = Buffer.length idat in
  if limit / 1032 > compressed + 16 then
    bad "the PNG's %s bytes of compressed data cannot hold its %d×%d pixels (%s bytes once inflated; deflate inflates at most 1,032 times)"
      (commas compressed) width height (commas limit);
  let data = try Inflate.zlib ~limit (Buffer.contents idat) with Inflate.Corrupt m -> bad "%s" m in
  let samples = png_samples data ~width ~height ~depth ~channels ~interlaced in
  let n = width * height in
  let pixels =
    match ctype with
    | 3 ->
        let pal = Option.value !plte ~default:"" in
        if String.length pal mod 3 <> 0 || String.length pal = 0 then bad "the PNG's palette (PLTE chunk) of %d bytes is not a whole number of colours" (String.length pal);
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
