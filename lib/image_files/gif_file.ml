(* GIF files as POV-Ray 3.7 reads them (gif.cpp, gifdecod.cpp). *)
open Image_file

(* GIF (gif.cpp, gifdecod.cpp): the global colour table and the first image's LZW data *)

(* Decode (gifdecod.cpp, from Fractint): the LZW codes of the image's data sub-blocks, written
   into [out] row by row. Its tolerance of bad data is POV-Ray's: a first code after a clear that
   is not yet in the table means index 0, a later one beyond the next free slot repeats the last
   string; a pixel past the image's last is an error ("Extra data in GIF file"); data that ends
   before the end code leaves the remaining pixels 0. *)
let lzw_decode s start min_size out =
  (* the data sub-blocks joined, each one's length checked against the file *)
  let buf = Buffer.create 4096 in
  let rec blocks pos =
    if pos >= String.length s then bad "the GIF's image data ends without its terminating block";
    let len = u8 s pos in
    if len > 0 then begin
      need s (pos + 1 + len) "image data";
      Buffer.add_substring buf s (pos + 1) len;
      blocks (pos + 1 + len)
    end
  in
  blocks start;
  let data = Buffer.contents buf in
  let max_codes = 4095 in
  let clear = 1 lsl min_size in
  let ending = clear + 1 and newcodes = clear + 2 in
  let suffix = Array.make (max_codes + 1) 0 and prefix = Array.make (max_codes + 1) 0 in
  (* the decoded string of one code, pushed last character first *)
  let stack = Array.make (max_codes + 2) 0 and sp = ref 0 in
  (* a damaged file can make the prefixes a loop (gifdecod.cpp then writes past its dstack) *)
  let push c =
    if !sp >= Array.length stack then bad "the GIF's LZW data is damaged: a code stands for more than %d pixels" (Array.length stack);
    stack.(!sp) <- c;
    incr sp
  in
  let n = Bytes.length out in
  let written = ref 0 in
  let put c =
    if !written >= n then bad "the GIF's image data holds more than its %d pixels" n;
    Bytes.set out !written (Char.unsafe_chr (c land 255));
    incr written
  in
  let curr_size = ref (min_size + 1) and top_slot = ref (1 lsl (min_size + 1)) and slot = ref newcodes in
  let bitpos = ref 0 in
  (* get_next_code: the next [curr_size] bits, least significant first; -1 at the end of the data *)
  let next_code () =
    if !bitpos + !curr_size > 8 * String.length data then -1
    else begin
      let v = ref 0 in
      for k = 0 to !curr_size - 1 do
        let b = !bitpos + k in
        if (u8 data (b lsr 3) lsr (b land 7)) land 1 = 1 then v := !v lor (1 lsl k)
      done;
      bitpos := !bitpos + !curr_size;
      !v
    end
  in
  let oc = ref 0 and fc = ref 0 in
  let rec loop () =
    let c = next_code () in
    if c >= 0 && c <> ending then
      if c = clear then begin
        curr_size := min_size + 1;
        slot := newcodes;
        top_slot := 1 lsl !curr_size;
        let rec skip_clears () = let c = next_code () in if c = clear then skip_clears () else c in
        let c = skip_clears () in
        if c >= 0 && c <> ending then begin
          let c = if c >= !slot then 0 else c in
          oc := c;
          fc := c;
          put c;
          loop ()
        end
      end
      else begin
        let code = ref c in
        if !code >= !slot then begin
          code := !oc;
          push !fc
        end;
        while !code >= newcodes do
          push suffix.(!code);
          code := prefix.(!code)
        done;
        push !code;
        if !slot < !top_slot then begin
          fc := !code;
          suffix.(!slot) <- !fc;
          prefix.(!slot) <- !oc;
          incr slot;
          oc := c
        end;
        if !slot >= !top_slot && !curr_size < 12 then begin
          top_slot := !top_slot lsl 1;
          incr curr_size
        end;
        while !sp > 0 do
          decr sp;
          put stack.(!sp)
        done;
        loop ()
      end
  in
  loop ()

let decode (o : options) s =
  need s 13 "header";
  if String.sub s 0 3 <> "GIF" then bad "not a GIF file";
  if s.[3] <> '8' || (s.[4] <> '7' && s.[4] <> '9') || s.[5] < 'A' || s.[5] > 'z' then bad "unsupported GIF version";
  let flags = u8 s 10 in
  if flags land 0x80 = 0 then bad "no global color map";
  (* gif.cpp reads the table's size from the low four bits, the sort flag included *)
  let size = 1 lsl ((flags land 0x0F) + 1) in
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
        (* POV-Ray's Image::Create of no pixels aborts; povml refuses the file *)
        if width = 0 || height = 0 then bad "the GIF's image is %d×%d pixels: it has none" width height;
        check_size o ~format:"GIF" ~width ~height ~samples:0;
        need s (pos + 1) "image data";
        (* Decode (gifdecod.cpp) refuses a code size outside 2 … 9 *)
        let code_size = u8 s pos in
        if code_size < 2 then bad "the GIF's LZW code size %d is below 2" code_size;
        if code_size > 9 then bad "the GIF's LZW code size %d is above 9" code_size;
        let index = Bytes.make (width * height) '\000' in
        lzw_decode s (pos + 1) code_size index;
        { width; height; pixels = Indexed { kind = Rgba_map; map; index }; premultiplied = false }
    | _ -> bad "cannot find GIF image data block"
  in
  objects (13 + (3 * size))

(* an index past the colour table reads outside POV-Ray's colour map (what it shows is undefined);
   povml refuses the file, as it does such a PNG *)
let read_gif o s =
  let img = decode o s in
  (match img.pixels with
  | Indexed { map; index; _ } ->
      let size = Array.length map in
      Bytes.iteri
        (fun i c ->
          if Char.code c >= size then
            bad "the GIF's pixel at column %d, row %d has colour index %d, beyond its %d-entry colour table" ((i mod img.width) + 1)
              ((i / img.width) + 1) (Char.code c) size)
        index
  | Grey _ | Colour _ -> ());
  img

(* A POT file holds two bytes per height: the right half of the GIF's indices are the low bytes of
   the left half's. The palette is ignored and no gamma applies. *)
let read_pot (o : options) s =
  let img = decode o s in
  match img.pixels with
  | Indexed { index; _ } ->
      if img.width land 1 <> 0 then bad "invalid width for POT file";
      let w = img.width / 2 in
      check_size o ~format:"POT" ~width:w ~height:img.height ~samples:1;
      let byte x y = Char.code (Bytes.get index (x + (y * img.width))) in
      let grey = Array.init (w * img.height) (fun i -> (byte (i mod w) (i / w) lsl 8) lor byte ((i mod w) + w) (i / w)) in
      { width = w; height = img.height; pixels = Grey { max = 65535; grey; alpha = None; lut = None }; premultiplied = false }
  | Grey _ | Colour _ -> img
