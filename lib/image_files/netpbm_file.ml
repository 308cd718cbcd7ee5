(* PPM and PGM files as POV-Ray 3.7 reads them (ppm.cpp). *)
open Image_file

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

(* Read_ASCII_File_Number (pgm.cpp): blanks skipped, then up to 49 digits (a longer run of digits
   goes on as the next number); its atoi's value stored in the container as POV-Ray's
   SetRGBValue(unsigned int) stores it, wrapped to the container's 8 or 16 bits ([max]); a number
   too long for strtol is LONG_MAX, whose low bits are all set *)
let ascii_numbers s start max =
  let pos = ref start in
  let is_space c = c = ' ' || c = '\t' || c = '\n' || c = '\r' || c = '\011' || c = '\012' in
  let is_digit c = c >= '0' && c <= '9' in
  fun () ->
    while !pos < String.length s && is_space s.[!pos] do incr pos done;
    if !pos >= String.length s then bad "the file ends before its last pixel";
    if not (is_digit s.[!pos]) then bad "invalid data in the pixels: '%c' where a number should be" s.[!pos];
    let value = ref 0 and digits = ref 0 in
    while !digits < 49 && !pos < String.length s && is_digit s.[!pos] do
      let d = Char.code s.[!pos] - 48 in
      value := if !value > (max_int - d) / 10 then max_int else (10 * !value) + d;
      incr digits;
      incr pos
    done;
    if !digits < 49 && !pos < String.length s && not (is_space s.[!pos]) then
      bad "invalid data in the pixels: '%c' inside a number" s.[!pos];
    !value land max

let read_netpbm ~colour (o : options) s =
  need s 2 "header";
  let ascii, binary = if colour then ('3', '6') else ('2', '5') in
  let format = if colour then "PPM" else "PGM" in
  if s.[0] <> 'P' || (s.[1] <> ascii && s.[1] <> binary) then bad "not a %s file" format;
  let width, height, depth, start = netpbm_header s in
  let max = if depth < 256 then 255 else 65535 in
  let curve = Gamma_curve.scaled_by_decoding (f (float_of_int max /. float_of_int depth)) (given_curve o) in
  let per_pixel = if colour then 3 else 1 in
  check_size o ~format ~width ~height ~samples:per_pixel;
  let count = width * height * per_pixel in
  let have = String.length s - min start (String.length s) in
  let values =
    if s.[1] = ascii then begin
      (* each number takes a digit and, but for the last, a blank *)
      check_data ~format ~width ~height ~have:(have + 1) ~need_per_pixel:(2 * per_pixel);
      let next = ascii_numbers s start max in
      Array.init count (fun _ -> next ())
    end
    else begin
      let size = if max = 255 then 1 else 2 in
      check_data ~format ~width ~height ~have ~need_per_pixel:(size * per_pixel);
      Array.init count (fun i -> if size = 1 then u8 s (start + i) else u16be s (start + (2 * i)))
    end
  in
  let lut = lut_of curve max in
  let pixels = if colour then Colour { max; rgb = values; alpha = None; lut } else Grey { max; grey = values; alpha = None; lut } in
  { width; height; pixels; premultiplied = false }
