(* Reading an image file of any format povml reads: the format's reader, JPEG through camlimages. *)
open Image_file

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
    | Png -> Ok (Png_file.read_png o (contents ()))
    | Ppm -> Ok (Netpbm_file.read_netpbm ~colour:true o (contents ()))
    | Pgm -> Ok (Netpbm_file.read_netpbm ~colour:false o (contents ()))
    | Tga -> Ok (Tga_file.read_tga o (contents ()))
    | Gif -> Ok (Gif_file.read_gif o (contents ()))
    | Pot -> Ok (Gif_file.read_pot o (contents ()))
    | Jpeg -> Ok (read_jpeg o path)
    | Iff | Tiff | Bmp | Exr | Hdr -> Error (Printf.sprintf "not supported yet: '%s' images" (format_name fmt))
  with
  | Bad m -> Error m
  | Sys_error m -> Error m
  | Invalid_argument m | Failure m -> Error m
