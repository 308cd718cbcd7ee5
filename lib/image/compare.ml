(* Comparing two encoded images: differing pixels, peak, RMSE, PSNR. *)

type t = { pixels : int; differing : int; peak : int; rmse : float }

let images (a : Encode.t) (b : Encode.t) =
  if a.width <> b.width || a.height <> b.height then
    Error (Printf.sprintf "sizes differ: %dx%d against %dx%d" a.width a.height b.width b.height)
  else
    let n = a.width * a.height in
    let differing = ref 0 and peak = ref 0 and sq = ref 0. in
    for p = 0 to n - 1 do
      let diff = ref false in
      for c = 0 to 2 do
        let i = (3 * p) + c in
        let d = abs (Char.code (Bytes.get a.pixels i) - Char.code (Bytes.get b.pixels i)) in
        if d > 0 then diff := true;
        if d > !peak then peak := d;
        sq := !sq +. float_of_int (d * d)
      done;
      if !diff then incr differing
    done;
    Ok { pixels = n; differing = !differing; peak = !peak; rmse = sqrt (!sq /. float_of_int (max 1 (3 * n))) }

let identical_share c = if c.pixels = 0 then 1. else float_of_int (c.pixels - c.differing) /. float_of_int c.pixels
let psnr c = if c.rmse = 0. then infinity else 20. *. log10 (255. /. c.rmse)
let differing_share c = if c.pixels = 0 then 0. else float_of_int c.differing /. float_of_int c.pixels
