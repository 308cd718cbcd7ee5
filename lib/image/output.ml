(* Encoding images as PNG or PPM bytes, written whole or not at all (Whole_file); reading PNGs
   back. *)

type format = Png | Ppm

(* the header and the pixels, which are not copied: the bytes are never changed once encoded *)
let ppm (img : Encode.t) = [ Printf.sprintf "P6\n%d %d\n255\n" img.width img.height; Bytes.unsafe_to_string img.pixels ]

let rgb24 (img : Encode.t) =
  let rgb = Rgb24.create img.width img.height in
  for y = 0 to img.height - 1 do
    for x = 0 to img.width - 1 do
      let i = 3 * ((y * img.width) + x) in
      Rgb24.unsafe_set rgb x y
        { Color.r = Char.code (Bytes.get img.pixels i); g = Char.code (Bytes.get img.pixels (i + 1)); b = Char.code (Bytes.get img.pixels (i + 2)) }
    done
  done;
  rgb

let rec read_fd fd buf chunk =
  match Unix.read fd chunk 0 (Bytes.length chunk) with
  | 0 -> Buffer.contents buf
  | n -> Buffer.add_subbytes buf chunk 0 n; read_fd fd buf chunk
  | exception Unix.Unix_error (EINTR, _, _) -> read_fd fd buf chunk

let rec waitpid pid =
  match Unix.waitpid [] pid with _, st -> st | exception Unix.Unix_error (EINTR, _, _) -> waitpid pid

(* camlimages (libpng) writes a PNG only to a file it opens by name, and does not report every
   failed write. So a child process writes it into a pipe, opened as its /dev/stdout, and the
   bytes come back here: nothing reaches the disk but through Whole_file, and a full disk never
   meets libpng. The child leaves by [_exit], without the parent's buffered output. *)
let png_max_side = 1_000_000

let png (img : Encode.t) =
  if img.width > png_max_side || img.height > png_max_side then
    Error (Printf.sprintf "a PNG is at most %s pixels wide and high (libpng's limit), this image is %d×%d" "1,000,000" img.width img.height)
  else
  match Unix.pipe ~cloexec:true () with
  | exception Unix.Unix_error (e, _, _) -> Error (Unix.error_message e)
  | r, w -> (
      match Unix.fork () with
      | exception Unix.Unix_error (e, _, _) -> Unix.close r; Unix.close w; Error (Unix.error_message e)
      | 0 ->
          Sys.set_signal Sys.sigpipe Sys.Signal_default;
          let ok =
            match Unix.dup2 ~cloexec:false w Unix.stdout; Png.save "/dev/stdout" [] (Images.Rgb24 (rgb24 img)) with
            | () -> true
            | exception _ -> false
          in
          Unix._exit (if ok then 0 else 1)
      | pid -> (
          Unix.close w;
          let data = Fun.protect ~finally:(fun () -> Unix.close r) (fun () -> read_fd r (Buffer.create 65536) (Bytes.create 65536)) in
          match waitpid pid with
          | WEXITED 0 when Png_text.whole data -> Ok data
          | WEXITED _ | WSIGNALED _ | WSTOPPED _ -> Error "the PNG encoder (libpng) failed"))

let encode ?area fmt img =
  match fmt with
  | Ppm -> Ok (ppm img)
  | Png -> (
      match (png img, area) with
      | (Error _ as e), _ -> e
      | Ok data, None -> Ok [ data ]
      | Ok data, Some a -> Ok [ Png_text.add data ~key:Png_text.area_key ~value:a ])

(* The signals are held back from the encoding on: one that arrives meanwhile cancels the write. *)
let write ?area fmt path img =
  Interrupt.hold (fun () ->
      Interrupt.check ();
      match encode ?area fmt img with Error m -> Error m | Ok parts -> Whole_file.write_parts path parts)

let read_png path =
  match Png.load path [] with
  | exception e -> Error (match e with Sys_error m | Failure m -> m | e -> Printexc.to_string e)
  | Images.Rgb24 img ->
      let w = img.Rgb24.width and h = img.Rgb24.height in
      let pixels = Bytes.create (3 * w * h) in
      for y = 0 to h - 1 do
        for x = 0 to w - 1 do
          let c = Rgb24.get img x y in
          let i = 3 * ((y * w) + x) in
          Bytes.set pixels i (Char.chr c.r);
          Bytes.set pixels (i + 1) (Char.chr c.g);
          Bytes.set pixels (i + 2) (Char.chr c.b)
        done
      done;
      Ok { Encode.width = w; height = h; pixels }
  | Images.Rgba32 img ->
      let w = img.Rgba32.width and h = img.Rgba32.height in
      let pixels = Bytes.create (3 * w * h) in
      for y = 0 to h - 1 do
        for x = 0 to w - 1 do
          let c = Rgba32.get img x y in
          let i = 3 * ((y * w) + x) in
          Bytes.set pixels i (Char.chr c.color.r);
          Bytes.set pixels (i + 1) (Char.chr c.color.g);
          Bytes.set pixels (i + 2) (Char.chr c.color.b)
        done
      done;
      Ok { Encode.width = w; height = h; pixels }
  | _ -> Error (path ^ ": not an 8-bit RGB PNG")
