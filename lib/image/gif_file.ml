(* GIF files as POV-Ray 3.7 reads them (gif.cpp, gifdecod.cpp). *)
open Image_file

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

(* A POT file holds two bytes per height: the right half of the GIF's indices are the low bytes of
   the left half's. The palette is ignored and no gamma applies. *)
let read_pot (o : options) s =
  let img = read_gif o s in
  match img.pixels with
  | Indexed { index; _ } ->
      if img.width land 1 <> 0 then bad "invalid width for POT file";
      let w = img.width / 2 in
      let byte x y = Char.code (Bytes.get index (x + (y * img.width))) in
      let grey = Array.init (w * img.height) (fun i -> (byte (i mod w) (i / w) lsl 8) lor byte ((i mod w) + w) (i / w)) in
      { width = w; height = img.height; pixels = Grey { max = 65535; grey; alpha = None; lut = None }; premultiplied = false }
  | Grey _ | Colour _ -> img
