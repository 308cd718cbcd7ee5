(* Reading an image file of any format povml reads: the format's reader, JPEG through camlimages. *)
open Image_file

type failure = Unreadable of string | Over_limit of { msg : string; option : string }

(* the file's bytes, refused when the file alone is larger than the memory limit *)
let file_contents (o : options) path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      let len = in_channel_length ic in
      if len / 1048576 >= o.max_memory_mb then
        raise (Image_file.Over_limit { option = "--max-memory MIB"; msg = Printf.sprintf "the file is %s MiB, more than povml's memory limit of %s MiB (raise it with --max-memory MIB)" (commas (len / 1048576))
          (commas o.max_memory_mb) });
      really_input_string ic len)

let message = function Unreadable m | Over_limit { msg = m; _ } -> m

(* JPEG (jpeg.cpp): libjpeg's 8-bit samples through camlimages, sRGB unless told otherwise *)

(* The size in the first start-of-frame marker (SOF0 … SOF15 but DHT, JPG and DAC), found by
   walking the marker segments from SOI; None when the walk fails (libjpeg then says why). *)
let jpeg_size s =
  let len = String.length s in
  let rec walk pos =
    if pos + 4 > len || s.[pos] <> '\xff' then None
    else
      let marker = Char.code s.[pos + 1] in
      if marker = 0xff then walk (pos + 1)
      else if marker = 0xd8 || marker = 0x01 || (marker >= 0xd0 && marker <= 0xd7) then walk (pos + 2)
      else
        let seg = u16be s (pos + 2) in
        if marker >= 0xc0 && marker <= 0xcf && marker <> 0xc4 && marker <> 0xc8 && marker <> 0xcc then
          if pos + 9 > len then None else Some (u16be s (pos + 7), u16be s (pos + 5))
        else if seg < 2 then None
        else walk (pos + 2 + seg)
  in
  if len >= 2 && s.[0] = '\xff' && s.[1] = '\xd8' then walk 2 else None

(* [f ()] with the process's standard error sent to a temporary file, and what was written there:
   camlimages gives libjpeg its default error manager, which prints its warnings and errors on
   standard error; povml says what went wrong once, located in the scene *)
let capturing_stderr o f =
  let tmp = Filename.temp_file "povml-jpeg" ".txt" in
  flush stderr;
  let saved = Unix.dup Unix.stderr in
  let restore () =
    flush stderr;
    Unix.dup2 saved Unix.stderr;
    Unix.close saved
  in
  let said () =
    let text = try file_contents { o with max_memory_mb = max_int } tmp with Sys_error _ | Image_file.Over_limit _ -> "" in
    (try Sys.remove tmp with Sys_error _ -> ());
    text
  in
  (match Unix.openfile tmp [ O_WRONLY; O_TRUNC ] 0o600 with
  | fd -> Unix.dup2 fd Unix.stderr; Unix.close fd
  | exception Unix.Unix_error _ -> ());
  match f () with
  | v ->
      restore ();
      (Ok v, said ())
  | exception e ->
      restore ();
      (Error e, said ())

let first_line text =
  let lines = List.filter (fun l -> String.trim l <> "" && not (String.length l > 8 && String.sub l 0 8 = "setting ")) (String.split_on_char '\n' text) in
  match lines with l :: _ -> Some (String.trim l) | [] -> None

let read_jpeg (o : options) path =
  let curve = assumed_curve o in
  let data = file_contents o path in
  (match jpeg_size data with
  | Some (width, height) -> check_size o ~format:"JPEG" ~width ~height ~samples:3
  | None -> ());
  let result, said = capturing_stderr o (fun () -> Jpeg.load path []) in
  let libjpeg = first_line said in
  let img =
    match result with
    | Ok img -> (
        (* libjpeg pads a file that ends early with an end marker and warns; POV-Ray's source
           manager does not, and libjpeg refuses the file *)
        match libjpeg with
        | Some m when String.length m >= 10 && String.sub m 0 10 = "Premature " -> bad "the JPEG is damaged: %s" m
        | Some _ | None -> img)
    | Error (Failure m) -> (
        match libjpeg with Some l when m = "" || String.length m < String.length l -> bad "%s" l | Some _ | None -> bad "%s" m)
    | Error Images.Wrong_file_type -> bad "not a JPEG file"
    | Error e -> raise e
  in
  let rgb24 = match img with Images.Rgb24 b -> b | _ -> bad "unsupported color format in JPEG image" in
  let width = rgb24.Rgb24.width and height = rgb24.Rgb24.height in
  check_size o ~format:"JPEG" ~width ~height ~samples:3;
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

let decode fmt o ~contents ~path =
  match fmt with
  | Png -> Png_file.read_png o (contents ())
  | Ppm -> Netpbm_file.read_netpbm ~colour:true o (contents ())
  | Pgm -> Netpbm_file.read_netpbm ~colour:false o (contents ())
  | Tga -> Tga_file.read_tga o (contents ())
  | Gif -> Gif_file.read_gif o (contents ())
  | Pot -> Gif_file.read_pot o (contents ())
  | Jpeg -> read_jpeg o path
  | Iff | Tiff | Bmp | Exr | Hdr -> bad "not supported yet: '%s' images" (format_name fmt)

let read fmt o path =
  let contents () = file_contents o path in
  try Ok (decode fmt o ~contents ~path) with
  | Bad m -> Error (Unreadable m)
  | Image_file.Over_limit { msg; option } -> Error (Over_limit { msg; option })
  | Sys_error m -> Error (Unreadable m)
  | Out_of_memory -> Error (Over_limit { msg = "decoding it needs more memory than the process may use"; option = "ulimit -v" })
