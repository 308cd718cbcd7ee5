(* PNG tEXt chunks: added to a PNG's bytes before they are written, found when it is read back. *)

let area_key = "povml-area"

(* CRC-32 of the chunk type and data, as PNG computes it *)
let crc = Png_crc.crc

let be32 n = String.init 4 (fun i -> Char.chr ((n lsr (8 * (3 - i))) land 0xff))
let read32 s i = (Char.code s.[i] lsl 24) lor (Char.code s.[i + 1] lsl 16) lor (Char.code s.[i + 2] lsl 8) lor Char.code s.[i + 3]

let read_all path =
  let ic = open_in_bin path in
  Fun.protect ~finally:(fun () -> close_in_noerr ic) (fun () -> really_input_string ic (in_channel_length ic))

(* the chunks after the 8-byte signature: (type, data start, data length), in order *)
let chunks s =
  let rec go i acc =
    if i + 8 > String.length s then List.rev acc
    else
      let len = read32 s i in
      let kind = String.sub s (i + 4) 4 in
      if i + 12 + len > String.length s then List.rev acc else go (i + 12 + len) ((kind, i + 8, len, i) :: acc)
  in
  if String.length s >= 8 && String.sub s 1 3 = "PNG" then go 8 [] else []

(* the IEND chunk, when it ends the file *)
let iend s =
  match List.rev (chunks s) with
  | ("IEND", _, 0, at) :: _ when at + 12 = String.length s -> Some at
  | _ -> None

let whole s =
  match iend s with
  | None -> false
  | Some _ -> List.for_all (fun (_, start, len, _) -> read32 s (start + len) = crc (String.sub s (start - 4) (len + 4))) (chunks s)

let add png ~key ~value =
  match iend png with
  | None -> invalid_arg "Png_text.add: not a whole PNG file"
  | Some at ->
      let body = "tEXt" ^ key ^ "\000" ^ value in
      let chunk = be32 (String.length body - 4) ^ body ^ be32 (crc body) in
      String.concat "" [ String.sub png 0 at; chunk; String.sub png at (String.length png - at) ]

let find path ~key =
  match read_all path with
  | exception Sys_error _ -> None
  | s ->
      List.find_map
        (fun (k, start, len, _) ->
          if k <> "tEXt" then None
          else
            let data = String.sub s start len in
            match String.index_opt data '\000' with
            | Some i when String.sub data 0 i = key -> Some (String.sub data (i + 1) (String.length data - i - 1))
            | Some _ | None -> None)
        (chunks s)
