(* RFC 1951's inflate: stored, fixed-Huffman and dynamic-Huffman blocks, read bit by bit with
   canonical Huffman tables decoded by code length. *)

exception Corrupt of string

let corrupt fmt = Printf.ksprintf (fun s -> raise (Corrupt s)) fmt

(* The input as a bit stream, least significant bit first within each byte. *)
type bits = { src : string; mutable pos : int; mutable bit_buf : int; mutable bit_count : int }

let need b n =
  while b.bit_count < n do
    if b.pos >= String.length b.src then corrupt "the compressed data ends early";
    b.bit_buf <- b.bit_buf lor (Char.code b.src.[b.pos] lsl b.bit_count);
    b.pos <- b.pos + 1;
    b.bit_count <- b.bit_count + 8
  done

let take b n =
  if n = 0 then 0
  else begin
    need b n;
    let v = b.bit_buf land ((1 lsl n) - 1) in
    b.bit_buf <- b.bit_buf lsr n;
    b.bit_count <- b.bit_count - n;
    v
  end

(* A canonical Huffman code: how many codes have each length, and the symbols in code order. *)
type huffman = { counts : int array; symbols : int array }

let huffman (lengths : int array) =
  let counts = Array.make 16 0 in
  Array.iter (fun l -> counts.(l) <- counts.(l) + 1) lengths;
  counts.(0) <- 0;
  let offsets = Array.make 16 0 in
  for l = 1 to 14 do offsets.(l + 1) <- offsets.(l) + counts.(l) done;
  let symbols = Array.make (Array.length lengths) 0 in
  Array.iteri
    (fun sym l ->
      if l <> 0 then begin
        symbols.(offsets.(l)) <- sym;
        offsets.(l) <- offsets.(l) + 1
      end)
    lengths;
  { counts; symbols }

(* one symbol: the code is read a bit at a time, most significant first; [first] is the first
   code of the current length and [index] its first symbol *)
let decode b h =
  let code = ref 0 and first = ref 0 and index = ref 0 and result = ref (-1) and len = ref 1 in
  while !result < 0 do
    if !len > 15 then corrupt "an invalid Huffman code";
    code := !code lor take b 1;
    let count = h.counts.(!len) in
    if !code - count < !first then result := h.symbols.(!index + (!code - !first))
    else begin
      index := !index + count;
      first := (!first + count) lsl 1;
      code := !code lsl 1;
      incr len
    end
  done;
  !result

let length_base = [| 3; 4; 5; 6; 7; 8; 9; 10; 11; 13; 15; 17; 19; 23; 27; 31; 35; 43; 51; 59; 67; 83; 99; 115; 131; 163; 195; 227; 258 |]
let length_extra = [| 0; 0; 0; 0; 0; 0; 0; 0; 1; 1; 1; 1; 2; 2; 2; 2; 3; 3; 3; 3; 4; 4; 4; 4; 5; 5; 5; 5; 0 |]

let dist_base =
  [| 1; 2; 3; 4; 5; 7; 9; 13; 17; 25; 33; 49; 65; 97; 129; 193; 257; 385; 513; 769; 1025; 1537; 2049; 3073; 4097; 6145; 8193; 12289; 16385; 24577 |]

let dist_extra = [| 0; 0; 0; 0; 1; 1; 2; 2; 3; 3; 4; 4; 5; 5; 6; 6; 7; 7; 8; 8; 9; 9; 10; 10; 11; 11; 12; 12; 13; 13 |]

let fixed_lit = huffman (Array.init 288 (fun i -> if i < 144 then 8 else if i < 256 then 9 else if i < 280 then 7 else 8))
let fixed_dist = huffman (Array.make 30 5)

(* the literal/length and distance codes of a dynamic block, themselves Huffman-coded *)
let dynamic_tables b =
  let nlen = take b 5 + 257 in
  let ndist = take b 5 + 1 in
  let ncode = take b 4 + 4 in
  let order = [| 16; 17; 18; 0; 8; 7; 9; 6; 10; 5; 11; 4; 12; 3; 13; 2; 14; 1; 15 |] in
  let code_lengths = Array.make 19 0 in
  for i = 0 to ncode - 1 do code_lengths.(order.(i)) <- take b 3 done;
  let lencode = huffman code_lengths in
  let lengths = Array.make (nlen + ndist) 0 in
  let i = ref 0 in
  while !i < nlen + ndist do
    let sym = decode b lencode in
    if sym < 16 then begin
      lengths.(!i) <- sym;
      incr i
    end
    else begin
      let value, repeat =
        match sym with
        | 16 ->
            if !i = 0 then corrupt "a repeated code length with no length before it";
            (lengths.(!i - 1), 3 + take b 2)
        | 17 -> (0, 3 + take b 3)
        | _ -> (0, 11 + take b 7)
      in
      if !i + repeat > nlen + ndist then corrupt "too many code lengths";
      for _ = 1 to repeat do
        lengths.(!i) <- value;
        incr i
      done
    end
  done;
  (huffman (Array.sub lengths 0 nlen), huffman (Array.sub lengths nlen ndist))

let codes b out lit dist =
  let fin = ref false in
  while not !fin do
    let sym = decode b lit in
    if sym < 256 then Buffer.add_char out (Char.chr sym)
    else if sym = 256 then fin := true
    else begin
      let sym = sym - 257 in
      if sym >= 29 then corrupt "an invalid length code";
      let len = length_base.(sym) + take b length_extra.(sym) in
      let dsym = decode b dist in
      if dsym >= 30 then corrupt "an invalid distance code";
      let d = dist_base.(dsym) + take b dist_extra.(dsym) in
      let start = Buffer.length out - d in
      if start < 0 then corrupt "a distance before the start of the data";
      for k = 0 to len - 1 do Buffer.add_char out (Buffer.nth out (start + k)) done
    end
  done

let zlib s =
  if String.length s < 2 then corrupt "the zlib header is missing";
  let cmf = Char.code s.[0] and flg = Char.code s.[1] in
  if cmf land 0x0f <> 8 || ((cmf lsl 8) lor flg) mod 31 <> 0 then corrupt "not a deflate stream";
  if flg land 0x20 <> 0 then corrupt "a preset dictionary, which PNG does not allow";
  let b = { src = s; pos = 2; bit_buf = 0; bit_count = 0 } in
  let out = Buffer.create (4 * String.length s) in
  let last = ref false in
  while not !last do
    last := take b 1 = 1;
    match take b 2 with
    | 0 ->
        (* a stored block starts at a byte boundary *)
        b.bit_buf <- 0;
        b.bit_count <- 0;
        if b.pos + 4 > String.length s then corrupt "a stored block ends early";
        let len = Char.code s.[b.pos] lor (Char.code s.[b.pos + 1] lsl 8) in
        b.pos <- b.pos + 4;
        if b.pos + len > String.length s then corrupt "a stored block ends early";
        Buffer.add_substring out s b.pos len;
        b.pos <- b.pos + len
    | 1 -> codes b out fixed_lit fixed_dist
    | 2 ->
        let lit, dist = dynamic_tables b in
        codes b out lit dist
    | _ -> corrupt "an invalid block type"
  done;
  Buffer.contents out
