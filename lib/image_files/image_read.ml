(* Reading an image file of any format povml reads: the format's reader. *)
open Image_file

type failure = Unreadable of string | Over_limit of { msg : string; option : string }

(* the file's bytes, refused when the file alone is larger than the memory limit *)
let file_contents (o : options) path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () ->
      let len = in_channel_length ic in
      if len / 1048576 >= o.max_memory_mb then
        over_limit "--max-memory MIB" "the file is %s MiB, more than povml's memory limit of %s MiB" (commas (len / 1048576)) (commas o.max_memory_mb);
      really_input_string ic len)

let message = function Unreadable m | Over_limit { msg = m; _ } -> m

let decode fmt o ~contents =
  match fmt with
  | Png -> Png_file.read_png o (contents ())
  | Ppm -> Netpbm_file.read_netpbm ~colour:true o (contents ())
  | Pgm -> Netpbm_file.read_netpbm ~colour:false o (contents ())
  | Tga -> Tga_file.read_tga o (contents ())
  | Gif -> Gif_file.read_gif o (contents ())
  | Pot -> Gif_file.read_pot o (contents ())
  | Jpeg -> Jpeg_file.read_jpeg o (contents ())
  | Iff | Tiff | Bmp | Exr | Hdr -> bad "not supported yet: '%s' images" (format_name fmt)

let guarded f =
  try Ok (f ()) with
  | Bad m -> Error (Unreadable m)
  | Image_file.Over_limit { msg; option } -> Error (Over_limit { msg; option })
  | Sys_error m -> Error (Unreadable m)
  | Out_of_memory -> Error (Over_limit { msg = "decoding it needs more memory than the process may use"; option = "ulimit -v" })

let read fmt o path = guarded (fun () -> decode fmt o ~contents:(fun () -> file_contents o path))

let of_string fmt o data = guarded (fun () -> decode fmt o ~contents:(fun () -> data))
