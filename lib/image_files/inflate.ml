(* RFC 1951's inflate: stored, fixed-Huffman and dynamic-Huffman blocks, each Huffman code
   decoded with one table lookup on the next bits of the stream. *)

exception Corrupt of string

let corrupt fmt = Printf.ksprintf (fun s -> raise (Corrupt s)) fmt

(* The input as a bit stream, least significant bit first within each byte. Past the end of the
   data the stream reads zero bytes, counted in [over], so that a lookup may look ahead; bits
   taken from them mean the data ended early. *)
type bits = { src : string; mutable pos : int; mutable bit_buf : int; mutable bit_count : int; mutable over : int }

let[@inline] need b n =
  while b.bit_count < n do
    if b.pos < String.length b.src then begin
      b.bit_buf <- b.bit_buf lor (Char.code (String.unsafe_get b.src b.pos) lsl b.bit_count);
      b.pos <- b.pos + 1
    end
    else b.over <- b.over + 8;
    b.bit_count <- b.bit_count + 8
  done

let[@inline] drop b n =
  b.bit_buf <- b.bit_buf lsr n;
  b.bit_count <- b.bit_count - n;
  if b.bit_count < b.over then corrupt "the compressed data ends early"

let take b n =
  if n = 0 then 0
  else begin
    need b n;
    let v = b.bit_buf land ((1 lsl n) - 1) in
    drop b n;
    v
  end

(* A canonical Huffman code as a table indexed by the next [bits] bits of the stream (the code's
   longest length): each entry is symbol × 16 + code length, 0 where no code starts so. *)
type huffman = { bits : int; table : int array }

let reverse code len =
  let r = ref 0 in
  for i = 0 to len - 1 do if code land (1 lsl i) <> 0 then r := !r lor (1 lsl (len - 1 - i)) done;
  !r

let huffman (lengths : int array) =
  let counts = Array.make 16 0 in
  Array.iter (fun l -> counts.(l) <- counts.(l) + 1) lengths;
  counts.(0) <- 0;
  let bits = Array.fold_left max 1 lengths in
  (* the first code of each length, in canonical order *)
  let next = Array.make 16 0 in
  let code = ref 0 in
  for l = 1 to 15 do
    code := (!code + counts.(l - 1)) lsl 1;
    next.(l) <- !code
  done;
  let table = Array.make (1 lsl bits) 0 in
  Array.iteri
    (fun sym l ->
      if l <> 0 then begin
        let c = next.(l) in
        next.(l) <- c + 1;
        if c < 1 lsl l then begin
          (* the stream holds the code's bits most significant first: the table index reversed *)
          let k = ref (reverse c l) in
          while !k < 1 lsl bits do
            table.(!k) <- (sym lsl 4) lor l;
            k := !k + (1 lsl l)
          done
        end
      end)
    lengths;
  { bits; table }

(* one symbol *)
let[@inline] decode b h =
  need b h.bits;
  let e = Array.unsafe_get h.table (b.bit_buf land ((1 lsl h.bits) - 1)) in
  if e = 0 then corrupt "an invalid Huffman code";
  drop b (e land 15);
  e lsr 4

(* The output, grown by doubling up to [limit] and a block's worth more; [Full] stops the
   decompression once [limit] bytes are out. *)
type out = { mutable buf : Bytes.t; mutable len : int; limit : int }

exception Full

let[@inline] room o n =
  if o.len + n > Bytes.length o.buf then begin
    let b = Bytes.create (max (min (2 * Bytes.length o.buf) (o.limit + min 65536 (max_int - o.limit))) (o.len + n)) in
    Bytes.blit o.buf 0 b 0 o.len;
    o.buf <- b
  end

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
    if sym < 256 then begin
      room out 1;
      Bytes.unsafe_set out.buf out.len (Char.unsafe_chr sym);
      out.len <- out.len + 1;
      if out.len >= out.limit then raise Full
    end
    else if sym = 256 then fin := true
    else begin
      let sym = sym - 257 in
      if sym >= 29 then corrupt "an invalid length code";
      let len = length_base.(sym) + take b length_extra.(sym) in
      let dsym = decode b dist in
      if dsym >= 30 then corrupt "an invalid distance code";
      let d = dist_base.(dsym) + take b dist_extra.(dsym) in
      let start = out.len - d in
      if start < 0 then corrupt "a distance before the start of the data";
      room out len;
      (* byte by byte: a copy may overlap what it writes *)
      let buf = out.buf and at = out.len in
      for k = 0 to len - 1 do Bytes.unsafe_set buf (at + k) (Bytes.unsafe_get buf (start + k)) done;
      out.len <- at + len;
      if out.len >= out.limit then raise Full
    end
  done

let zlib ?(limit = max_int) s =
  if String.length s < 2 then corrupt "the zlib header is missing";
  let cmf = Char.code s.[0] and flg = Char.code s.[1] in
  if cmf land 0x0f <> 8 || ((cmf lsl 8) lor flg) mod 31 <> 0 then corrupt "not a deflate stream";
  if flg land 0x20 <> 0 then corrupt "a preset dictionary, which PNG does not allow";
  let b = { src = s; pos = 2; bit_buf = 0; bit_count = 0; over = 0 } in
  let out = { buf = Bytes.create (max 1 (min (max 64 (4 * String.length s)) limit)); len = 0; limit } in
  let last = ref false in
  (try
  while (not !last) && out.len < limit do
    last := take b 1 = 1;
    match take b 2 with
    | 0 ->
        (* a stored block starts at a byte boundary *)
        (* whole bytes already read into the bit buffer are given back first *)
        b.pos <- b.pos - ((b.bit_count - b.over) / 8);
        b.bit_buf <- 0;
        b.bit_count <- 0;
        b.over <- 0;
        if b.pos + 4 > String.length s then corrupt "a stored block ends early";
        let len = Char.code s.[b.pos] lor (Char.code s.[b.pos + 1] lsl 8) in
        b.pos <- b.pos + 4;
        if b.pos + len > String.length s then corrupt "a stored block ends early";
        room out len;
        Bytes.blit_string s b.pos out.buf out.len len;
        out.len <- out.len + len;
        b.pos <- b.pos + len
    | 1 -> codes b out fixed_lit fixed_dist
    | 2 ->
        let lit, dist = dynamic_tables b in
        codes b out lit dist
    | _ -> corrupt "an invalid block type"
  done
  with Full -> ());
  Bytes.sub_string out.buf 0 (min out.len limit)
