(* Mutations of binary files, as AFL's havoc stage makes them. *)

let awkward8 = [| 0; 1; 2; 7; 8; 9; 12; 13; 16; 0x7f; 0x80; 0xfe; 0xff |]
let awkward16 = [| 0; 1; 0x7f; 0x80; 0xff; 0x100; 0x7fff; 0x8000; 0xfffe; 0xffff |]
let awkward32 = [| 0; 1; 0xff; 0xffff; 0x10000; 0x7fffffff; 0x80000000; 0xffffffff |]

let one rng ~seeds data =
  let n = String.length data in
  let b = Bytes.of_string data in
  let at () = Random.State.int rng (max 1 n) in
  let set_word v width =
    if n >= width then begin
      let p = Random.State.int rng (n - width + 1) in
      let big = Random.State.bool rng in
      for k = 0 to width - 1 do
        let shift = 8 * if big then width - 1 - k else k in
        Bytes.set b (p + k) (Char.chr ((v lsr shift) land 0xff))
      done
    end;
    Bytes.to_string b
  in
  if n = 0 then String.make 1 (Char.chr (Random.State.int rng 256))
  else
    match Random.State.int rng 9 with
    | 0 ->
        let p = at () in
        Bytes.set b p (Char.chr (Char.code (Bytes.get b p) lxor (1 lsl Random.State.int rng 8)));
        Bytes.to_string b
    | 1 ->
        Bytes.set b (at ()) (Char.chr (Random.State.int rng 256));
        Bytes.to_string b
    | 2 -> set_word awkward8.(Random.State.int rng (Array.length awkward8)) 1
    | 3 -> set_word awkward16.(Random.State.int rng (Array.length awkward16)) 2
    | 4 -> set_word awkward32.(Random.State.int rng (Array.length awkward32)) 4
    | 5 ->
        (* a run deleted *)
        let p = at () in
        let len = min (n - p) (1 + Random.State.int rng 16) in
        String.sub data 0 p ^ String.sub data (p + len) (n - p - len)
    | 6 ->
        (* a run duplicated *)
        let p = at () in
        let len = min (n - p) (1 + Random.State.int rng 32) in
        String.sub data 0 (p + len) ^ String.sub data p (n - p)
    | 7 ->
        (* truncated *)
        String.sub data 0 (at ())
    | _ ->
        (* a run of another seed spliced in *)
        let other = seeds.(Random.State.int rng (Array.length seeds)) in
        if other = "" then data
        else
          let q = Random.State.int rng (String.length other) in
          let len = min (String.length other - q) (1 + Random.State.int rng 64) in
          let p = at () in
          String.sub data 0 p ^ String.sub other q len ^ String.sub data p (n - p)

let mutate rng ~seeds data =
  let rec go k d = if k = 0 then d else go (k - 1) (one rng ~seeds d) in
  go (1 + Random.State.int rng 4) data
