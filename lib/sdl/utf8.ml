(* UTF-8 decoding for the strings of text objects (docs/povray-rules.md §15.9). *)

(* Characters beyond 0xFFFF are dropped, as POV-Ray keeps UCS-2 only. *)
let decode ~invalid s =
  let n = String.length s in
  let b i = Char.code s.[i] in
  let acc = ref [] and i = ref 0 in
  let cont k = !i + k < n && b (!i + k) land 0xC0 = 0x80 in
  while !i < n do
    let c = b !i in
    if c < 0x80 then (acc := c :: !acc; incr i)
    else if c land 0xE0 = 0xC0 && cont 1 then (acc := ((c land 0x1F) lsl 6) lor (b (!i + 1) land 0x3F) :: !acc; i := !i + 2)
    else if c land 0xF0 = 0xE0 && cont 1 && cont 2 then (
      acc := ((c land 0x0F) lsl 12) lor ((b (!i + 1) land 0x3F) lsl 6) lor (b (!i + 2) land 0x3F) :: !acc;
      i := !i + 3)
    else if c land 0xF8 = 0xF0 && cont 1 && cont 2 && cont 3 then i := !i + 4
    else begin
      invalid c;
      incr i
    end
  done;
  Array.of_list (List.rev !acc)
