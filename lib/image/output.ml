(* Writing encoded images as PNG or PPM, whole or not at all, and reading PNGs back. *)

type format = Png | Ppm

let write_ppm path (img : Encode.t) =
  let oc = open_out_bin path in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () ->
      Printf.fprintf oc "P6\n%d %d\n255\n" img.width img.height;
      output_bytes oc img.pixels)

let write_png path (img : Encode.t) =
  let rgb = Rgb24.create img.width img.height in
  for y = 0 to img.height - 1 do
    for x = 0 to img.width - 1 do
      let i = 3 * ((y * img.width) + x) in
      Rgb24.unsafe_set rgb x y
        { Color.r = Char.code (Bytes.get img.pixels i); g = Char.code (Bytes.get img.pixels (i + 1)); b = Char.code (Bytes.get img.pixels (i + 2)) }
    done
  done;
  Png.save path [] (Images.Rgb24 rgb)

(* Whether the image is written through [path] rather than renamed onto it: a device, a pipe, a
   socket (+O/dev/null) or a symbolic link (/dev/stdout), which a rename would replace. *)
let written_through path =
  match (Unix.lstat path).st_kind with
  | S_REG | S_DIR -> false
  | S_LNK | S_CHR | S_BLK | S_FIFO | S_SOCK -> true
  | exception Unix.Unix_error _ -> false

let copy src dst =
  let text = Png_text.read_all src in
  let oc = open_out_gen [ Open_wronly; Open_binary ] 0o644 dst in
  Fun.protect ~finally:(fun () -> close_out_noerr oc) (fun () -> output_string oc text)

(* The temporary file is created, and renamed or removed, with SIGINT and SIGTERM held back, so
   that it always has a name to remove by; a signal that came while the image was being encoded
   cancels the rename. *)
let write ?area fmt path img =
  let through = written_through path in
  let dir = if through then Filename.get_temp_dir_name () else Filename.dirname path in
  Interrupt.hold (fun () ->
      Interrupt.check ();
      match Filename.temp_file ~temp_dir:dir ".povml-" ".part" with
      | exception Sys_error msg ->
          (* the message names the temporary file, which never existed: name the directory *)
          let reason = match String.rindex_opt msg ':' with Some i -> String.sub msg (i + 2) (String.length msg - i - 2) | None -> msg in
          Error (dir ^ ": " ^ reason)
      | tmp -> (
          let discard () = try Sys.remove tmp with Sys_error _ -> () in
          match
            (match fmt with
            | Png -> (
                write_png tmp img;
                match area with
                | None -> ()
                | Some a -> ( match Png_text.add tmp ~key:Png_text.area_key ~value:a with Ok () -> () | Error m -> failwith m))
            | Ppm -> write_ppm tmp img);
            Interrupt.check ()
          with
          | () when through -> (
              match copy tmp path with
              | () -> discard (); Ok ()
              | exception Sys_error m -> discard (); Error m)
          | () -> (
              (* the temporary file is private; the image gets ordinary permissions *)
              (try Unix.chmod tmp 0o644 with Unix.Unix_error _ -> ());
              match Unix.rename tmp path with
              | () -> Ok ()
              | exception Unix.Unix_error (e, _, _) -> discard (); Error (Unix.error_message e))
          | exception Interrupt.Interrupted -> discard (); raise Interrupt.Interrupted
          | exception e -> discard (); Error (match e with Sys_error m | Failure m -> m | e -> Printexc.to_string e)))

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
