(* The decoder fuzz target: a file through a decoder, every pixel read back. *)

type kind = Image of Image_file.format | Font

let kinds =
  [
    ("png", Image Image_file.Png);
    ("gif", Image Gif);
    ("pot", Image Pot);
    ("jpeg", Image Jpeg);
    ("ppm", Image Ppm);
    ("pgm", Image Pgm);
    ("tga", Image Tga);
    ("ttf", Font);
  ]

let options =
  {
    Image_file.gamma_correct = true;
    default_gamma = None;
    working_gamma = Gamma_curve.Neutral;
    gamma_override = false;
    premultiply = None;
    max_pixels = 1 lsl 20;
    max_memory_mb = 64;
  }

type outcome = Decoded | Refused of string | Bug of string

let be32 s i = (Char.code s.[i] lsl 24) lor (Char.code s.[i + 1] lsl 16) lor (Char.code s.[i + 2] lsl 8) lor Char.code s.[i + 3]

let fix_png_crcs_of data =
  let b = Bytes.of_string data in
  let n = String.length data in
  let rec go pos =
    if pos + 12 <= n then begin
      let len = be32 data pos in
      if len >= 0 && len <= n - pos - 12 then begin
        let crc = Png_text.crc (String.sub data (pos + 4) (len + 4)) in
        for k = 0 to 3 do Bytes.set b (pos + 8 + len + k) (Char.chr ((crc lsr (8 * (3 - k))) land 0xff)) done;
        go (pos + 12 + len)
      end
    end
  in
  go 8;
  Bytes.to_string b

(* every pixel read back as the renderer reads it *)
let read_back (img : Image_file.t) =
  for y = 0 to img.height - 1 do
    for x = 0 to img.width - 1 do
      ignore (Image_file.rgbft img x y);
      ignore (Image_file.index img (x + (y * img.width)))
    done
  done;
  ignore (Image_file.is_opaque img);
  ignore (Image_file.has_transparency img);
  if Image_file.is_indexed img then
    ignore (Image_file.with_filter_transmit img ~entry:0 ~filter:(Some 0.5) ~transmit:None ())

(* a few strings laid out, each glyph's outline made *)
let lay_out font =
  let codes s = Array.init (String.length s) (fun i -> Char.code s.[i]) in
  List.iter
    (fun s -> ignore (Font.layout font (codes s) ~offset:(Vec.make 0.1 0. 0.)))
    [ "AVgW i"; "POV-Ray 3.7"; String.init 32 (fun i -> Char.chr (i + 96)) ];
  ignore (Font.layout ~utf8:true font [| 0x263A; 0xE9; 0x41 |] ~offset:(Vec.make 0. 0. 0.))

let describe e =
  let bt = Printexc.get_backtrace () in
  Printexc.to_string e ^ if bt = "" then "" else "\n" ^ bt

let run ?(fix_png_crcs = false) kind data =
  match kind with
  | Image fmt -> (
      let data = if fix_png_crcs && fmt = Png then fix_png_crcs_of data else data in
      match Image_read.of_string fmt options data with
      | Error f -> Refused (Image_read.message f)
      | Ok img -> ( match read_back img with () -> Decoded | exception e -> Bug ("reading the decoded image back: " ^ describe e))
      | exception e -> Bug (describe e))
  | Font -> (
      match Font.parse data with
      | Error m -> Refused m
      | Ok font -> ( match lay_out font with () -> Decoded | exception e -> Bug ("laying out text: " ^ describe e))
      | exception e -> Bug (describe e))
let fix_png_crcs = fix_png_crcs_of
