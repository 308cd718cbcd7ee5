(* Malformed and hostile files made at test time, for the decoders' tests (hostile_image and
   test/unit/test_decoders.ml). *)

let be32 n = String.init 4 (fun i -> Char.chr ((n lsr (8 * (3 - i))) land 0xff))
let le16 n = String.init 2 (fun i -> Char.chr ((n lsr (8 * i)) land 0xff))

(* a PNG chunk with its length and CRC; [bad_crc] spoils the CRC *)
let chunk ?(bad_crc = false) kind body =
  let crc = Png_text.crc (kind ^ body) in
  be32 (String.length body) ^ kind ^ body ^ be32 (if bad_crc then crc lxor 1 else crc)

let ihdr ?(depth = 8) ?(ctype = 2) w h = chunk "IHDR" (be32 w ^ be32 h ^ String.make 1 (Char.chr depth) ^ String.make 1 (Char.chr ctype) ^ "\000\000\000")
let png chunks = "\137PNG\r\n\026\n" ^ String.concat "" chunks ^ chunk "IEND" ""

(* a zlib stream of [data] in stored blocks *)
let stored data =
  let b = Buffer.create (String.length data + 64) in
  Buffer.add_string b "\x78\x01";
  let n = String.length data in
  let rec go pos =
    let len = min 65535 (n - pos) in
    Buffer.add_char b (if pos + len >= n then '\001' else '\000');
    Buffer.add_string b (le16 len);
    Buffer.add_string b (le16 (len lxor 0xffff));
    Buffer.add_string b (String.sub data pos len);
    if pos + len < n then go (pos + len)
  in
  go 0;
  Buffer.add_string b "\000\000\000\000";
  Buffer.contents b

(* a zlib stream inflating to [copies] × 258 + 1 zero bytes: one fixed-Huffman block of a literal
   0 and then length-258, distance-1 copies, 13 bits each *)
let bomb copies =
  let b = Buffer.create ((copies * 13 / 8) + 16) in
  Buffer.add_string b "\x78\x01";
  let acc = ref 0 and nbits = ref 0 in
  let put v n =
    acc := !acc lor (v lsl !nbits);
    nbits := !nbits + n;
    while !nbits >= 8 do
      Buffer.add_char b (Char.chr (!acc land 255));
      acc := !acc lsr 8;
      nbits := !nbits - 8
    done
  in
  (* a Huffman code goes most significant bit first *)
  let code v n = for i = n - 1 downto 0 do put ((v lsr i) land 1) 1 done in
  put 1 1;
  put 1 2;
  code 0x30 8;
  for _ = 1 to copies do
    code 0xc5 8 (* length 258: symbol 285 *);
    code 0 5 (* distance 1 *)
  done;
  code 0 7 (* end of block *);
  put 0 7;
  Buffer.add_string b "\000\000\000\000";
  Buffer.contents b

(* a GIF of [w]×[h] pixels whose colour table has 2^(bits+1) entries, the LZW data [indices] at
   code size [code_size] written without compression (a clear code before the table grows) *)
let gif ?(bits = 0) ?code_size w h indices =
  let min_size = Option.value code_size ~default:2 in
  let size = min_size + 1 and clear = 1 lsl min_size in
  let codes = ref [ clear ] and n = ref 0 in
  List.iter
    (fun v ->
      if !n >= (1 lsl size) - clear - 4 then begin codes := clear :: !codes; n := 0 end;
      codes := v :: !codes;
      incr n)
    indices;
  let codes = List.rev ((clear + 1) :: !codes) in
  let data = Buffer.create 64 in
  let acc = ref 0 and nb = ref 0 in
  List.iter
    (fun c ->
      acc := !acc lor (c lsl !nb);
      nb := !nb + size;
      while !nb >= 8 do Buffer.add_char data (Char.chr (!acc land 255)); acc := !acc lsr 8; nb := !nb - 8 done)
    codes;
  if !nb > 0 then Buffer.add_char data (Char.chr (!acc land 255));
  let data = Buffer.contents data in
  let blocks = Buffer.create 64 in
  let rec go pos =
    if pos < String.length data then begin
      let len = min 255 (String.length data - pos) in
      Buffer.add_char blocks (Char.chr len);
      Buffer.add_string blocks (String.sub data pos len);
      go (pos + len)
    end
  in
  go 0;
  let table = String.init (3 * (1 lsl (bits + 1))) (fun i -> if i mod 3 = 0 then '\255' else '\000') in
  "GIF89a" ^ le16 w ^ le16 h ^ String.make 1 (Char.chr (0x80 lor bits)) ^ "\000\000" ^ table ^ "," ^ le16 0 ^ le16 0 ^ le16 w ^ le16 h ^ "\000"
  ^ String.make 1 (Char.chr (Option.value code_size ~default:2)) ^ Buffer.contents blocks ^ "\000;"

let tga ~rle w h body =
  String.concat "" [ "\000\000"; String.make 1 (if rle then '\010' else '\002'); "\000\000\000\000\000\000\000\000\000"; le16 w; le16 h; "\024\032"; body ]

let jpeg () =
  let tmp = Filename.temp_file "hostile" ".jpg" in
  let img = Rgb24.create 16 16 in
  for y = 0 to 15 do for x = 0 to 15 do Rgb24.set img x y { Color.r = 16 * x; g = 16 * y; b = 128 } done done;
  Jpeg.save tmp [ Images.Save_Quality 90 ] (Images.Rgb24 img);
  let ic = open_in_bin tmp in
  let s = really_input_string ic (in_channel_length ic) in
  close_in ic;
  Sys.remove tmp;
  s

(* A TrueType font whose glyph 0 (character 'A') is made of [k] copies of glyph 1, itself made of
   [k] copies of glyph 2, and so on 8 deep, glyph 8 a single point: k⁸ glyphs for one character. *)
let nested_font k =
  let be16 n = String.init 2 (fun i -> Char.chr ((n lsr (8 * (1 - i))) land 0xff)) in
  let composite next = be16 0xffff ^ String.make 8 '\000' ^ String.concat "" (List.init k (fun i -> be16 (if i < k - 1 then 0x22 else 0x02) ^ be16 next ^ be16 0)) in
  let simple = be16 1 ^ String.make 8 '\000' ^ be16 0 ^ be16 0 ^ "\001" ^ be16 10 ^ be16 20 ^ "\000" in
  let glyphs = List.init 8 (fun g -> composite (g + 1)) @ [ simple ] in
  let glyf = String.concat "" glyphs in
  let offsets = List.rev (snd (List.fold_left (fun (o, acc) g -> (o + String.length g, o :: acc)) (0, []) glyphs)) in
  let loca = String.concat "" (List.map (fun o -> be16 (o / 2)) (offsets @ [ String.length glyf ])) in
  let head = String.make 12 '\000' ^ be32 0x5F0F3CF5 ^ be16 0 ^ be16 1000 ^ String.make 30 '\000' ^ be16 0 ^ be16 0 in
  let maxp = be32 0x00010000 ^ be16 9 in
  let hhea = String.make 34 '\000' ^ be16 1 in
  let hmtx = be16 500 ^ be16 0 in
  let cmap = be16 0 ^ be16 1 ^ be16 1 ^ be16 0 ^ be32 12 ^ be16 0 ^ be16 262 ^ be16 0 ^ String.init 256 (fun _ -> '\000') in
  let tables = [ ("cmap", cmap); ("glyf", glyf); ("head", head); ("hhea", hhea); ("hmtx", hmtx); ("loca", loca); ("maxp", maxp) ] in
  let start = 12 + (16 * List.length tables) in
  let _, records, bodies =
    List.fold_left
      (fun (o, rs, bs) (tag, body) -> (o + String.length body, rs ^ tag ^ be32 0 ^ be32 o ^ be32 (String.length body), bs ^ body))
      (start, "", "") tables
  in
  be32 0x00010000 ^ be16 (List.length tables) ^ String.make 6 '\000' ^ records ^ bodies
