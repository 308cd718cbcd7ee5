(* Targa files as POV-Ray 3.7 reads them (targa.cpp). *)
open Image_file

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
  (* the palette index, the colour and the alpha of every pixel *)
  check_size o ~format:"Targa" ~width ~height ~samples:4;
  (* a raw pixel takes its bytes; a run-length packet, a byte and one pixel's, covers at most 128 *)
  let have = String.length s - min (String.length s) !pos in
  if compressed then begin
    let packets = (mul width height + 127) / 128 in
    if packets > have then
      bad "the Targa's size %d×%d needs at least %s run-length packets, but the file holds %s bytes of pixel data" width height (commas packets) (commas have)
  end
  else check_data ~format:"Targa" ~width ~height ~have ~need_per_pixel:psizeb;
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
